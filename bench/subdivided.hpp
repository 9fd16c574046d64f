// The quarry section subdivided into collinear pieces: for bench_sim and bench_one_run.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include "pierre/sim/scenario.hpp"

namespace pierre::bench {

// The same geometry with every segment cut into equal collinear pieces (model-2d.md §2: the
// same physics, so the same numbers).
inline sim::Scenario subdivided(const sim::Scenario& s, std::size_t target_vertices) {
  const auto& segs = s.profile.segments();
  const std::size_t per = std::max<std::size_t>(1, (target_vertices - 1) / segs.size());
  std::vector<geometry::Vec2> pts;
  std::vector<int> mats;
  for (const auto& g : segs)
    for (std::size_t k = 0; k < per; ++k) {
      const double u = double(k) / per;
      pts.push_back({g.a.x + u * (g.b.x - g.a.x), g.a.z + u * (g.b.z - g.a.z)});
      mats.push_back(g.material);
    }
  pts.push_back(segs.back().b);
  sim::Scenario out = s;
  out.profile = *geometry::Profile::build(pts, mats, nullptr);
  return out;
}

}  // namespace pierre::bench
