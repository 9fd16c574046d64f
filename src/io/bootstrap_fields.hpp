// The size of a rule set's bootstrap, read the same way for barriers and quarries.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

#include <fmt/format.h>

#include "pierre/design/bootstrap_size.hpp"
#include "toml_fields.hpp"

namespace pierre::io::detail {

// docs/barriers.md step 8: a 90 % interval from at least 1000 resamples. A rule set may ask
// for more (a wider interval, more resamples), not for less.
inline void read_bootstrap_size(const TomlTable& t, std::string_view confidence_key,
                                std::string_view resamples_key, double& confidence,
                                std::size_t& resamples) {
  confidence = t.number(confidence_key, confidence);
  t.check(confidence_key, confidence >= design::kMinBootstrapConfidence && confidence < 1,
          fmt::format("a confidence from {} to below 1 (docs/barriers.md step 8: a 90 % "
                      "interval)", design::kMinBootstrapConfidence));
  if (const auto n = t.integer(resamples_key)) {
    const auto least = static_cast<std::int64_t>(design::kMinBootstrapResamples);
    t.check(resamples_key, *n >= least && *n <= 1'000'000,
            fmt::format("an integer from {} to 1000000 (docs/barriers.md step 8: at least "
                        "{})", least, least));
    resamples = static_cast<std::size_t>(*n);
  }
  // The interval's ends are the type-7 percentiles (1 ∓ c)/2 of the replicates: with fewer
  // than one replicate beyond each end, they are the extreme replicates, not an estimate of
  // the percentile. So R (1 − c)/2 ≥ 1, i.e. R ≥ 2 / (1 − c).
  const double tail = static_cast<double>(resamples) * (1 - confidence) / 2;
  t.check(confidence_key, tail >= 1 - 1e-9,
          fmt::format("at most {:.6g} with {} resamples (each end of the interval needs at least one "
                      "resample beyond it: resamples ≥ 2 / (1 − confidence)); for a higher "
                      "confidence, raise {}",
                      1 - 2.0 / static_cast<double>(resamples), resamples, resamples_key));
}

}  // namespace pierre::io::detail
