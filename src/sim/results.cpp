#include "pierre/sim/results.hpp"

#include <cmath>

namespace pierre::sim {

std::string_view to_string(StopReason r) {
  switch (r) {
    case StopReason::energy: return "energy";
    case StopReason::friction: return "friction";
    case StopReason::boundary: return "boundary";
    case StopReason::time_limit: return "time-limit";
    case StopReason::impact_limit: return "impact-limit";
    case StopReason::numerical: return "numerical";
  }
  return "numerical";
}

double TrajectorySummary::runout() const { return std::abs(stop.x - start.x); }

}  // namespace pierre::sim
