// Crest, toe and height H of a quarry section (design-checks.md §2, "Crest, toe, H").
//
// Crest: given (as a chainage x), or the highest vertex of the section (of several at the
// same height, the one nearest the runout end: the edge of the face, not the bench behind it).
// Toe: given (as a chainage x), or found: walking from the crest towards the runout end, the
// first vertex from which every later segment is flatter than the floor angle (default 15°).
// A segment's inclination is measured against the main direction: atan2(|dz|, dx·dir) in
// [0°, 180°], so a vertical (90°) or overhanging (> 90°) segment is never floor.
// H = crest z − toe z, given or derived; both are reported.
//
// The floor is the profile past the toe: `floor_segment` is the index of its first segment,
// for sim::SimulationSettings::floor_segment. A toe given inside a segment makes that segment
// the first floor segment here; the quarry reader cuts the segment at the toe first, so that
// the floor starts exactly there.
// Distances are horizontal, from the toe, along the main direction (Profile::main_direction).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "pierre/geometry/profile.hpp"
#include "pierre/stats/outcome.hpp"

namespace pierre::design {

enum class GeometryOrigin { given, found };
std::string_view to_string(GeometryOrigin o);  // "given", "found"

struct QuarryGeometryInput {
  std::optional<double> crest_x;  // m
  std::optional<double> toe_x;    // m
  std::optional<double> height;   // m
  double floor_angle_deg = 15;
};

struct QuarryGeometry {
  geometry::Vec2 crest, toe;  // m
  GeometryOrigin crest_origin = GeometryOrigin::found;
  GeometryOrigin toe_origin = GeometryOrigin::found;
  GeometryOrigin height_origin = GeometryOrigin::found;
  std::optional<std::size_t> crest_vertex, toe_vertex;  // when they are vertices
  double height = 0;          // H used, m
  double height_derived = 0;  // crest z − toe z, m (equals `height` unless H was given)
  int floor_segment = -1;     // first segment of the floor
  int direction = 1;          // Profile::main_direction
  double floor_length = 0;    // horizontal distance from the toe to the runout end, m
  double source_end_distance = 0;  // distance of the source end from the toe, m (<= 0 usually)
  double floor_angle_deg = 15;
};

// Inclination of the segment a → b against the main direction `dir` (+1 or −1), degrees: 0 level,
// 90 vertical, above 90 overhanging. The toe finder's floor is flatter than the floor angle.
double inclination_deg(geometry::Vec2 a, geometry::Vec2 b, int dir);

stats::Outcome<QuarryGeometry> quarry_geometry(const geometry::Profile& profile,
                                               const QuarryGeometryInput& input);

// Horizontal distance of x from the toe along the main direction (negative behind the toe).
inline double distance_from_toe(const QuarryGeometry& g, double x) {
  return (x - g.toe.x) * g.direction;
}

}  // namespace pierre::design
