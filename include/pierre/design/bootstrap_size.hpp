// The bootstrap of design-checks.md §1 step 8, for barriers and quarries alike: a 90 % interval
// from at least 1000 resamples. These are the defaults and the least a rule set may ask for.
#pragma once

#include <cstddef>

namespace pierre::design {

inline constexpr double kMinBootstrapConfidence = 0.90;
inline constexpr std::size_t kMinBootstrapResamples = 1000;

}  // namespace pierre::design
