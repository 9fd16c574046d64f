// The slope profile: a polyline of vertices ordered from the source end, the air on the
// left of the walking direction (model-2d.md §1, thesis §3.1). Each segment carries a
// material index. Contact search and ground queries go through a bounding-volume tree
// over consecutive segments, so a 10 000-vertex section costs little more than a
// 10-vertex one (model-2d.md §2).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "pierre/geometry/vec2.hpp"

namespace pierre::geometry {

struct Segment {
  Vec2 a;             // start vertex (source side)
  Vec2 b;             // end vertex
  Vec2 d;             // unit direction a -> b
  Vec2 n;             // unit outward normal (left of d): points into the air
  double length = 0;  // |b - a|
  double x_lo = 0, x_hi = 0;  // horizontal extent
  int material = 0;   // index into the scenario's material list
};

// How the surface turns at a vertex, independent of the travel direction.
enum class VertexTurn : std::uint8_t { straight, convex, concave };

// A problem with the input polyline; `vertex` is the 0-based index of the offending vertex.
struct ProfileIssue {
  std::size_t vertex = 0;
  std::string what;
  std::optional<std::size_t> other_vertex;  // a crossing: where the segment met starts
};

// Where the flight leaves the ground: the segments it departs from have c = 0 exactly
// (model-2d.md §2). `tangent` marks a segment the block leaves along its own line (sliding
// off a convex vertex): gravity takes the block below that line at once, so it cannot be hit.
struct Departure {
  int segment[2] = {-1, -1};
  bool tangent[2] = {false, false};
  bool concave_vertex = false;  // departing from a concave vertex: entering a neighbour is a contact at t = 0
};

struct Contact {
  double t = 0;     // time from the start of the arc, s
  int segment = -1;
  double s = 0;     // distance along the segment from its start vertex, m
};

struct GroundPoint {
  double z = 0;
  int segment = -1;
};

class Profile {
 public:
  // Builds the profile; returns the issues instead when the polyline is unusable (fewer than
  // two vertices, repeated vertex, self-intersection, folding back on itself at a vertex,
  // non-finite coordinates, not one material a segment).
  static std::optional<Profile> build(const std::vector<Vec2>& vertices,
                                      const std::vector<int>& materials,
                                      std::vector<ProfileIssue>* issues);

  // The same profile with `point`, a point inside segment `segment`, as a vertex between two
  // collinear pieces of it (the same physics: model-2d.md §2); the issues when that cannot be
  // (the point off the segment's line, or so near an end that a piece has no length).
  std::optional<Profile> split_at(std::size_t segment, Vec2 point,
                                  std::vector<ProfileIssue>* issues) const;

  std::size_t segment_count() const { return segments_.size(); }
  const Segment& segment(std::size_t i) const { return segments_[i]; }
  const std::vector<Segment>& segments() const { return segments_; }
  const std::vector<Vec2>& vertices() const { return vertices_; }
  // Turn at the vertex between segment i and i + 1.
  VertexTurn turn_after(std::size_t i) const { return turns_[i]; }
  double x_min() const { return x_min_; }
  double x_max() const { return x_max_; }
  double z_min() const { return z_min_; }  // the lowest and highest vertex (m)
  double z_max() const { return z_max_; }
  // +1 when the profile runs towards increasing x (its source end has the smaller x).
  int main_direction() const { return main_direction_; }

  // Earliest contact of the block centre's parabola p(t) = p0 + v0 t - g t^2 / 2 (z)
  // with a segment, entering from the air side, for 0 < t < t_max (exact roots).
  std::optional<Contact> first_contact(Vec2 p0, Vec2 v0, double g, double t_max,
                                       const Departure& dep) const;

  // The first ground line met going straight down from (x, z) (matters under overhangs).
  std::optional<GroundPoint> ground_below(double x, double z) const;
  // The highest ground line at x.
  std::optional<GroundPoint> top_ground(double x) const;
  // The first line met going straight up from (x, z), strictly above it: a ground line (air
  // above it: the point is inside the rock) or a ceiling (the underside of an overhang, air
  // below it: the point is in the air). Vertical faces are passed by.
  struct LineAbove {
    double z = 0;
    int segment = -1;
    bool ground = false;
  };
  std::optional<LineAbove> line_above(double x, double z) const;

