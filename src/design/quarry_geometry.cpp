#include "pierre/design/quarry_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "pierre/design/number_text.hpp"

namespace pierre::design {
namespace {

using geometry::Vec2;

std::string num(double v) { return number_text(v, 6); }

// A point of the section at a given chainage: a vertex, or inside a segment.
struct PointAt {
  Vec2 p;
  double order = 0;  // position along the profile: vertex i = i, inside segment j = j + 0.5
  std::optional<std::size_t> vertex;
  int segment = -1;  // the segment it lies in (inside), -1 for a vertex
};

std::vector<PointAt> points_at(const geometry::Profile& profile, double x) {
  const auto& v = profile.vertices();
  const double tol = 1e-9 * std::max(1.0, std::abs(x));
  std::vector<PointAt> out;
  for (std::size_t i = 0; i < v.size(); ++i)
    if (std::abs(v[i].x - x) <= tol) out.push_back({v[i], static_cast<double>(i), i, -1});
  for (std::size_t j = 0; j + 1 < v.size(); ++j) {
    const Vec2 a = v[j], b = v[j + 1];
    const double lo = std::min(a.x, b.x), hi = std::max(a.x, b.x);
    if (!(x > lo + tol && x < hi - tol)) continue;
    const double t = (x - a.x) / (b.x - a.x);
    out.push_back({{x, a.z + t * (b.z - a.z)}, static_cast<double>(j) + 0.5, std::nullopt,
                   static_cast<int>(j)});
  }
  return out;
}

}  // namespace

double inclination_deg(Vec2 a, Vec2 b, int dir) {
  return geometry::degrees(std::atan2(std::abs(b.z - a.z), (b.x - a.x) * dir));
}

std::string_view to_string(GeometryOrigin o) {
  return o == GeometryOrigin::given ? "given" : "found";
}

stats::Outcome<QuarryGeometry> quarry_geometry(const geometry::Profile& profile,
                                               const QuarryGeometryInput& in) {
  using Result = stats::Outcome<QuarryGeometry>;
  const auto& v = profile.vertices();
  const std::size_t n = v.size();
  if (n < 2) return Result::failure("the section has fewer than two vertices");
  if (!(in.floor_angle_deg > 0 && in.floor_angle_deg < 90))
    return Result::failure("floor angle " + num(in.floor_angle_deg) + "° is not in (0°, 90°)");

  QuarryGeometry g;
  g.direction = profile.main_direction();
  g.floor_angle_deg = in.floor_angle_deg;

  // The toe when given: the lowest point at its chainage (below an overhang, the floor).
  std::optional<PointAt> toe_given;
  if (in.toe_x) {
    const auto pts = points_at(profile, *in.toe_x);
    if (pts.empty())
      return Result::failure("the toe x = " + num(*in.toe_x) + " m is outside the section [" +
                             num(profile.x_min()) + ", " + num(profile.x_max()) + "] m");
    toe_given = *std::min_element(pts.begin(), pts.end(), [](const PointAt& a, const PointAt& b) {
      return a.p.z < b.p.z || (a.p.z == b.p.z && a.order > b.order);
    });
  }

  // Crest.
  double crest_order = 0;
  if (in.crest_x) {
    const auto pts = points_at(profile, *in.crest_x);
    if (pts.empty())
      return Result::failure("the crest x = " + num(*in.crest_x) + " m is outside the section [" +
                             num(profile.x_min()) + ", " + num(profile.x_max()) + "] m");
    const PointAt c = *std::max_element(pts.begin(), pts.end(), [](const PointAt& a, const PointAt& b) {
      return a.p.z < b.p.z || (a.p.z == b.p.z && a.order < b.order);
    });
    g.crest = c.p;
    g.crest_vertex = c.vertex;
    g.crest_origin = GeometryOrigin::given;
    crest_order = c.order;
  } else {
    const double limit = toe_given ? toe_given->order : static_cast<double>(n - 1);
    std::size_t best = 0;
    for (std::size_t i = 0; i < n && static_cast<double>(i) <= limit; ++i)
      if (v[i].z >= v[best].z) best = i;  // ties: the one nearest the runout end
    g.crest = v[best];
    g.crest_vertex = best;
    g.crest_origin = GeometryOrigin::found;
    crest_order = static_cast<double>(best);
  }

  // Toe.
  if (toe_given) {
    if (toe_given->order < crest_order)
      return Result::failure("the toe x = " + num(*in.toe_x) + " m lies before the crest (x = " +
                             num(g.crest.x) + " m) along the section");
    g.toe = toe_given->p;
    g.toe_vertex = toe_given->vertex;
    g.toe_origin = GeometryOrigin::given;
    g.floor_segment = toe_given->vertex ? static_cast<int>(*toe_given->vertex) : toe_given->segment;
    if (g.floor_segment >= static_cast<int>(n) - 1)
      return Result::failure("the toe x = " + num(*in.toe_x) +
                             " m is the section's last vertex: there is no floor past it");
  } else {
    // flat_from[i]: every segment from vertex i on is flatter than the floor angle.
    std::vector<bool> flat_from(n, true);
    for (std::size_t j = n - 1; j-- > 0;)
      flat_from[j] = flat_from[j + 1] && inclination_deg(v[j], v[j + 1], g.direction) < in.floor_angle_deg;
    const auto start = static_cast<std::size_t>(std::ceil(crest_order));
    std::optional<std::size_t> toe;
    for (std::size_t i = start; i + 1 < n; ++i)
      if (flat_from[i]) {
        toe = i;
        break;
      }
    if (!toe)
      return Result::failure("a section with no toe: it does not end in a floor flatter than " +
          num(in.floor_angle_deg) + "° past the crest at x = " + num(g.crest.x) +
          " m (give the toe)");
    g.toe = v[*toe];
    g.toe_vertex = *toe;
    g.toe_origin = GeometryOrigin::found;
    g.floor_segment = static_cast<int>(*toe);
  }

  g.height_derived = g.crest.z - g.toe.z;
  if (in.height) {
    if (!(*in.height > 0)) return Result::failure("the height H = " + num(*in.height) + " m is not > 0");
    g.height = *in.height;
    g.height_origin = GeometryOrigin::given;
  } else {
    if (!(g.height_derived > 0))
      return Result::failure("the crest (z = " + num(g.crest.z) + " m) is not above the toe (z = " +
          num(g.toe.z) + " m): H = " + num(g.height_derived) + " m");
    g.height = g.height_derived;
    g.height_origin = GeometryOrigin::found;
  }
  const double x_end = g.direction > 0 ? profile.x_max() : profile.x_min();
  g.floor_length = distance_from_toe(g, x_end);
  g.source_end_distance = distance_from_toe(g, g.direction > 0 ? profile.x_min() : profile.x_max());
  return Result::success(g);
}

}  // namespace pierre::design
