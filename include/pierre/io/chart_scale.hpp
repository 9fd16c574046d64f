// The axis bounds of a chart drawn at one scale (a slope section: metres across the same as
// metres up), so that a 30° slope looks like one. Pure arithmetic, apart from the workbook.
#pragma once

namespace pierre::io {

struct AxisBounds {
  double x0 = 0, x1 = 1, z0 = 0, z1 = 1;  // m
};

// Bounds holding [xmin, xmax] × [zmin − m, zmax + m] (m: a twentieth of the height, so that a
// path at the crest is not drawn on the chart's edge) in a plot area of width × height px, at
// the same metres per pixel both ways, on round numbers (Excel labels the ticks from them):
// each bound is a multiple of half a power of ten, and rounding only widens. Invalid extents
// (xmax ≤ xmin, zmax < zmin, not finite) give nothing to go by: the bounds are left as
// {0, 1, 0, 1} and the caller keeps Excel's own.
AxisBounds equal_scale_bounds(double xmin, double xmax, double zmin, double zmax, double width,
                              double height);
bool valid_extent(double xmin, double xmax, double zmin, double zmax);

// The plot height, between min_height and max_height px, to give a section drawn at one scale
// in a plot area `width` px wide: the least at which its width, not its height, sets the scale
// (the horizontal axis is as short as it gets at max_height). A section of fixed shape drew
// Vaujany's 486 m slope on a 0–750 m axis: the chart's height bound the scale, and a third of
// the frame stood empty. Invalid extents give max_height.
double fitting_height(double xmin, double xmax, double zmin, double zmax, double width,
                      double min_height, double max_height);

// One axis of values from lo to hi on round numbers: a step of 1, 2, 2.5 or 5 × 10^k that
// cuts the range into at most `intervals`, and lo and hi moved out to multiples of it. Excel
// labels the ticks from the minimum on: from a data minimum of 7.962 m/s they read
// 7.96209041749611, 12.9620904174961, … (user review). An empty or invalid range (hi ≤ lo, not
// finite) is returned as it is, with a step of 0 (the caller keeps Excel's own).
struct AxisRange {
  double lo = 0, hi = 1, step = 0;
};
AxisRange round_axis(double lo, double hi, int intervals = 8);

}  // namespace pierre::io
