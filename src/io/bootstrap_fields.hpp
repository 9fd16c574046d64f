// The size of a rule set's bootstrap, read the same way for barriers and quarries.
#pragma once

#include <cstddef>
#include <string_view>

#include "toml_fields.hpp"

namespace pierre::io::detail {

// design-checks.md §1 step 8: a 90 % interval from at least 1000 resamples. A rule set may ask
// for more (a wider interval, more resamples), not for less.
inline void read_bootstrap_size(const TomlTable& t, std::string_view confidence_key,
                                std::string_view resamples_key, double& confidence,
                                std::size_t& resamples) {
  confidence = t.number(confidence_key, confidence);
  t.check(confidence_key, confidence >= 0.9 && confidence < 1,
          "a confidence from 0.9 to below 1 (design-checks.md §1 step 8: a 90 % interval)");
  if (const auto n = t.integer(resamples_key)) {
    t.check(resamples_key, *n >= 1000 && *n <= 1'000'000,
            "an integer from 1000 to 1000000 (design-checks.md §1 step 8: at least 1000)");
    resamples = static_cast<std::size_t>(*n);
  }
}

}  // namespace pierre::io::detail
