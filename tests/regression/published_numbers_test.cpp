// Whole runs of the shipped examples, as a user runs them (the real binary, the examples' own
// seeds), against the numbers the thesis publishes. The examples are reconstructions: where the
// thesis does not print a geometry or the masses, their headers say what was assumed and how far
// pierre's results stand from the published ones. Each band below is the published value with
// that documented gap and a margin for it; what it catches is a change in the model or the
// presets that moves the results by more (model-2d.md §1: with k_t,ref = 0.5 instead of 0.95 the
// quarry RD50/H falls from about 0.39 to 0.07).
#include <gtest/gtest.h>

#include <string>

#include "support/cli_fixture.hpp"

namespace {

namespace fs = std::filesystem;

class Published : public pierre::test::PierreCli {
 protected:
  nlohmann::json run_example(const char* name) {
    const fs::path out = dir_ / name;
    const auto r = pierre(std::string("run ") + PIERRE_SOURCE_DIR + "/examples/" + name +
                          "/scenario.toml --quiet --out " + q(out));
    EXPECT_EQ(r.code, 0) << r.err;
    return summary(out);
  }
};

// Vaujany, thesis Table 7.2 (2-D model, truncated-normal roughness, shape factor): P95 speed
// 20.8 m/s at Screen 1 and 21.5 m/s at Screen 2; §7.2.1: P95 passing height 3.42 m and 3.56 m.
// The reconstructed slope (examples/vaujany-2d header) runs about 10 % faster (22.7 and 23.8 m/s
// over six seeds) and 0.6–0.8 m higher: the bands are [−5 %, +18 %] of the speeds and
// [−0.3 m, +1.0 m] of the heights.
TEST_F(Published, VaujanyScreensP95AgainstTable72) {
  const auto j = run_example("vaujany-2d");
  ASSERT_EQ(j["lines"].size(), 2u);
  const double speed[] = {20.8, 21.5}, height[] = {3.42, 3.56};
  for (int i = 0; i < 2; ++i) {
    const auto& line = j["lines"][i];
    SCOPED_TRACE(line["name"].get<std::string>());
    const double v95 = line["speed_m_s"]["p95"].get<double>();
    const double h95 = line["passing_height_m"]["p95"].get<double>();
    EXPECT_GE(v95, 0.95 * speed[i]);
    EXPECT_LE(v95, 1.18 * speed[i]);
    EXPECT_GE(h95, height[i] - 0.3);
    EXPECT_LE(h95, height[i] + 1.0);
  }
}

// The Austrian quarries, thesis Tables 6.2 and 6.3, the "calculated" average rows: RD50/H 0.39,
// RD95/H 0.92, ID50/H 0.11. examples/quarry-austria (illustrative sections and masses, see
// docs/quarry.md) gives 0.41–0.42, 1.03–1.08 and 0.12–0.13 over six seeds: the bands are ±15 %
// of RD50/H, [−8 %, +25 %] of RD95/H and [0.08, 0.15] for ID50/H.
TEST_F(Published, QuarryAveragesAgainstTables62And63) {
  const auto j = run_example("quarry-austria");
  const auto& a = j["quarry_average"];
  const double rd50 = a["RD50_h"].get<double>(), rd95 = a["RD95_h"].get<double>(),
               id50 = a["ID50_h"].get<double>();
  EXPECT_NEAR(rd50, 0.39, 0.15 * 0.39);
  EXPECT_GE(rd95, 0.92 * 0.92);
  EXPECT_LE(rd95, 1.25 * 0.92);
  EXPECT_GE(id50, 0.08);
  EXPECT_LE(id50, 0.15);
}

}  // namespace
