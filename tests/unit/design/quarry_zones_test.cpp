// Zones, governing distances and every quarry check line passing and failing
// (design-checks.md §2, "Zones").
#include "pierre/design/quarry_zones.hpp"

#include <gtest/gtest.h>

#include <boost/math/special_functions/erf.hpp>
#include <cmath>
#include <limits>
#include <random>

#include "pierre/design/number_kind.hpp"
#include "pierre/design/number_text.hpp"
#include "support/builders.hpp"
#include "support/seeded_samples.hpp"

namespace pierre::design {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// A 20 m vertical face at x = 10 over a 400 m floor.
QuarryGeometry face(double H = 20) {
  const auto p = test::make_profile({{0, H}, {10, H}, {10, 0}, {410, 0}});
  return *quarry_geometry(p, {});
}

// Distances from runouts (m; +inf: left the profile) with the first impact at a fifth of each.
QuarryDistances distances(const std::vector<double>& rd, const QuarryGeometry& g) {
  QuarryDistances d;
  std::uint64_t k = 0;
  for (double r : rd) {
    sim::TrajectorySummary t;
    t.trajectory = k++;
    t.start = {10.5, g.crest.z + 0.5};
    t.duration = 4;
    if (std::isinf(r)) {
      t.stop = {g.toe.x + g.floor_length, 0};
      t.stop_reason = sim::StopReason::boundary;
    } else {
      t.stop = {g.toe.x + r, 0};
      t.stop_reason = sim::StopReason::energy;
    }
    if (r > 0) {
      t.has_floor_contact = true;
      t.floor_contact = {g.toe.x + std::min(r, g.floor_length) / 5, 0};
    }
    d.add(t, g);
  }
  return d;
}

std::vector<double> one_to(int n) {
  std::vector<double> v;
  for (int i = 1; i <= n; ++i) v.push_back(i);
  return v;
}

std::vector<double> lognormal_runouts(std::size_t n, double H, std::uint64_t seed) {
  std::mt19937_64 g(seed);
  std::vector<double> v;
  for (std::size_t i = 0; i < n; ++i) {
    const double u = test::seeded_uniform(g);
    v.push_back(H * std::exp(-0.9 - 0.5 * std::sqrt(2.0) * boost::math::erfc_inv(2 * u)));
  }
  return v;
}

QuarryRuleSet thesis() {
  QuarryRuleSet r;
  r.name = "quarry-thesis-2015";
  return r;
}
QuarryRuleSet conservative() {
  QuarryRuleSet r;
  r.name = "quarry-conservative";
  r.governing = {QuarryGoverning::maximum, QuarryGoverning::lognormal};
  r.lognormal_percentile = 99;
  return r;
}

QuarrySectionInput section(const std::string& name, const std::vector<double>& rd,
                           QuarryRuleSet rules = thesis(), double H = 20) {
  QuarrySectionInput s;
  s.spec.name = name;
  s.rules = std::move(rules);
  s.geometry = face(H);
  s.distances = distances(rd, s.geometry);
  return s;
}

const CheckLine* find(const QuarryDesign& d, const std::string& subject, const std::string& id) {
  for (const auto& l : d.checks)
    if (l.subject == subject && l.id == id) return &l;
  return nullptr;
}

TEST(QuarryZones, WorkAreasInsideAndOutsideTheDangerZone) {
  auto s = section("Face A", one_to(100));
  s.spec.work_areas = {{"crusher", 120}, {"haul-road", 50}};
  const auto out = design_quarry({s}, 1);
  ASSERT_TRUE(out.design) << out.error;
  const QuarryDesign& d = *out.design;
  EXPECT_DOUBLE_EQ(d.sections[0].danger_zone, 95.05);  // P95 of 1..100
  EXPECT_DOUBLE_EQ(d.sections[0].first_impact_zone, 95.05 / 5);
  // How it was found, in /H to two decimals as Tables 6.2/6.3 print it: 95.05 m / 20 m.
  EXPECT_EQ(d.rows[0].rd_gov.how, "P95 4.75 H");
  const CheckLine* crusher = find(d, "Face A", "zone.crusher");
  const CheckLine* road = find(d, "Face A", "zone.haul-road");
  ASSERT_TRUE(crusher && road);
  EXPECT_EQ(crusher->status, CheckStatus::pass);
  EXPECT_EQ(road->status, CheckStatus::fail);
  EXPECT_DOUBLE_EQ(road->value, 50);
  EXPECT_DOUBLE_EQ(road->limit, 95.05);
  EXPECT_EQ(road->unit, "m");
  // The reason in the decimals of the value and limit cells, with the share of the blocks that
  // stop beyond the area: of the runouts 1..100 m, 51..100 lie beyond 50 m, none beyond 120 m.
  EXPECT_EQ(road->reason, "50.00 m from the toe is inside the danger zone: RD_gov = 95.05 m (P95 4.75 H); "
                          "50 % of the section's 100 simulated blocks stop beyond 50.00 m");
  EXPECT_EQ(crusher->reason,
            "120.00 m from the toe is outside the danger zone: RD_gov = 95.05 m (P95 4.75 H); "
            "0 % of the section's 100 simulated blocks stop beyond 120.00 m");
  EXPECT_TRUE(any_failure(d.checks));
}

// A work area outside the zone but inside its bootstrap interval: the margin is within the
// sampling uncertainty, so the line WARNs instead of passing; one beyond the interval passes.
TEST(QuarryZones, AWorkAreaWithinTheZonesIntervalWarns) {
  auto probe = section("Face A", one_to(100));
  const auto first = design_quarry({probe}, 1);
  ASSERT_TRUE(first.design) << first.error;
  const auto& ci = first.design->rows[0].rd_interval;
  ASSERT_TRUE(ci);
  const double zone = first.design->sections[0].danger_zone, upper = ci->upper * 20;  // H = 20 m
  ASSERT_GT(upper, zone + 0.2);  // P95 of 1..100 resampled: the interval reaches past 95.05 m
  auto s = section("Face A", one_to(100));
  s.spec.work_areas = {{"near", 0.5 * (zone + upper)}, {"far", upper + 0.1}};
  const auto out = design_quarry({s}, 1);  // the same seed: the same interval
  ASSERT_TRUE(out.design) << out.error;
  const CheckLine* near = find(*out.design, "Face A", "zone.near");
  const CheckLine* far = find(*out.design, "Face A", "zone.far");
  ASSERT_TRUE(near && far);
  EXPECT_EQ(near->status, CheckStatus::warn);
  EXPECT_NE(near->reason.find("is outside the danger zone: RD_gov = 95.05 m (P95 4.75 H), but within "
                              "its 90 % bootstrap interval (up to "),
            std::string::npos)
      << near->reason;
  EXPECT_EQ(far->status, CheckStatus::pass);
  EXPECT_EQ(far->reason.find("bootstrap interval"), std::string::npos) << far->reason;
  EXPECT_FALSE(any_failure(out.design->checks));
}

// A group's pooled zone can fall short of one section's own percentile: an area between the two
// WARNs. Runouts 1..100 m and 1..50 m under two 20 m faces pool to 150 values of k/20 H; their
// P95 (type 7, position 141.55 of 0..149: k = 92 and 93) is 92.55 m, while the first face's own
// P95 is 95.05 m.
TEST(QuarryZones, AnAreaInsideItsSectionsOwnPercentileButOutsideThePooledZoneWarns) {
  auto a = section("Face A", one_to(100));
  auto b = section("Face B", one_to(50));
  a.spec.group = b.spec.group = "AB";
  a.spec.work_areas = {{"shed", 94}, {"yard", 150}};
  const auto out = design_quarry({a, b}, 1);
  ASSERT_TRUE(out.design) << out.error;
  EXPECT_NEAR(out.design->sections[0].danger_zone, 92.55, 1e-9);
  const CheckLine* shed = find(*out.design, "Face A", "zone.shed");
  const CheckLine* yard = find(*out.design, "Face A", "zone.yard");
  ASSERT_TRUE(shed && yard);
  EXPECT_EQ(shed->status, CheckStatus::warn);
  // (Also inside the pooled zone's bootstrap interval: one "but" for both.)
  EXPECT_NE(shed->reason.find("inside this section's own P95 (95.05 m; the zone is the "
                              "group's, pooled)"),
            std::string::npos)
      << shed->reason;
  EXPECT_EQ(shed->reason.find("but"), shed->reason.rfind("but")) << shed->reason;
  EXPECT_EQ(yard->status, CheckStatus::pass);
  EXPECT_EQ(yard->reason.find("own P95"), std::string::npos) << yard->reason;
}

// A work area past the end of the modelled floor passes (outside the zone) but says that the
// ground there is not in the section (a new user's area at 80 m on a 50 m floor passed silently).
TEST(QuarryZones, AWorkAreaPastTheFloorSaysSo) {
  auto s = section("Face A", one_to(100));  // floor 400 m long, RD_gov 95.05 m
  s.spec.work_areas = {{"yard", 450}, {"road", 400}};
  const auto out = design_quarry({s}, 1);
  ASSERT_TRUE(out.design) << out.error;
  const CheckLine* yard = find(*out.design, "Face A", "zone.yard");
  const CheckLine* road = find(*out.design, "Face A", "zone.road");
  ASSERT_TRUE(yard && road);
  EXPECT_EQ(yard->status, CheckStatus::pass);
  EXPECT_EQ(yard->reason,
            "450.00 m from the toe is outside the danger zone: RD_gov = 95.05 m (P95 4.75 H); 0 % "
            "of the section's 100 simulated blocks stop beyond 450.00 m; the "
            "area lies past the end of the section's floor (400.00 m from the toe), on ground the "
            "section does not model: extend it");
  EXPECT_EQ(road->reason.find("past the end"), std::string::npos);  // at the floor's end: on it
}

TEST(QuarryZones, ConservativeTakesTheLargerOfMaximumAndLognormal) {
  auto s = section("Face A", lognormal_runouts(2000, 20, 5), conservative());
  const auto out = design_quarry({s}, 1);
  ASSERT_TRUE(out.design) << out.error;
  const QuarryRow& row = out.design->rows[0];
  ASSERT_TRUE(row.rd.fit);
  EXPECT_DOUBLE_EQ(row.rd_gov.maximum_h, row.rd.max_h);
  EXPECT_DOUBLE_EQ(row.rd_gov.lognormal_h, stats::value_at_exceedance(*row.rd.fit, 0.01));
  EXPECT_DOUBLE_EQ(row.rd_gov.value_h, std::max(row.rd_gov.maximum_h, row.rd_gov.lognormal_h));
  EXPECT_TRUE(std::isnan(row.rd_gov.percentile_h));
  EXPECT_NE(row.rd_gov.how.find("larger of"), std::string::npos);
  // The 95 % rule's zone is smaller.
  auto t = section("Face A", lognormal_runouts(2000, 20, 5));
  const auto out95 = design_quarry({t}, 1);
  EXPECT_LT(out95.design->sections[0].danger_zone, out.design->sections[0].danger_zone);
}

TEST(QuarryZones, DangerZoneBeyondTheProfileFails) {
  auto v = one_to(90);
  for (int i = 0; i < 10; ++i) v.push_back(kInf);
  auto s = section("Face A", v);
  s.spec.work_areas = {{"office", 390}};
  auto t = section("Face B", v);  // no work area: zone.extent says so
  const auto out = design_quarry({s, t}, 1);
  ASSERT_TRUE(out.design) << out.error;
  EXPECT_TRUE(std::isinf(out.design->sections[0].danger_zone));
  const CheckLine* office = find(*out.design, "Face A", "zone.office");
  ASSERT_TRUE(office);
  EXPECT_EQ(office->status, CheckStatus::fail);
  EXPECT_NE(office->reason.find("beyond the profile"), std::string::npos) << office->reason;
  const CheckLine* extent = find(*out.design, "Face B", "zone.extent");
  ASSERT_TRUE(extent);
  EXPECT_EQ(extent->status, CheckStatus::fail);
  // The reason names the rule that reached beyond: here P95 (10 of 100 left, more than 5 %).
  EXPECT_NE(office->reason.find("P95 beyond the profile; 10 of 100 blocks left"), std::string::npos)
      << office->reason;
  // Under the conservative rule one block out of 100 is enough (the maximum): the reason says
  // so, not "more than 5 % left".
  auto one_out = one_to(99);
  one_out.push_back(kInf);
  auto c = section("Face C", one_out, conservative());
  c.spec.work_areas = {{"office", 390}};
  const auto outc = design_quarry({c}, 1);
  ASSERT_TRUE(outc.design) << outc.error;
  const CheckLine* office_c = find(*outc.design, "Face C", "zone.office");
  ASSERT_TRUE(office_c);
  EXPECT_EQ(office_c->status, CheckStatus::fail);
  EXPECT_NE(office_c->reason.find("maximum beyond the profile"), std::string::npos) << office_c->reason;
  EXPECT_NE(office_c->reason.find("1 of 100 blocks left"), std::string::npos) << office_c->reason;
}

// A finite danger zone longer than the floor the section models (a log-normal extrapolation, or
// a group's pooled zone on a section with a short floor) reaches where nothing was simulated.
// The zone lines judge as design-checks.md §2 has them (FAIL only inside the zone), and a
// zone.extent WARN says the zone's end is extrapolated, with or without work areas.
QuarrySectionInput short_floor(const std::string& name, double floor_end, std::string group = "") {
  QuarrySectionInput s;
  s.spec.name = name;
  s.spec.group = std::move(group);
  s.rules = thesis();
  s.geometry = *quarry_geometry(test::make_profile({{0, 20}, {10, 20}, {10, 0}, {floor_end, 0}}), {});
  s.distances = distances(one_to(100), s.geometry);  // 1 … 100 m: RD95 = 95.05 m
  return s;
}

TEST(QuarryZones, DangerZonePastTheFloorWarns) {
  auto a = short_floor("Short", 10 + 101);  // a 101 m floor: every block stops on it
  a.geometry.floor_length = 90;             // … but say it models only 90 m
  a.spec.work_areas = {{"yard", 300}, {"shed", 60}};
  auto b = short_floor("Bare", 10 + 101);
  b.geometry.floor_length = 90;
  auto ok = short_floor("Long", 10 + 101);  // 101 m of floor: the zone fits
  ok.spec.work_areas = {{"yard", 300}};
  const auto out = design_quarry({a, b, ok}, 1);
  ASSERT_TRUE(out.design) << out.error;
  EXPECT_NEAR(out.design->sections[0].danger_zone, 95.05, 1e-9);
  EXPECT_TRUE(out.design->sections[0].danger_zone_beyond_profile());
  const CheckLine* yard = find(*out.design, "Short", "zone.yard");
  const CheckLine* shed = find(*out.design, "Short", "zone.shed");
  ASSERT_TRUE(yard && shed);
  EXPECT_EQ(yard->status, CheckStatus::pass) << yard->reason;  // 300 m >= 95.05 m
  EXPECT_EQ(shed->status, CheckStatus::fail) << shed->reason;  // 60 m < 95.05 m
  for (const char* name : {"Short", "Bare"}) {
    const CheckLine* extent = find(*out.design, name, "zone.extent");
    ASSERT_TRUE(extent) << name;
    EXPECT_EQ(extent->status, CheckStatus::warn) << name;
    EXPECT_DOUBLE_EQ(extent->value, 90.0);
    EXPECT_NEAR(extent->limit, 95.05, 1e-9);
    EXPECT_NE(extent->reason.find("extrapolated"), std::string::npos) << extent->reason;
    EXPECT_EQ(extent->reason.rfind("RD_gov = 95.05 m (P95 ", 0), 0u) << extent->reason;
    EXPECT_NE(extent->reason.find(") reaches past the floor's end at 90.00 m from the toe"),
              std::string::npos)
        << extent->reason;
  }
  const CheckLine* fine = find(*out.design, "Long", "zone.yard");
  ASSERT_TRUE(fine);
  EXPECT_EQ(fine->status, CheckStatus::pass) << fine->reason;
  EXPECT_FALSE(find(*out.design, "Long", "zone.extent"));
}

TEST(QuarryZones, BenchRetentionAndRitchie) {
  auto pass = section("Wide", one_to(100));
  pass.spec.bench_width = 90;  // 90 of 100 blocks stop within 90 m: exactly the 90 % target
  auto fail = section("Narrow", one_to(100));
  fail.spec.bench_width = 8;  // 8 % retained; and 8 m < 0.2·20 + 4.5 = 8.5 m
  const auto out = design_quarry({pass, fail}, 1);
  ASSERT_TRUE(out.design) << out.error;
  const auto& d = *out.design;
  const CheckLine* r1 = find(d, "Wide", "bench.retention");
  const CheckLine* r2 = find(d, "Narrow", "bench.retention");
  const CheckLine* k1 = find(d, "Wide", "bench.ritchie");
  const CheckLine* k2 = find(d, "Narrow", "bench.ritchie");
  ASSERT_TRUE(r1 && r2 && k1 && k2);
  EXPECT_EQ(r1->status, CheckStatus::pass);
  EXPECT_DOUBLE_EQ(r1->value, 90);
  EXPECT_DOUBLE_EQ(r1->limit, 90);
  EXPECT_EQ(r2->status, CheckStatus::fail);
  EXPECT_DOUBLE_EQ(r2->value, 8);
  EXPECT_EQ(k1->status, CheckStatus::pass);
  EXPECT_EQ(k2->status, CheckStatus::warn);
  EXPECT_DOUBLE_EQ(k2->limit, 8.5);
  EXPECT_DOUBLE_EQ(*d.sections[1].ritchie_width, 8.5);
  // The reasons give value and limit in the decimals of their cells (as the barrier lines do).
  EXPECT_EQ(r2->reason, "8.00 % of 100 blocks retained < 90.00 %");
  EXPECT_EQ(k2->reason, "bench 8.00 m < 8.50 m (H = 20.00 m)");
  // Exactly at the Ritchie width on paper: 0.2 × 14 + 4.5 is 7.300000000000001 m in binary.
  auto edge = section("Edge", one_to(100));
  edge.geometry.height = 14;
  edge.spec.bench_width = 7.3;
  ASSERT_GT(0.2 * 14 + 4.5, 7.3);
  const auto e = design_quarry({edge}, 1);
  ASSERT_TRUE(e.design) << e.error;
  const CheckLine* k3 = find(*e.design, "Edge", "bench.ritchie");
  ASSERT_TRUE(k3);
  EXPECT_EQ(k3->status, CheckStatus::pass) << k3->reason;
}

TEST(QuarryZones, SampleSize) {
  const auto small = design_quarry({section("Small", lognormal_runouts(20, 20, 1))}, 1);
  const auto big = design_quarry({section("Big", lognormal_runouts(40000, 20, 2))}, 1);
  ASSERT_TRUE(small.design && big.design);
  const CheckLine* a = find(*small.design, "Small", "sample.size");
  const CheckLine* b = find(*big.design, "Big", "sample.size");
  ASSERT_TRUE(a && b);
  EXPECT_EQ(a->status, CheckStatus::warn);
  EXPECT_NE(a->reason.find("reached the floor"), std::string::npos) << a->reason;
  EXPECT_EQ(b->status, CheckStatus::pass) << b->reason;
  EXPECT_LT(b->value, 5);
  ASSERT_TRUE(big.design->rows[0].rd_interval);
}

// A row whose RD95 is known too loosely says, as a barrier's sample.size does, how many
// trajectories and how many throws per block and source would do: n · (half-width / tolerance)²
// and throws · (half-width / tolerance)². Without the throws (0: unknown) it names none; a group
// of sections run with one number of throws names that one.
TEST(QuarryZones, SampleSizeNamesTheThrowsNeeded) {
  auto s = section("Loose", lognormal_runouts(200, 20, 4));
  s.throws = 8;  // e.g. 25 blocks x 8 throws
  const auto out = design_quarry({s}, 1);
  ASSERT_TRUE(out.design);
  const CheckLine* l = find(*out.design, "Loose", "sample.size");
  ASSERT_TRUE(l);
  ASSERT_EQ(l->status, CheckStatus::warn) << l->reason << " (the test needs a loose RD95)";
  const double factor = (l->value / l->limit) * (l->value / l->limit);
  const SampleNeeded needed = sample_needed(200, 8, l->value / 100, l->limit / 100);
  EXPECT_DOUBLE_EQ(needed.throws, std::ceil(8 * factor));
  EXPECT_DOUBLE_EQ(needed.trajectories, std::ceil(200 * factor));
  EXPECT_NE(l->reason.find("about " + number_text(needed.trajectories, 9) + " trajectories"),
            std::string::npos)
      << l->reason;
  EXPECT_NE(l->reason.find(throws_needed_text(needed)), std::string::npos) << l->reason;
  EXPECT_NE(l->reason.find("throws = " + number_text(std::ceil(8 * factor), 9) + " per block and source"),
            std::string::npos)
      << l->reason;
  // The estimate moves from run to run with the interval: a quarter more is offered as a margin.
  EXPECT_NE(l->reason.find("throws = " + number_text(std::ceil(1.25 * std::ceil(8 * factor)), 9) +
                           " leaves a margin"),
            std::string::npos)
      << l->reason;

  s.throws = 0;  // not known: no throws named
  const auto unknown = design_quarry({s}, 1);
  EXPECT_EQ(find(*unknown.design, "Loose", "sample.size")->reason.find("throws ="), std::string::npos);

  auto a = section("Loose A", lognormal_runouts(100, 20, 5)), b = section("Loose B", lognormal_runouts(100, 20, 6));
  a.spec.group = b.spec.group = "Loose";
  a.throws = b.throws = 4;
  const auto pooled = design_quarry({a, b}, 1);
  ASSERT_TRUE(pooled.design);
  EXPECT_EQ(pooled.design->rows[0].throws, 4u);
}

// One block: a bootstrap of one value has no spread, so no interval (it said "RD95 known to
// ±0 %"); and no block on the floor: no ID, said as "no values" (it said "P95 nan").
TEST(QuarryZones, OneBlockGivesNoIntervalAndAnEmptyIdSaysSo) {
  const auto one = design_quarry({section("One", {7.0})}, 1);
  ASSERT_TRUE(one.design);
  EXPECT_FALSE(one.design->rows[0].rd_interval);
  const CheckLine* l = find(*one.design, "One", "sample.size");
  ASSERT_TRUE(l);
  EXPECT_TRUE(std::isnan(l->value));
  EXPECT_NE(l->reason.find("no bootstrap interval"), std::string::npos) << l->reason;

  const auto none = design_quarry({section("None", {-3.0, -2.0, -1.0})}, 1);  // all above the toe
  ASSERT_TRUE(none.design);
  const auto& row = none.design->rows[0];
  EXPECT_TRUE(std::isnan(row.id_gov.value_h));
  EXPECT_EQ(row.id_gov.how, "P95: no values");
}

// Three blocks of 100 off the end: RD95 is finite, but resamples with six or more off the end
// put the interval's upper end beyond the profile, which more throws cannot close.
TEST(QuarryZones, SampleSizeWithAnIntervalBeyondTheProfile) {
  auto v = one_to(97);
  for (int i = 0; i < 3; ++i) v.push_back(kInf);
  const auto out = design_quarry({section("Edge", v)}, 1);
  ASSERT_TRUE(out.design);
  ASSERT_TRUE(out.design->rows[0].rd_interval);
  EXPECT_TRUE(std::isfinite(out.design->rows[0].rd_interval->estimate));
  EXPECT_TRUE(std::isinf(out.design->rows[0].rd_interval->upper));
  const CheckLine* l = find(*out.design, "Edge", "sample.size");
  ASSERT_TRUE(l);
  EXPECT_EQ(l->status, CheckStatus::warn);
  EXPECT_TRUE(std::isnan(l->value));
  EXPECT_NE(l->reason.find("reaches beyond the profile (3 of 100 blocks left"), std::string::npos)
      << l->reason;
}

// governing_value_h (what the bootstrap evaluates on each resample) is the governing
// distance's value, for every candidate, with blocks censored at two floors (a pool).
TEST(QuarryZones, GoverningValueFromTheSampleAloneIsTheGoverningDistance) {
  DistanceSample s;
  auto a = lognormal_runouts(300, 20, 11);
  a[5] = a[17] = kInf;
  s.add(a, 20, 80);
  s.add(lognormal_runouts(200, 14, 12), 14, 60);
  auto b = lognormal_runouts(100, 14, 13);
  b[0] = kInf;
  s.add(b, 14, 50);
  ASSERT_EQ(s.censored_at.size(), 3u);
  QuarryRuleSet p98 = thesis();
  p98.percentile = 98;
  QuarryRuleSet pm = thesis();
  pm.governing = {QuarryGoverning::percentile, QuarryGoverning::lognormal};
  const DistanceStatistics st = distance_statistics(s);
  ASSERT_TRUE(st.fit);
  for (const QuarryRuleSet& r : {thesis(), p98, conservative(), pm}) {
    const GoverningDistance g = governing_distance(s, st, r);
    EXPECT_EQ(governing_value_h(s, r), g.value_h) << g.how;
  }
  // Censored blocks make the maximum beyond the profile; without them it is finite.
  EXPECT_TRUE(std::isinf(governing_value_h(s, conservative())));
}

// sample.size judges the distance that sets the zone (design-checks.md §1 step 8 bootstraps
// the design values). Under the conservative rule that is the log-normal P99: an extrapolation
// far less certain than the empirical P99 the check used to bootstrap. Two clusters (most
// blocks near the toe, a tenth far out) fit a log-normal badly: its P99 is far beyond every
// block, and the interval is wide, while the empirical P99 (among the far blocks) is tight.
std::vector<double> two_clusters() {
  std::vector<double> v;  // m: 70 % within 2 cm of the toe, over a decade; 30 % at 20-30 m
  for (int i = 0; i < 2000; ++i) {
    const double u = (i % 97) / 97.0;
    v.push_back(i % 10 < 7 ? 0.001 * std::exp(3 * u) : 20 + 10 * u);
  }
  return v;
}

TEST(QuarryZones, SampleSizeJudgesTheGoverningDistance) {
  const std::vector<double> v = two_clusters();
  const auto out = design_quarry({section("Two", v, conservative())}, 1);
  ASSERT_TRUE(out.design) << out.error;
  const QuarryRow& row = out.design->rows[0];
  ASSERT_TRUE(row.rd_interval);
  EXPECT_DOUBLE_EQ(row.rd_interval->estimate, row.rd_gov.value_h);
  EXPECT_GT(row.rd_gov.lognormal_h, row.rd_gov.maximum_h);  // the fit governs
  EXPECT_LE(row.rd_interval->lower, row.rd_interval->estimate);
  EXPECT_GE(row.rd_interval->upper, row.rd_interval->estimate);
  const CheckLine* l = find(*out.design, "Two", "sample.size");
  ASSERT_TRUE(l);
  EXPECT_EQ(l->status, CheckStatus::warn) << l->reason;
  EXPECT_NEAR(l->value, 100 * row.rd_interval->half_width() / row.rd_gov.value_h, 1e-9);
  // The empirical P99 the check judged before is known far better than the 5 % tolerance.
  const auto p99 = stats::bootstrap_percentile_interval(row.rd_sample.normalized, 99, 1);
  ASSERT_TRUE(p99);
  EXPECT_LT(p99->half_width() / p99->estimate, 0.05);
  // The thesis rule: the interval is the exact percentile bootstrap of P95, as before.
  const auto t = design_quarry({section("Two", v)}, 1);
  ASSERT_TRUE(t.design && t.design->rows[0].rd_interval);
  const auto p95 = stats::bootstrap_percentile_interval(t.design->rows[0].rd_sample.normalized,
                                                        95, 1);
  ASSERT_TRUE(p95);
  EXPECT_EQ(t.design->rows[0].rd_interval->lower, p95->lower);
  EXPECT_EQ(t.design->rows[0].rd_interval->upper, p95->upper);
}

// A zone set by a log-normal that fit.RD rejects says so on the zone line itself; a zone set
// by a fit that passes, or by a percentile, does not.
TEST(QuarryZones, AZoneFromARejectedFitSaysSo) {
  const std::vector<double> two = two_clusters();
  auto bad = section("Bad", two, conservative());
  bad.spec.work_areas = {{"office", 35}};
  auto good = section("Good", lognormal_runouts(1000, 20, 3), conservative());
  good.spec.work_areas = {{"office", 35}};
  auto pct = section("Pct", two);
  pct.spec.work_areas = {{"office", 35}};
  const auto out = design_quarry({bad, good, pct}, 1);
  ASSERT_TRUE(out.design) << out.error;
  const auto& d = *out.design;
  ASSERT_EQ(find(d, "Bad", "fit.RD")->status, CheckStatus::warn);
  ASSERT_EQ(find(d, "Good", "fit.RD")->status, CheckStatus::pass);
  const std::string rejected = "comes from a log-normal fit that fit.RD rejects";
  EXPECT_NE(find(d, "Bad", "zone.office")->reason.find(rejected), std::string::npos)
      << find(d, "Bad", "zone.office")->reason;
  EXPECT_EQ(find(d, "Good", "zone.office")->reason.find(rejected), std::string::npos);
  EXPECT_EQ(find(d, "Pct", "zone.office")->reason.find(rejected), std::string::npos);
}

TEST(QuarryZones, FitChecks) {
  const auto good = design_quarry({section("Good", lognormal_runouts(1000, 20, 3))}, 1);
  // Two clusters, at about 1 m and 100 m: no log-normal fits that.
  std::vector<double> two;
  for (int i = 0; i < 500; ++i) two.push_back(i % 2 ? 1.0 + 0.001 * i : 100.0 + 0.001 * i);
  const auto bad = design_quarry({section("Bad", two)}, 1);
  ASSERT_TRUE(good.design && bad.design);
  EXPECT_EQ(find(*good.design, "Good", "fit.RD")->status, CheckStatus::pass);
  EXPECT_EQ(find(*bad.design, "Bad", "fit.RD")->status, CheckStatus::warn);
  EXPECT_EQ(find(*bad.design, "Bad", "fit.ID")->status, CheckStatus::warn);
  EXPECT_FALSE(any_failure(good.design->checks));
}

// A fit the KS test cannot reject because it has only a handful of values above zero (most
// blocks stopped above the toe) is a WARN, as a barrier's fit on too few crossings: p near 1
// from 20 values says nothing. With 40 the same kind of sample passes.
TEST(QuarryZones, AFitOnFewerValuesThanMinReachedWarns) {
  auto runouts = [](int positive) {
    std::vector<double> v(700, 0.0);  // at the toe or above it
    const auto far = lognormal_runouts(static_cast<std::size_t>(positive), 20, 3);
    v.insert(v.end(), far.begin(), far.end());
    return v;
  };
  const auto few = design_quarry({section("Few", runouts(20))}, 1);
  const auto enough = design_quarry({section("Enough", runouts(40))}, 1);
  ASSERT_TRUE(few.design && enough.design);
  const CheckLine* l = find(*few.design, "Few", "fit.RD");
  ASSERT_TRUE(l);
  EXPECT_GE(l->value, 0.05) << l->reason;  // not rejected ...
  EXPECT_EQ(l->status, CheckStatus::warn) << l->reason;  // ... but on 20 values
  EXPECT_NE(l->reason.find("n = 20 values above zero"), std::string::npos) << l->reason;
  EXPECT_NE(l->reason.find("from fewer than the 30 values the rule set asks (min_reached)"),
            std::string::npos)
      << l->reason;
  EXPECT_EQ(find(*enough.design, "Enough", "fit.RD")->status, CheckStatus::pass)
      << find(*enough.design, "Enough", "fit.RD")->reason;
}

// A work area outside a zone drawn from fewer blocks on the floor than min_reached (a source
// behind the crest: 3 of 700 went over, user review) is a WARN, not a PASS; with enough blocks
// on the floor the same area passes.
TEST(QuarryZones, AnAreaOutsideAZoneFromTooFewBlocksWarns) {
  auto with_area = [](const std::string& name, int positive) {
    std::vector<double> v(700, 0.0);
    const auto far = lognormal_runouts(static_cast<std::size_t>(positive), 20, 3);
    v.insert(v.end(), far.begin(), far.end());
    auto s = section(name, v);
    s.spec.work_areas = {{"road", 60}};
    return s;
  };
  const auto out = design_quarry({with_area("Few", 3), with_area("Enough", 300)}, 1);
  ASSERT_TRUE(out.design) << out.error;
  const CheckLine* few = find(*out.design, "Few", "zone.road");
  ASSERT_TRUE(few);
  EXPECT_EQ(few->status, CheckStatus::warn) << few->reason;
  EXPECT_NE(few->reason.find("is outside the danger zone"), std::string::npos) << few->reason;
  EXPECT_NE(few->reason.find(", but only 3 of the 703 blocks reached the floor (< 30, the rule set's "
                             "min_reached)"),
            std::string::npos)
      << few->reason;
  EXPECT_EQ(find(*out.design, "Enough", "zone.road")->status, CheckStatus::pass)
      << find(*out.design, "Enough", "zone.road")->reason;
}

// A bench "retains" blocks that never reached the floor: 700 stopping above the toe and 3 on
// the floor give 100 % retained of a 5 m bench, which is no evidence of the bench (new-user
// review: a source behind the crest, bench.retention 100 % PASS, exit 0). It WARNs, naming the
// count and what to check; with enough blocks on the floor the same share passes.
TEST(QuarryZones, ABenchFewBlocksReachedWarns) {
  auto with_bench = [](const std::string& name, std::size_t on_floor) {
    std::vector<double> v(700, 0.0);
    v.insert(v.end(), on_floor, 2.0);  // on the floor, within the 5 m bench
    auto s = section(name, v);
    s.spec.bench_width = 5;
    return s;
  };
  const auto out = design_quarry({with_bench("Few", 3), with_bench("Enough", 300)}, 1);
  ASSERT_TRUE(out.design) << out.error;
  const CheckLine* few = find(*out.design, "Few", "bench.retention");
  ASSERT_TRUE(few);
  EXPECT_EQ(few->status, CheckStatus::warn) << few->reason;
  EXPECT_DOUBLE_EQ(few->value, 100);
  EXPECT_NE(few->reason.find("100.00 % of 703 blocks retained >= 90.00 %, but only 3 of them "
                             "reached the floor (< 30, the rule set's min_reached)"),
            std::string::npos)
      << few->reason;
  EXPECT_NE(few->reason.find("not behind the crest"), std::string::npos) << few->reason;
  EXPECT_EQ(find(*out.design, "Enough", "bench.retention")->status, CheckStatus::pass)
      << find(*out.design, "Enough", "bench.retention")->reason;
  // Every block on the floor, but too few thrown: more throws, not the source or a ledge.
  auto all = section("All", std::vector<double>(10, 2.0));
  all.spec.bench_width = 5;
  const auto small = design_quarry({all}, 1);
  ASSERT_TRUE(small.design) << small.error;
  const CheckLine* a = find(*small.design, "All", "bench.retention");
  ASSERT_TRUE(a);
  EXPECT_EQ(a->status, CheckStatus::warn);
  EXPECT_NE(a->reason.find("only 10 of them reached the floor (< 30, the rule set's min_reached): "
                           "too few blocks thrown: more throws"),
            std::string::npos)
      << a->reason;
  EXPECT_EQ(a->reason.find("behind the crest"), std::string::npos) << a->reason;
}

// The field's P95 against the governing distance: a zone drawn shorter than what was seen
// warns; one that covers it passes; a summary without a P95 has nothing to judge.
TEST(QuarryZones, ObservedValuesAgainstTheGoverningDistances) {
  auto s = section("Face A", one_to(100));  // RD_gov = P95 of 1..100 = 95.05 m; ID = RD / 5
  s.observed.rd.p95 = 96;                     // m, a printed summary value
  s.observed.id.metres = one_to(10);          // raw: P95 = 1 + 9 · 0.95 = 9.55 m
  const auto out = design_quarry({s}, 1);
  ASSERT_TRUE(out.design) << out.error;
  const CheckLine* rd = find(*out.design, "Face A", "observed.RD");
  const CheckLine* id = find(*out.design, "Face A", "observed.ID");
  ASSERT_TRUE(rd && id);
  EXPECT_EQ(rd->status, CheckStatus::warn);
  EXPECT_DOUBLE_EQ(rd->value, 96.0);
  EXPECT_DOUBLE_EQ(rd->limit, 95.05);
  EXPECT_EQ(rd->unit, "m");
  EXPECT_EQ(rd->reason,
            "observed P95 96.00 m > RD_gov 95.05 m (P95 4.75 H): blocks at the face ran out farther "
            "from the toe than the simulation has them; check the materials and roughness against "
            "the observations before relying on the danger zone");
  EXPECT_EQ(id->status, CheckStatus::pass);
  EXPECT_DOUBLE_EQ(id->value, 9.55);
  EXPECT_DOUBLE_EQ(id->limit, 95.05 / 5);
  EXPECT_EQ(id->reason, "observed P95 9.55 m (n = 10) <= ID_gov 19.01 m (P95 0.95 H)");
  // A WARN, never a FAIL: the exit code stays with the zones.
  EXPECT_FALSE(any_failure(out.design->checks));
  // The value is the one given, to the last bit: 13.6 m at H = 20 m is not 13.6 / 20 · 20, which
  // is 13.599999999999998 (a script comparing it with its input saw a mismatch).
  s.observed.rd.p95 = 13.6;
  s.observed.id.metres = {13.6, 13.6};
  const auto exact = design_quarry({s}, 1);
  ASSERT_TRUE(exact.design) << exact.error;
  EXPECT_EQ(find(*exact.design, "Face A", "observed.RD")->value, 13.6);
  EXPECT_EQ(find(*exact.design, "Face A", "observed.ID")->value, 13.6);

  // A group of a 20 m and a 10 m face (row H 15 m) is judged in /H, each observation over its
  // own face's H. Pooled /H runouts k/20 and k/10 (k = 1..100): P95 = 9.0 + 0.05 · 0.1 =
  // 9.005 H = 135.075 m. 95 m seen under the 10 m face is fewer metres than that, but 9.5 H:
  // beyond the zone, and shown as 9.5 H at the row's H, 142.5 m.
  auto a = section("Face B1", one_to(100));
  auto b = section("Face B2", one_to(100), thesis(), 10);
  a.spec.group = b.spec.group = "B";
  b.observed.rd.metres = {95, 95};
  const auto group = design_quarry({a, b}, 1);
  ASSERT_TRUE(group.design) << group.error;
  EXPECT_DOUBLE_EQ(group.design->rows[0].rd_gov.value_h, 9.005);
  const CheckLine* scaled = find(*group.design, "B", "observed.RD");
  ASSERT_TRUE(scaled);
  EXPECT_EQ(scaled->status, CheckStatus::warn);
  EXPECT_DOUBLE_EQ(scaled->value, 142.5);
  EXPECT_DOUBLE_EQ(scaled->limit, 9.005 * 15);
  EXPECT_FALSE(find(*group.design, "B", "observed.ID"));  // none observed: no line

  auto u = section("Face C", one_to(100));
  u.observed.rd.p50 = 5;  // a summary without its P95
  const auto part = design_quarry({u}, 1);
  ASSERT_TRUE(part.design) << part.error;
  const CheckLine* none = find(*part.design, "Face C", "observed.RD");
  ASSERT_TRUE(none);
  EXPECT_EQ(none->status, CheckStatus::not_applicable);
  EXPECT_EQ(none->reason, "no observed P95");
}

// Covered by RD_gov, but by less than RD_gov's own sampling uncertainty: observed P95 above the
// lower end of its bootstrap interval is a WARN that says so, as a work area's zone line is (a
// reviewer found Preg 2's 21.90 m passing against 21.92 m, with an interval from 20.42 m).
TEST(QuarryZones, AnObservedRunoutWithinTheZonesIntervalWarns) {
  auto close = section("Close", one_to(100));  // RD_gov = 95.05 m
  close.observed.rd.p95 = 94.9;
  auto clear = section("Clear", one_to(100));
  clear.observed.rd.p95 = 60;
  const auto out = design_quarry({close, clear}, 1);
  ASSERT_TRUE(out.design) << out.error;
  const QuarryRow& row = out.design->rows[0];
  ASSERT_TRUE(row.rd_interval);
  const double lower = row.rd_interval->lower * row.height;
  ASSERT_LT(lower, 94.9);  // the case itself: the interval reaches below what was seen
  ASSERT_GT(lower, 60.0);
  const CheckLine* near = find(*out.design, "Close", "observed.RD");
  ASSERT_TRUE(near);
  EXPECT_EQ(near->status, CheckStatus::warn);
  EXPECT_EQ(near->reason, "observed P95 94.90 m <= RD_gov 95.05 m (P95 4.75 H), but within RD_gov's "
                          "90 % bootstrap interval (down to " + pierre::design::quantity_text(lower, "m") +
                              "): the margin is within the sampling uncertainty; more throws "
                              "settle it");
  const CheckLine* far = find(*out.design, "Clear", "observed.RD");
  ASSERT_TRUE(far);
  EXPECT_EQ(far->status, CheckStatus::pass) << far->reason;
}

TEST(QuarryZones, GroupsPoolSectionsAndAveragesTakeRows) {
  auto a = section("Kloech a", one_to(50));
  auto b = section("Kloech b", one_to(50));
  a.spec.group = b.spec.group = "Kloech";
  auto c = section("Preg 1", one_to(100), thesis(), 10);
  c.observed.rd.p50 = 5;  // m
  c.observed.rd.p95 = 9;
  c.observed.rd.max = 12;
  const auto out = design_quarry({a, b, c}, 1);
  ASSERT_TRUE(out.design) << out.error;
  const auto& d = *out.design;
  ASSERT_EQ(d.rows.size(), 2u);
  EXPECT_EQ(d.rows[0].name, "Kloech");
  EXPECT_TRUE(d.rows[0].pooled);
  EXPECT_EQ(d.rows[0].thrown, 100u);
  EXPECT_EQ(d.rows[0].sections, (std::vector<std::size_t>{0, 1}));
  EXPECT_DOUBLE_EQ(d.rows[0].rd.p95, 48.0);  // P95 of 1..50 twice
  // Each section's own statistics beside the pooled ones (design-checks.md §2): of 1..50,
  // P95 = 1 + 49 · 0.95 = 47.55 m, not the pooled 48 m; the lone section's are its row's.
  EXPECT_DOUBLE_EQ(d.sections[0].rd.p95, 47.55);
  EXPECT_DOUBLE_EQ(d.sections[0].rd.max, 50.0);
  EXPECT_EQ(d.sections[0].rd.count, 50u);
  EXPECT_EQ(d.sections[1].rd.count, 50u);
  EXPECT_DOUBLE_EQ(d.sections[2].rd.p95, d.rows[1].rd.p95);
  EXPECT_DOUBLE_EQ(d.sections[0].danger_zone, 48.0);
  EXPECT_DOUBLE_EQ(d.sections[1].danger_zone, 48.0);
  EXPECT_EQ(d.sections[2].row, 1u);
  // Averages of the per-row /H ratios: (48/20 + 95.05/10) / 2.
  EXPECT_DOUBLE_EQ(d.average.rd95_h, (48.0 / 20 + 95.05 / 10) / 2);
  EXPECT_EQ(d.average.rows, 2u);
  EXPECT_EQ(d.average.observed_rows, 1u);
  EXPECT_DOUBLE_EQ(d.average.obs_rd95_h, 0.9);
  ASSERT_TRUE(d.rows[1].observed_rd);
  EXPECT_TRUE(d.rows[1].observed_rd->cdf_rmse.has_value());
  EXPECT_EQ(d.all_rd.size(), 200u);
  // Row checks carry the group's name, zone checks the section's.
  EXPECT_TRUE(find(d, "Kloech", "sample.size"));
  EXPECT_TRUE(find(d, "Kloech", "fit.RD"));

  // A group must follow one rule set.
  b.rules = conservative();
  const auto mixed = design_quarry({a, b}, 1);
  EXPECT_FALSE(mixed.design);
  EXPECT_NE(mixed.error.find("different rule sets"), std::string::npos);
}

TEST(QuarryZones, ExceedanceRows) {
  auto s = section("Face A", lognormal_runouts(3000, 20, 9));
  s.spec.exceedance = {0.05, 0.01};
  const auto out = design_quarry({s}, 1);
  ASSERT_TRUE(out.design);
  const auto& row = out.design->rows[0];
  ASSERT_EQ(row.exceedance.size(), 2u);
  const auto& e = row.exceedance[0];
  EXPECT_DOUBLE_EQ(e.rd_empirical_h, row.rd.p95_h);
  EXPECT_DOUBLE_EQ(e.rd_empirical, e.rd_empirical_h * 20);
  // Fit and sample agree on a log-normal sample: within 10 %.
  EXPECT_NEAR(e.rd_fit_h, e.rd_empirical_h, 0.1 * e.rd_empirical_h);
  EXPECT_LT(row.exceedance[0].rd_fit_h, row.exceedance[1].rd_fit_h);
}

// A doubt on a section's inputs reaches its row, even a group of that one section; one on its
// simulation (blocks, sources: no ids) reaches the other sections of its group too, whose zones
// come from the pooled distances; one on a bench width or a work area stays the section's.
TEST(QuarryZones, PooledDoubtsReachTheGroupAndOnlyThePooledInputsReachItsSections) {
  QuarryDesign d;
  for (const char* name : {"A", "B", "C", "Solo"}) {
    QuarrySectionResult s;
    s.spec.name = name;
    d.sections.push_back(s);
  }
  QuarryRow pool, lone, solo;
  pool.name = "Pool";
  pool.sections = {0, 1};
  pool.pooled = true;
  lone.name = "C";
  lone.sections = {2};
  solo.name = "Group of one";
  solo.sections = {3};
  d.rows = {pool, lone, solo};
  auto subjects = [&](const DoubtedInput& in) {
    std::vector<std::string> out;
    for (const DoubtedInput& o : pooled_doubts(d, {in})) {
      EXPECT_EQ(o.field, in.field);
      EXPECT_EQ(o.ids, in.ids);
      out.push_back(o.subject);
    }
    return out;
  };
  using V = std::vector<std::string>;
  EXPECT_EQ(subjects({"quarries[0].blocks.density", "A", {}, 2.65}), (V{"A", "Pool", "B"}));
  EXPECT_EQ(subjects({"quarries[0].bench_width", "A", {"bench."}, 300}), (V{"A", "Pool"}));
  EXPECT_EQ(subjects({"quarries[2].blocks.density", "C", {}, 2.65}), (V{"C"}));
  EXPECT_EQ(subjects({"quarries[3].sources[0].z", "Solo", {}, 500}), (V{"Solo", "Group of one"}));
  EXPECT_EQ(subjects({"simulation.gravity", "", {}, 98.1}), (V{""}));
}

}  // namespace
}  // namespace pierre::design
