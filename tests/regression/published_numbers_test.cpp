// Whole runs of the shipped examples, as a user runs them (the real binary, the examples' own
// seeds), against the numbers the thesis publishes. The examples are reconstructions: where the
// thesis does not print a geometry or the masses, their headers say what was assumed and how far
// pierre's results stand from the published ones. What the bands catch is a change in the model
// or the presets that moves the results by more than the sampling error (model-2d.md §1: with
// k_t,ref = 0.5 instead of 0.95 the quarry RD50/H falls from about 0.39 to 0.07).
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

// Each band is the published value moved by the reconstruction's documented gap, measured once
// over eight seeds (1-8, 2026-11-24) and stated here, ± 4 standard deviations of the example's
// own seed-to-seed spread (its sampling error at its size): centred on what the example should
// give, and as wide on both sides.

// Vaujany, thesis Table 7.2 (2-D model, truncated-normal roughness, shape factor): P95 speed
// 20.8 m/s at Screen 1 and 21.5 m/s at Screen 2; §7.2.1: P95 passing height 3.42 m and 3.56 m.
// The reconstructed slope (examples/vaujany-2d header) runs faster and higher: over eight seeds
// the P95 speeds average 1.10 × the published (22.85 and 23.70 m/s, sd 0.6 m/s) and the P95
// heights the published + 0.62 m (4.09 and 4.13 m, sd 0.25 m).
TEST_F(Published, VaujanyScreensP95AgainstTable72) {
  const auto j = run_example("vaujany-2d");
  ASSERT_EQ(j["lines"].size(), 2u);
  const double speed[] = {20.8, 21.5}, height[] = {3.42, 3.56};
  constexpr double kSpeedGap = 1.10, kSpeedSd = 0.6, kHeightGap = 0.62, kHeightSd = 0.25;
  for (int i = 0; i < 2; ++i) {
    const auto& line = j["lines"][i];
    SCOPED_TRACE(line["name"].get<std::string>());
    EXPECT_NEAR(line["speed_m_s"]["p95"].get<double>(), kSpeedGap * speed[i], 4 * kSpeedSd);
    EXPECT_NEAR(line["passing_height_m"]["p95"].get<double>(), height[i] + kHeightGap,
                4 * kHeightSd);
  }
}

// The Austrian quarries, thesis Tables 6.2 and 6.3, the "calculated" average rows: RD50/H 0.39,
// RD95/H 0.92, ID50/H 0.11. examples/quarry-austria (illustrative sections and masses, see
// docs/quarry.md) gives over eight seeds 1.08, 1.15 and 1.14 × those (0.420, 1.059, 0.1254;
// sd 0.011, 0.027, 0.002).
TEST_F(Published, QuarryAveragesAgainstTables62And63) {
  const auto j = run_example("quarry-austria");
  const auto& a = j["quarry_average"];
  EXPECT_NEAR(a["RD50_h"].get<double>(), 1.08 * 0.39, 4 * 0.011);
  EXPECT_NEAR(a["RD95_h"].get<double>(), 1.15 * 0.92, 4 * 0.027);
  EXPECT_NEAR(a["ID50_h"].get<double>(), 1.14 * 0.11, 4 * 0.002);
}

}  // namespace
