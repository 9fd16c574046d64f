#include "pierre/design/check_line.hpp"

#include <algorithm>

#include "pierre/design/number_text.hpp"

namespace pierre::design {

std::string_view to_string(CheckStatus s) {
  switch (s) {
    case CheckStatus::pass: return "PASS";
    case CheckStatus::fail: return "FAIL";
    case CheckStatus::warn: return "WARN";
    case CheckStatus::not_applicable: return "N/A";
  }
  return "N/A";
}

bool any_failure(const std::vector<CheckLine>& lines) {
  return std::any_of(lines.begin(), lines.end(),
                     [](const CheckLine& l) { return l.status == CheckStatus::fail; });
}

SampleNeeded sample_needed(double trajectories, std::uint32_t throws, double relative,
                           double tolerance) {
  const double factor = (relative / tolerance) * (relative / tolerance);
  SampleNeeded n;
  n.trajectories = std::ceil(trajectories * factor);
  if (throws > 0) n.throws = std::ceil(static_cast<double>(throws) * factor);
  return n;
}

std::string throws_needed_text(const SampleNeeded& needed) {
  if (!(needed.throws > 0)) return {};
  return ", i.e. throws = " + number_text(needed.throws, 9) + " per block and source";
}

std::string within_interval_text(std::string_view whose, double confidence, const std::string& upper) {
  return "within " + std::string(whose) + " " + number_text(100 * confidence) +
         " % bootstrap interval (up to " + upper + ")";
}

}  // namespace pierre::design
