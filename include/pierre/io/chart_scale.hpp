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

}  // namespace pierre::io
