#include "pierre/sim/scenario.hpp"

#include <limits>

namespace pierre::sim {

std::optional<std::string> scenario_fault(const Scenario& s) {
  if (s.profile.segment_count() == 0) return "the profile has no segment";
  for (std::size_t j = 0; j < s.profile.segment_count(); ++j) {
    const int m = s.profile.segment(j).material;
    if (m < 0 || static_cast<std::size_t>(m) >= s.materials.size())
      return "segment " + std::to_string(j) + " names material " + std::to_string(m) + ", but " +
             std::to_string(s.materials.size()) + " material(s) are given";
  }
  constexpr std::uint64_t kMax32 = std::numeric_limits<std::uint32_t>::max();
  if (s.sources.size() > kMax32 || s.blocks.size() > kMax32)
    return "more than 2^32 - 1 sources or blocks";
  std::uint64_t n = 0;
  if (__builtin_mul_overflow(std::uint64_t{s.sources.size()}, std::uint64_t{s.blocks.size()}, &n) ||
      __builtin_mul_overflow(n, std::uint64_t{s.settings.throws}, &n))
    return "sources x blocks x throws overflows 2^64 trajectories";
  return std::nullopt;
}

}  // namespace pierre::sim
