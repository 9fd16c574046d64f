// io::equal_scale_bounds: a section drawn at one scale holds all of its extent with a margin
// above and below, whatever the rounding of the bounds to tick values.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "pierre/io/chart_scale.hpp"

namespace {

using pierre::io::AxisBounds;
using pierre::io::equal_scale_bounds;

// What every drawing must satisfy: the extent and its margin inside, the same metres per pixel
// both ways up to the widening of the upper bounds to a tick (at most half a tick step, which
// is at most half the window), and bounds on multiples of half a power of ten.
void expect_drawable(double xmin, double xmax, double zmin, double zmax, double w, double h) {
  const AxisBounds b = equal_scale_bounds(xmin, xmax, zmin, zmax, w, h);
  const double margin = 0.05 * std::max(zmax - zmin, 1e-9);
  SCOPED_TRACE(testing::Message() << "x " << xmin << ".." << xmax << ", z " << zmin << ".." << zmax
                                  << " in " << w << " x " << h << " px -> x " << b.x0 << ".."
                                  << b.x1 << ", z " << b.z0 << ".." << b.z1);
  EXPECT_LE(b.x0, xmin);
  EXPECT_GE(b.x1, xmax);
  EXPECT_LE(b.z0, zmin - margin * (1 - 1e-12));
  EXPECT_GE(b.z1, zmax + margin * (1 - 1e-12));
  const double across = (b.x1 - b.x0) / w, up = (b.z1 - b.z0) / h;
  EXPECT_LE(std::max(across, up) / std::min(across, up), 1.5 + 1e-12);
  // Each bound a multiple of a tick step k · 10^e / 2 that is not tiny against its window (at
  // least a two-hundredth of it): Excel labels the ticks from the bounds.
  auto on_tick = [](double v, double window) {
    for (int e = -12; e <= 12; ++e) {
      const double step = std::pow(10.0, e) / 2;
      if (step < window / 200) continue;
      const double k = v / step;
      if (std::abs(k - std::round(k)) < 1e-9 * std::max(1.0, std::abs(k))) return true;
    }
    return false;
  };
  for (double v : {b.x0, b.x1}) EXPECT_TRUE(on_tick(v, b.x1 - b.x0)) << v << " is not a tick value";
  for (double v : {b.z0, b.z1}) EXPECT_TRUE(on_tick(v, b.z1 - b.z0)) << v << " is not a tick value";
}

// The quarry section of Preg 1 (examples/quarry-austria): a crest at 20 m over an 80 m floor.
// The lower bound went down to −5 m and the window, sized from z0 = zmin − margin, stopped at
// 20 m: the crest, and the paths starting above it, ran along the chart's top edge.
TEST(ChartScale, TheCrestIsInsideTheChart) {
  const double w = 620 * 2.0 * 0.85, h = 330 * 1.4 * 0.68;
  const AxisBounds b = equal_scale_bounds(0, 80, 0, 20, w, h);
  EXPECT_GE(b.z1, 21.0) << b.z0 << ".." << b.z1;
  expect_drawable(0, 80, 0, 20, w, h);
}

// A grid of extents, wide and tall, at and off round numbers, in the chart sizes the report
// uses (the profile 1.6 × 1.6, the quarry section 2.0 × 1.4 of the default 620 × 330 px).
TEST(ChartScale, EveryExtentIsHeldAtOneScale) {
  const double sizes[][2] = {{620 * 1.6 * 0.85, 330 * 1.6 * 0.68}, {620 * 2.0 * 0.85, 330 * 1.4 * 0.68},
                             {100, 400}};
  for (const auto& s : sizes)
    for (double x0 : {-37.5, 0.0, 5.0, 1234.0})
      for (double dx : {0.3, 12.0, 80.0, 486.0, 999.9, 25000.0})
        for (double z0 : {-120.0, -2.0, 0.0, 96.86})
          for (double dz : {0.0, 0.4, 20.0, 20.5, 302.0, 4000.0})
            expect_drawable(x0, x0 + dx, z0, z0 + dz, s[0], s[1]);
}

// Vaujany's profile (examples/vaujany-2d: x 0–486 m, z 97.9–349.95 m) in the Profile sheet's
// plot area, 843 px wide: at 359 px high (the fixed shape of before) its height set the scale
// and the axis ran to 750 m; at the fitting height the axis ends at 500 m, the first 50 m tick
// beyond 486 m, and no lower height does that.
TEST(ChartScale, TheChartIsAsTallAsTheSectionNeeds) {
  using pierre::io::fitting_height;
  const double w = 620 * 1.6 * 0.85, h = 330 * 0.68;
  EXPECT_EQ(equal_scale_bounds(0, 486, 97.9, 349.95, w, 1.6 * h).x1, 750);
  const double fit = fitting_height(0, 486, 97.9, 349.95, w, h, 2.6 * h);
  const AxisBounds b = equal_scale_bounds(0, 486, 97.9, 349.95, w, fit);
  EXPECT_EQ(b.x0, 0);
  EXPECT_EQ(b.x1, 500);
  EXPECT_GT(equal_scale_bounds(0, 486, 97.9, 349.95, w, fit - 1.6 * h / 200).x1, 500);
  expect_drawable(0, 486, 97.9, 349.95, w, fit);
  // A long flat section needs no more than the least height. A cliff is held by its height
  // even at the most: its axis is as short as there (round ticks), no shorter.
  EXPECT_EQ(fitting_height(0, 2000, 0, 40, w, h, 2.6 * h), h);
  const double cliff = fitting_height(0, 30, 0, 200, w, h, 2.6 * h);
  EXPECT_GT(cliff, 2 * h);
  EXPECT_EQ(equal_scale_bounds(0, 30, 0, 200, w, cliff).x1, equal_scale_bounds(0, 30, 0, 200, w, 2.6 * h).x1);
  EXPECT_GT(equal_scale_bounds(0, 30, 0, 200, w, cliff - 1.6 * h / 200).x1, equal_scale_bounds(0, 30, 0, 200, w, cliff).x1);
  EXPECT_EQ(fitting_height(0, NAN, 0, 200, w, h, 2.6 * h), 2.6 * h);
}

TEST(ChartScale, NothingToGoByLeavesTheDefaults) {
  for (const AxisBounds& b : {equal_scale_bounds(5, 5, 0, 1, 100, 100),
                              equal_scale_bounds(0, 1, 2, 1, 100, 100),
                              equal_scale_bounds(0, NAN, 0, 1, 100, 100),
                              equal_scale_bounds(0, 1, 0, 1, 0, 100)}) {
    EXPECT_EQ(b.x0, 0);
    EXPECT_EQ(b.x1, 1);
    EXPECT_EQ(b.z0, 0);
    EXPECT_EQ(b.z1, 1);
  }
}

// A curve's axis from its data's ends: the user review's speeds, 7.962… to 32.1 m/s, labelled
// 7.96209041749611, 12.9620904174961, … on an axis set to the data minimum; rounded they read
// 5, 10, …, 35.
TEST(ChartScale, AnAxisFromTheDataIsOnRoundNumbers) {
  const pierre::io::AxisRange r = pierre::io::round_axis(7.962090417496109, 32.1);
  EXPECT_EQ(r.lo, 5);
  EXPECT_EQ(r.hi, 35);
  EXPECT_EQ(r.step, 5);
}

// Whatever the range: it is held, in at most the intervals asked, the ends are multiples of the
// step, and the step is 1, 2, 2.5 or 5 times a power of ten.
TEST(ChartScale, EveryRangeIsHeldOnRoundTicks) {
  for (double lo : {-37.5, -0.004, 0.0, 0.0123, 7.962090417496109, 96.86, 1234.0})
    for (double span : {1e-3, 0.05, 0.7, 3.0, 24.14, 99.0, 1000.0, 31e3})
      for (int intervals : {4, 6, 8, 10}) {
        const double hi = lo + span;
        const pierre::io::AxisRange r = pierre::io::round_axis(lo, hi, intervals);
        SCOPED_TRACE(testing::Message() << lo << " " << hi << " " << intervals);
        ASSERT_GT(r.step, 0);
        EXPECT_LE(r.lo, lo);
        EXPECT_GE(r.hi, hi);
        const double n = (r.hi - r.lo) / r.step;
        EXPECT_LE(n, intervals + 1e-9);
        EXPECT_NEAR(r.lo / r.step, std::round(r.lo / r.step), 1e-9);
        EXPECT_NEAR(r.hi / r.step, std::round(r.hi / r.step), 1e-9);
        const double mantissa = r.step / std::pow(10.0, std::floor(std::log10(r.step) + 1e-12));
        EXPECT_TRUE(std::abs(mantissa - 1) < 1e-9 || std::abs(mantissa - 2) < 1e-9 ||
                    std::abs(mantissa - 2.5) < 1e-9 || std::abs(mantissa - 5) < 1e-9)
            << r.step;
        // Not coarser than needed: a step one notch finer would take more than `intervals`
        // (or the range is within the first notch of its decade).
        EXPECT_GT(n, intervals / 5.0) << r.step;
      }
  for (const auto& bad : {pierre::io::round_axis(5, 5), pierre::io::round_axis(2, 1),
                          pierre::io::round_axis(0, NAN)})
    EXPECT_EQ(bad.step, 0);
}

}  // namespace