  // Largest vertical distance between the parabola and the ground directly below it over
  // the arc 0 <= t <= t_end (model-2d.md §4). Exact: piecewise concave, maximised per segment.
  // Returns at_least when the arc cannot exceed it (the trajectory's running maximum), which
  // lets the search skip every part of the section that cannot hold a new maximum. seg_a and
  // seg_b, when known, are the segments under the arc's two ends (where it departs and lands).
  double max_height_above_ground(Vec2 p0, Vec2 v0, double g, double t_end,
                                 double at_least = 0.0, int seg_a = -1, int seg_b = -1) const;

 private:
  // Bounds of the segments [first, last): their box, and a band about the chord from the
  // first to the last vertex — every point of them has z − (icpt + slope·x) in [off_lo, off_hi].
  // On a sloping or finely subdivided section the band is far tighter than the box.
  struct Node {
    double x_lo = 0, x_hi = 0, z_lo = 0, z_hi = 0;
    double slope = 0, icpt = 0, off_lo = 0, off_hi = 0;
    int first = 0, last = 0;
    bool straight = false;  // collinear segments: one line for the search
    int left = -1, right = -1;
  };
  int build_node(int first, int last);
  // The segments a vertical line at x crosses (vertical faces left out), each with its z there,
  // from the leaves of the tree that `prune(node)` does not cut off (defined in profile.cpp).
  template <class Prune, class Visit>
  void segments_at(double x, Prune prune, Visit visit) const;
  // The general searches behind the closed-form fast paths of the two queries above (kept
  // out of line so that the fast paths stay small). `under`: segment_under(p0.x) for a flight
  // from a source, when already found.
  std::optional<Contact> first_contact_search(Vec2 p0, Vec2 v0, double g, double t_max,
                                              const Departure& dep, int under = -1) const;
  // first_contact's march for a hop whose departure (or starting segment) is in run r, which
  // holds no contact: the runs ahead solved in order, as first_contact_search does. 1: found
  // (out); 0: none before the section ends; -1: first_contact_search must decide (none within
  // its march).
  int march_runs(Vec2 p0, Vec2 v0, double g, double t_max, int r, Contact& out) const;
  // first_contact's search for an arc that starts on or over segment j (kind 1: departed from
  // it, without a neighbour; 0: a flight from a source above it): j, its run, then march_runs.
  // Returns as march_runs does.
  int contact_from(Vec2 p0, Vec2 v0, double g, double t_max, int j, int kind, Contact& out) const;
  // The contact at `along` metres on the line of the collinear segments [first, last) from a
  // (direction d): the segment it lies on (by bisection) and the distance along that segment.
  Contact contact_on_line(Vec2 a, Vec2 d, int first, int last, double t, double along) const;
  // The last segment whose start is not beyond x along the main direction (x-monotone sections).
  int segment_under(double x) const;
  // max_height_above_ground over the runs [r_lo, r_hi] of an x-monotone section, each one line.
  double max_height_runs(Vec2 p0, Vec2 v0, double g, double t_end, double best, int r_lo,
                         int r_hi) const;
  double max_height_search(Vec2 p0, Vec2 v0, double g, double t_end, double at_least, int seg_a,
                           int seg_b) const;
  // A maximal straight run of collinear segments [begin, end): one line for every search.
  struct Run {
    Vec2 a;              // its first vertex
    Vec2 d, n;           // unit direction and air-side normal (of its first segment)
    double length = 0;   // along d from a to its last vertex
    double x_lo = 0, x_hi = 0;  // horizontal extent
    double slope = 0;    // dz/dx (0 when vertical: d.x == 0)
    int begin = 0, end = 0;
  };

  std::vector<Vec2> vertices_;
  std::vector<Segment> segments_;
  std::vector<VertexTurn> turns_;
  std::vector<Node> nodes_;
  std::vector<int> parents_;  // parent of each node (-1 for the root)
  std::vector<int> leaf_of_;  // leaf node holding each segment
  std::vector<Run> runs_;      // in segment order
  std::vector<int> run_of_;    // run holding each segment
  double x_min_ = 0, x_max_ = 0, z_min_ = 0, z_max_ = 0;
  int main_direction_ = 1;
  bool x_monotone_ = true;  // every vertical line meets the ground once: no overhangs
};

}  // namespace pierre::geometry
