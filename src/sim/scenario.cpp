#include "pierre/sim/scenario.hpp"

namespace pierre::sim {

std::vector<std::size_t> sources_against_main_direction(const Scenario& s) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < s.sources.size(); ++i) {
    const geometry::Vec2 p = s.sources[i].position;
    int segment = -1;
    if (const auto above = s.profile.line_above(p.x, p.z); above && above->ground)
      segment = above->segment;  // inside the rock: the ground over it
    else if (const auto below = s.profile.ground_below(p.x, p.z))
      segment = below->segment;
    else if (const auto top = s.profile.top_ground(p.x))
      segment = top->segment;
    // Rising along the vertex order: it falls towards the first vertex. (Level ground says
    // nothing; a vertical face is never the ground under a point.)
    if (segment >= 0 && s.profile.segment(segment).d.z > 0.0) out.push_back(i);
  }
  return out;
}

}  // namespace pierre::sim
