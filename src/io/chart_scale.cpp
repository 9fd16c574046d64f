#include "pierre/io/chart_scale.hpp"

#include <algorithm>
#include <cmath>

namespace pierre::io {

bool valid_extent(double xmin, double xmax, double zmin, double zmax) {
  return std::isfinite(xmin) && std::isfinite(xmax) && std::isfinite(zmin) &&
         std::isfinite(zmax) && xmax > xmin && zmax >= zmin;
}

AxisBounds equal_scale_bounds(double xmin, double xmax, double zmin, double zmax, double width,
                              double height) {
  AxisBounds b;
  if (!valid_extent(xmin, xmax, zmin, zmax) || !(width > 0) || !(height > 0)) return b;
  const double margin = 0.05 * std::max(zmax - zmin, 1e-9);
  const double lo = zmin - margin, hi = zmax + margin;
  // Half a power of ten below the range: 50 m ticks on a few hundred metres.
  auto round_step = [](double range) { return std::pow(10.0, std::floor(std::log10(range))) / 2; };
  double per_px = std::max((xmax - xmin) / width, (hi - lo) / height);
  // The lower bounds move down to round numbers, and the window must still reach the upper
  // ends from there: widen the scale until it does (the steps it implies can only grow, so a
  // few rounds settle it).
  double xs = 0, zs = 0;
  for (int round = 0; round < 8; ++round) {
    xs = round_step(per_px * width);
    zs = round_step(per_px * height);
    b.x0 = std::floor(xmin / xs) * xs;
    b.z0 = std::floor(lo / zs) * zs;
    const double need = std::max((xmax - b.x0) / width, (hi - b.z0) / height);
    if (need <= per_px) break;
    per_px = need;
  }
  b.x1 = std::max(std::ceil((b.x0 + per_px * width) / xs) * xs, std::ceil(xmax / xs) * xs);
  b.z1 = std::max(std::ceil((b.z0 + per_px * height) / zs) * zs, std::ceil(hi / zs) * zs);
  return b;
}

double fitting_height(double xmin, double xmax, double zmin, double zmax, double width,
                      double min_height, double max_height) {
  if (!valid_extent(xmin, xmax, zmin, zmax) || !(width > 0) || !(min_height <= max_height))
    return max_height;
  auto span = [&](double h) {
    const AxisBounds b = equal_scale_bounds(xmin, xmax, zmin, zmax, width, h);
    return b.x1 - b.x0;
  };
  // The span only shrinks as the height grows (a taller area lets the width set the scale), in
  // steps, as the bounds move from one tick to the next: the first height of the last step.
  const double best = span(max_height);
  constexpr int kSteps = 200;
  for (int k = 0; k <= kSteps; ++k) {
    const double h = min_height + (max_height - min_height) * k / kSteps;
    if (span(h) <= best * (1 + 1e-12)) return h;
  }
  return max_height;
}

AxisRange round_axis(double lo, double hi, int intervals) {
  if (!(std::isfinite(lo) && std::isfinite(hi) && hi > lo && intervals > 0)) return {lo, hi, 0};
  const double decade = std::pow(10.0, std::floor(std::log10((hi - lo) / intervals)));
  for (double m : {1.0, 2.0, 2.5, 5.0, 10.0, 20.0}) {
    const double step = m * decade;
    const double a = std::floor(lo / step) * step, b = std::ceil(hi / step) * step;
    if ((b - a) / step <= intervals + 1e-9) return {a, b, step};
  }
  return {lo, hi, 0};  // only for intervals < 4: 20 × decade spans any range in intervals / 2 + 2
}

}  // namespace pierre::io
