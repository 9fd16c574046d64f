// report.xlsx, opened for real: a ReportData built by hand (the small test scenario, a
// BarrierDesign with known numbers, PASS / FAIL / WARN check lines, a few paths) is written,
// then LibreOffice (headless) exports every sheet to CSV and the workbook to PDF. The tests
// check the sheet names and order, key cells (MEL_req on the barrier sheet, a check's status on
// Summary), that numbers are numbers (unquoted in the CSV, parse as double), the row caps, the
// charts in the zip (scatter series with x and y values), the conditional formats, identical
// bytes for identical inputs, and that a failed write leaves nothing behind.
//
// LibreOffice is installed by `tools/bootstrap test`; without `soffice` the tests that need it
// are skipped with a message (the others still run).
#include <gtest/gtest.h>
#include <unzip.h>
#include <zip.h>

#include <algorithm>

#include <cmath>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "pierre/io/report_template.hpp"
#include "pierre/io/scenario_reader.hpp"
#include "pierre/io/xlsx_report.hpp"
#include "pierre/model/roughness.hpp"
#include "pierre/stats/weibull_fit.hpp"
#include "support/workbook_reader.hpp"
#include "test_files.hpp"
#include "xlsx_parts_check.hpp"

namespace {

namespace fs = std::filesystem;
using namespace pierre;
using namespace pierre::test;

const fs::path kTemplate = PIERRE_SOURCE_DIR "/templates/report.toml";
const fs::path kRules = PIERRE_SOURCE_DIR "/rules";
const fs::path kSmall = PIERRE_TEST_DATA "/small/scenario.toml";

// A heading of the Summary's barrier tables, as the shipped layout writes it.
std::string tpl_heading(const char* key) {
  return io::load_report_template(kTemplate).get("headings.barriers", key);
}

// ---- the report data -------------------------------------------------------------------

struct Fixture {
  io::LoadedScenario scenario;
  io::ReportData data;
};

design::CheckLine line(std::string subject, std::string id, double value, double limit,
                       std::string unit, design::CheckStatus st) {
  design::CheckLine l;
  l.subject = std::move(subject);
  l.id = std::move(id);
  l.what = "candidate's value against the limit (" + l.id + ")";
  l.value = value;
  l.limit = limit;
  l.unit = std::move(unit);
  l.rule = "thesis-2015 §4.7";
  l.status = st;
  l.reason = std::string(design::to_string(st)) + " by design of the test";
  return l;
}

// A small Weibull-ish sample by inversion of a fixed sequence (no random numbers needed).
std::vector<double> weibull_sample(double k, double lambda, int n) {
  std::vector<double> x;
  for (int i = 0; i < n; ++i) {
    const double u = (i + 0.5) / n;
    x.push_back(lambda * std::pow(-std::log(1 - u), 1 / k));
  }
  return x;
}

std::unique_ptr<Fixture> make_fixture(int crossings = 400, int trajectories = 30) {
  auto f = std::make_unique<Fixture>();
  f->scenario = io::load_scenario(kSmall, kRules);
  auto& d = f->data;
  d.scenario = &f->scenario;
  d.pierre_version = "0.1.0-test";
  d.date = "2024-05-17";
  d.seed = 12345;
  d.throws = 300;
  d.rule_sets = {"thesis-2015 — Mitchell (2015) §4.7"};

  // Crossings at "Screen 1" (line 0, x = 60), one per trajectory, main direction.
  const auto v = weibull_sample(3.5, 20, crossings), hgt = weibull_sample(1.4, 1.6, crossings);
  for (int i = 0; i < crossings; ++i) {
    sim::Crossing c;
    c.trajectory = static_cast<std::uint64_t>(i);
    c.line = 0;
    c.mass = 3180;
    c.speed = v[static_cast<std::size_t>((i * 37) % crossings)];
    c.velocity = {c.speed * 0.9, -c.speed * 0.3};
    c.height = hgt[static_cast<std::size_t>((i * 53) % crossings)];
    c.translational_energy = 0.5 * c.mass * c.speed * c.speed;
    c.rotational_energy = 0.05 * c.translational_energy;
    c.time = 4.5;
    d.crossings.push_back(c);
  }
  d.total_crossings = static_cast<std::uint64_t>(crossings) + 1000;  // "the CSV holds more"
  for (int i = 0; i < trajectories; ++i) {
    sim::TrajectorySummary t;
    t.trajectory = static_cast<std::uint64_t>(i);
    t.block = static_cast<std::uint32_t>(i % 2);
    t.throw_index = static_cast<std::uint32_t>(i / 2);
    t.mass = 500;
    t.start = {5, 67.5};
    t.stop = {100.0 + i, 0.5};
    t.stop_reason = sim::StopReason::energy;
    t.duration = 8.25;
    t.impacts = 12;
    t.has_first_impact = i % 3 != 0;
    t.first_impact = {9, 60};
    t.max_jump_height = 2.5;
    t.max_speed = 24;
    t.max_energy = 150000;
    d.trajectories.push_back(t);
  }
  d.total_trajectories = 600;
  d.statistics.trajectories = 600;

  // The barrier: Table 4.1's worked example, numbers by hand.
  design::BarrierDesign b;
  b.spec.name = "Screen A";
  b.spec.line = "Screen 1";
  b.spec.rules = "thesis-2015";
  b.spec.design_block.kind = design::DesignBlock::Kind::given;
  b.spec.design_block.volume = 1.26;
  b.spec.design_block.density = 2800;
  b.spec.free_board_diameter = 1.2;
  design::CandidateBarrier cand;
  cand.energy_class = 6;  // MEL 3000, SEL 1000 kJ
  cand.height = 3.5;
  b.spec.candidate = cand;
  b.rules_name = "thesis-2015";
  b.rules_title = "Mitchell (2015) §4.7";
  b.rules_source = "Mitchell, PhD thesis, 2015";
  b.rules_file = "firm-rules/thesis-2015.toml";
  b.classes_name = "etag027-classes";
  b.classes_title = "ETAG 027 energy classes";
  b.classes_file = "firm-rules/etag027-classes.toml";
  b.chainage = 60;
  b.crossings = static_cast<std::uint64_t>(crossings);
  b.not_reached = 200;
  std::vector<double> e_kJ;
  for (const auto& c : d.crossings) e_kJ.push_back(c.translational_energy / 1000);
  auto fill = [](design::QuantityFit& q, double mean, double k, double lambda) {
    q.summary = {static_cast<std::size_t>(400), mean, mean / 3, mean / 10, mean * 2.5};
    q.weibull = stats::WeibullFit{k, lambda, 400, 0};
    q.weibull_ks = stats::KolmogorovSmirnovTest{0.031, 0.82, 0.83, 400};
    q.lognormal = stats::LognormalFit{std::log(mean), 0.35, 400, 0};
    q.lognormal_ks = stats::KolmogorovSmirnovTest{0.052, 0.21, 0.22, 400};
  };
  fill(b.speed, 18, 3.5, 20);
  fill(b.height, 1.45, 1.4, 1.6);
  fill(b.energy, 560, 1.8, 640);
  b.rotational_energy = {400, 28, 9, 3, 70};
  b.v_k = {24.0 / 1.16 + 0.01, 24.0 / 1.16, 24.0 / 1.16,
           stats::BootstrapInterval{20.69, 20.1, 21.3, 0.9, 1000}};
  b.h_k = {3.42, 3.38, 3.42, stats::BootstrapInterval{3.42, 3.2, 3.7, 0.9, 1000}};
  b.gamma_F = {1.16, "γF = 1.16 (given)"};
  b.gamma_M = {1.05, "γM = 1.05 (given)"};
  b.gamma_h = {1.0, "γh = 1.0 (given)"};
  b.gamma_E_MEL = 1.3;
  b.gamma_E_SEL = 1.0;
  b.gamma_d_MEL = 1.3;  // designs on MEL's elongation; no γd,SEL
  b.design_volume = 1.26;
  b.design_density = 2800;
  b.v_d = 24.0;
  b.m_d = 3704.4;
  b.E_d_kJ = 1066.9;
  b.SEL_req_kJ = 1066.9;
  b.MEL_req_kJ = 1386.9;
  b.energy_class = design::EnergyClass{7, 1500, 4500, false};
  b.free_board_diameter = 1.2;
  b.free_board = 0.6;
  b.h_d = 3.42;
  b.h_i = 4.02;
  b.h_max_sim = 6.9;
  b.candidate_mel_kJ = 3000;
  b.candidate_sel_kJ = 1000;
  b.E_d_interval = stats::BootstrapInterval{1066.9, 1010, 1120, 0.9, 1000};
  b.exceedance = {{"P(E > SEL_req)", 1066.9, "kJ", 0.0123, 0.0125, 0.011},
                  {"P(E > MEL_req)", 1386.9, "kJ", 0.0021, 0.0025, std::nullopt},
                  {"P(h > h_i)", 4.02, "m", 0.025, 0.0225, 0.0250},
                  {"P(h > h_max)", 6.9, "m", 0.0004, 0.0, std::nullopt}};
  b.checks = {line("Screen A", "energy.mel", 3000, 1386.9, "kJ", design::CheckStatus::pass),
              line("Screen A", "energy.sel", 1000, 1066.9, "kJ", design::CheckStatus::fail),
              line("Screen A", "fit.h", 0.03, 0.05, "", design::CheckStatus::warn)};
  b.notes = {"A note for the engineer."};
  d.checks = b.checks;
  d.checks.push_back(
      line("Screen A", "height.interception", 3.5, 4.02, "m", design::CheckStatus::fail));
  d.barriers.push_back(b);

  // Statistics of the lines (what the run computed).
  design::LineStatistics ls;
  ls.name = "Screen 1";
  ls.chainage = 60;
  ls.count = 400;
  ls.not_reached = 200;
  ls.speed = {400, 18, 18.2, 24.1, 31};
  ls.height = {400, 1.45, 1.2, 3.4, 6.9};
  ls.translational_energy = {400, 560e3, 520e3, 950e3, 1400e3};
  d.statistics.lines.push_back(ls);
  design::LineStatistics never;  // a line no trajectory crossed
  never.name = "Screen 9";
  never.chainage = 190;
  never.not_reached = 600;
  never.speed = never.height = never.translational_energy = design::quantity_statistics({});
  d.statistics.lines.push_back(never);
  d.statistics.runout = {600, 95, 110, 118, 125};
  d.statistics.stop_reasons = {{sim::StopReason::energy, 560},    {sim::StopReason::friction, 30},
                               {sim::StopReason::boundary, 10},   {sim::StopReason::time_limit, 0},
                               {sim::StopReason::impact_limit, 0}, {sim::StopReason::numerical, 0}};

  // Two sample paths.
  for (int p = 0; p < 2; ++p) {
    std::vector<geometry::Vec2> path;
    for (int i = 0; i <= 40; ++i) {
      const double x = 5 + 2.5 * i;
      path.push_back({x, 67.5 - 0.6 * (x - 5) + (p + 1) * 1.5 * std::sin(i * 0.7) + 2});
    }
    d.sample_paths.push_back(path);
  }
  return f;
}

// ---- tests -----------------------------------------------------------------------------

TEST(XlsxReport, WorkbookStructureChartsAndConditionalFormats) {
  PIERRE_NEED_PROGRAM("unzip");
  TempDir dir;
  const auto f = make_fixture();
  const auto tpl = io::load_report_template(kTemplate);
  const fs::path xlsx = dir.path() / "report.xlsx";
  io::write_report(xlsx, f->data, tpl);
  ASSERT_TRUE(fs::is_regular_file(xlsx));

  const auto names = zip_list(xlsx, dir.path());
  std::vector<std::string> charts;
  for (const auto& n : names)
    if (n.rfind("xl/charts/chart", 0) == 0) charts.push_back(n);
  // Per barrier: 3 histograms + 3 CDFs; plus the profile.
  EXPECT_EQ(charts.size(), 7u);
  for (const auto& c : charts) {
    SCOPED_TRACE(c);
    const std::string xml = zip_entry(xlsx, c, dir.path());
    EXPECT_NE(xml.find("<c:scatterChart>"), std::string::npos);
    const auto series = occurrences(xml, "<c:ser>");
    EXPECT_GE(series, 2u);
    EXPECT_EQ(occurrences(xml, "<c:xVal>"), series);
    EXPECT_EQ(occurrences(xml, "<c:yVal>"), series);
  }

  // Tab order as the template says.
  const std::string wb = zip_entry(xlsx, "xl/workbook.xml", dir.path());
  std::vector<std::string> order;
  for (auto p = wb.find("<sheet name=\""); p != std::string::npos;
       p = wb.find("<sheet name=\"", p + 1)) {
    const auto b = p + 13;
    order.push_back(wb.substr(b, wb.find('"', b) - b));
  }
  EXPECT_EQ(order, (std::vector<std::string>{"Summary", "Screen A", "Profile", "Inputs", "Blocks",
                                             "Trajectories", "Crossings"}));

  // Summary (sheet1): status cells coloured by conditional formats, not by static fills.
  const std::string s1 = zip_entry(xlsx, "xl/worksheets/sheet1.xml", dir.path());
  EXPECT_NE(s1.find("<conditionalFormatting"), std::string::npos);
  // Two status columns: the barriers' verdicts and the check lines', each PASS, FAIL, WARN.
  EXPECT_EQ(occurrences(s1, "type=\"containsText\""), 6u);
  for (const char* w : {"PASS", "FAIL", "WARN"})
    EXPECT_NE(s1.find(std::string("NOT(ISERROR(SEARCH(\"") + w), std::string::npos) << w;

  // The creation time is the run's date.
  const std::string core = zip_entry(xlsx, "docProps/core.xml", dir.path());
  EXPECT_NE(core.find("2024-05-17T00:00:00Z"), std::string::npos) << core;
}

TEST(XlsxReport, SameInputsSameBytes) {
  TempDir dir;
  const auto f = make_fixture();
  const auto tpl = io::load_report_template(kTemplate);
  io::write_report(dir.path() / "a.xlsx", f->data, tpl);
  io::write_report(dir.path() / "b.xlsx", f->data, tpl);
  EXPECT_EQ(read_file(dir.path() / "a.xlsx"), read_file(dir.path() / "b.xlsx"));
}

// SOURCE_DATE_EPOCH=0, common in reproducible pipelines, is 1970-01-01: a creation time of 0,
// which libxlsxwriter replaced by the current time, so two reports differed.
TEST(XlsxReport, TheFirstDayOf1970IsAFixedDateToo) {
  TempDir dir;
  auto f = make_fixture();
  f->data.date = "1970-01-01";
  const auto tpl = io::load_report_template(kTemplate);
  io::write_report(dir.path() / "a.xlsx", f->data, tpl);
  const std::string core = zip_entry(dir.path() / "a.xlsx", "docProps/core.xml", dir.path());
  EXPECT_NE(core.find("1970-01-01T00:00:01Z"), std::string::npos) << core;
}

// A block bouncing in place until the impact limit records hundreds of thousands of path
// points. Four such paths (1.2 million rows unthinned) overflowed the Profile sheet's
// 1 048 576 rows and the report failed. Now a path is drawn with the points closer than 1/10 000
// of its extent to the one before dropped (the bouncing adds nothing a chart shows), then at
// most 2 000 evenly spaced: the flight before the bouncing keeps its points, and the first and
// last point stay.
TEST(XlsxReport, LongPathsAreThinnedToFitTheSheet) {
  PIERRE_NEED_PROGRAM("unzip");
  TempDir dir;
  auto f = make_fixture();
  f->data.sample_paths.clear();
  constexpr int kFlight = 5000;  // a 100 m flight, one point per 2 cm: more than 2 000 to show
  for (int k = 0; k < 4; ++k) {
    std::vector<geometry::Vec2> path;
    for (int i = 0; i <= kFlight; ++i) {
      const double x = 5.0 + 100.0 * i / kFlight;
      path.push_back({x, 60.0 - 0.004 * (x - 5) * (x - 5)});
    }
    const geometry::Vec2 end = path.back();
    for (int i = 0; i < 300'000; ++i)  // bouncing in place within a millimetre
      path.push_back({end.x + (i % 2) * 1e-3, end.z});
    path.push_back({end.x + 1e-3, end.z - 1e-3 * (k + 1)});  // the last point stays
    f->data.sample_paths.push_back(path);
  }
  const fs::path xlsx = dir.path() / "report.xlsx";
  ASSERT_NO_THROW(io::write_report(xlsx, f->data, io::load_report_template(kTemplate)));

  // The paths' series spans 4 paths of 2 000 points and a gap row after each but the last.
  std::string ref;
  for (const auto& n : zip_list(xlsx, dir.path()))
    if (n.rfind("xl/charts/chart", 0) == 0) {
      const std::string xml = zip_entry(xlsx, n, dir.path());
      const auto at = xml.find("<c:f>Profile!$C$");
      if (at != std::string::npos) ref = xml.substr(at + 16, xml.find('<', at + 5) - at - 16);
    }
  ASSERT_FALSE(ref.empty()) << "no paths series on the Profile chart";
  const long first = std::stol(ref);
  const long last = std::stol(ref.substr(ref.rfind('$') + 1));
  EXPECT_EQ(last - first + 1, 4 * 2000 + 3) << ref;

  // The Profile sheet's column C (x) in the series' rows: almost every drawn point is on the
  // flight, not in the bouncing (which an even thinning of every point would have kept
  // instead: 300 000 of 305 000 points), and each path's first point is x = 5.
  const std::string wb = zip_entry(xlsx, "xl/workbook.xml", dir.path());
  int index = 0, profile = 0;
  for (auto p = wb.find("<sheet name=\""); p != std::string::npos; p = wb.find("<sheet name=\"", p + 1)) {
    ++index;
    if (wb.compare(p + 13, 8, "Profile\"") == 0) profile = index;
  }
  ASSERT_GT(profile, 0) << wb;
  const std::string sheet =
      zip_entry(xlsx, "xl/worksheets/sheet" + std::to_string(profile) + ".xml", dir.path());
  std::vector<double> xs, zs;  // one pass over the cells: <c r="C123" ...><v>value</v>
  for (auto at = sheet.find("<c r=\""); at != std::string::npos; at = sheet.find("<c r=\"", at + 1)) {
    const char col = sheet[at + 6];
    if (col != 'C' && col != 'D') continue;
    const long row = std::strtol(sheet.c_str() + at + 7, nullptr, 10);
    if (row < first || row > last) continue;
    const auto v = sheet.find("<v>", at);
    (col == 'C' ? xs : zs).push_back(std::strtod(sheet.c_str() + v + 3, nullptr));
  }
  ASSERT_EQ(xs.size(), 4u * 2000u);  // the gap rows are empty
  long on_flight = 0;
  for (double x : xs) on_flight += x < 104.99;
  EXPECT_GE(on_flight, 4 * 1990) << "the bouncing crowded out the flight";
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(xs[k * 2000], 5.0) << k;
    EXPECT_NEAR(zs[k * 2000 + 1999], 60.0 - 0.004 * 100 * 100 - 1e-3 * (k + 1), 1e-9) << k;
  }
}

TEST(XlsxReport, LibreOfficeReadsEverySheet) {
  PIERRE_NEED_PROGRAM("soffice");
  TempDir dir;
  const auto f = make_fixture();
  // Roughness settings other than the defaults, each its own number, to find on Inputs.
  auto& rough = f->scenario.scenario.settings.roughness;
  rough.distribution = model::RoughnessDistribution::uniform;
  rough.mean = 0.4;
  rough.sd = 0.6;
  rough.size_reduction = false;
  rough.b = 1.2;
  rough.m = 0.25;
  rough.floor = 0.35;
  auto tpl = io::load_report_template(kTemplate);
  tpl.trajectory_rows = 10;  // cap below the 30 trajectories given
  const fs::path xlsx = dir.path() / "report.xlsx";
  io::write_report(xlsx, f->data, tpl);

  // Every sheet, raw values rather than as shown.
  auto [r, sheets] = export_sheets(xlsx, dir.path());
  ASSERT_EQ(r.status, 0) << r.output;
  for (const char* s : {"Summary", "Screen A", "Profile", "Inputs", "Blocks", "Trajectories", "Crossings"})
    EXPECT_TRUE(sheets.count(s)) << "no sheet " << s << "\n" << r.output;
  ASSERT_TRUE(sheets.count("Summary") && sheets.count("Screen A"));

  // Summary: the check lines with their status, numbers as numbers.
  const Sheet& sum = sheets["Summary"];
  const auto hdr = find_row(sum, 0, "Subject");
  ASSERT_TRUE(hdr);
  const auto sel = find_row(sum, 1, "energy.sel", *hdr);
  ASSERT_TRUE(sel);
  EXPECT_EQ(cell(sum, *sel, 7)->text, "FAIL");
  EXPECT_EQ(number(sum, *sel, 3), 1000.0);
  EXPECT_EQ(number(sum, *sel, 4), 1066.9);
  const auto mel = find_row(sum, 1, "energy.mel", *hdr);
  ASSERT_TRUE(mel);
  EXPECT_EQ(cell(sum, *mel, 7)->text, "PASS");
  const auto fit = find_row(sum, 1, "fit.h", *hdr);
  ASSERT_TRUE(fit);
  EXPECT_EQ(cell(sum, *fit, 7)->text, "WARN");
  // The verdict above the table counts the lines by status, as `pierre check` does.
  std::size_t counts[4] = {0, 0, 0, 0};
  for (const auto& l : f->data.checks) ++counts[static_cast<int>(l.status)];
  ASSERT_GT(counts[1], 0u);
  // Then the lines that FAIL, by subject and id, so that they are not lost in the list.
  std::string failing;
  for (const auto& l : f->data.checks)
    if (l.status == design::CheckStatus::fail)
      failing += (failing.empty() ? "FAIL: " : ", ") + l.subject + " " + l.id;
  EXPECT_EQ(cell(sum, *hdr - 1, 0)->text, failing);
  EXPECT_NE(failing.find("Screen A energy.sel"), std::string::npos) << failing;
  EXPECT_EQ(cell(sum, *hdr - 2, 0)->text,
            std::to_string(f->data.checks.size()) + " check lines: " + std::to_string(counts[1]) +
                " FAIL, " + std::to_string(counts[2]) + " WARN, " + std::to_string(counts[0]) +
                " PASS, " + std::to_string(counts[3]) +
                " N/A (a FAIL makes pierre check exit with code 1, for pipelines; a WARN is advisory)");
  const auto seed = find_row(sum, 0, "Seed");
  ASSERT_TRUE(seed);
  EXPECT_EQ(number(sum, *seed, 2), 12345.0);
  // The observation lines as the console prints them: mean, P50, P95 and max of each quantity,
  // energies in kJ; a line nobody crossed says so rather than showing empty cells.
  const auto sl = find_row(sum, 0, "Screen 1");
  ASSERT_TRUE(sl);
  EXPECT_EQ(cell(sum, *sl, 2)->text, "Speed (m/s)");
  EXPECT_EQ(number(sum, *sl, 3), 18.0);
  EXPECT_EQ(number(sum, *sl, 4), 18.2);
  EXPECT_EQ(number(sum, *sl, 5), 24.1);
  EXPECT_EQ(number(sum, *sl, 6), 31.0);
  EXPECT_EQ(number(sum, *sl, 7), 400.0);
  EXPECT_EQ(number(sum, *sl, 8), 200.0);
  EXPECT_EQ(cell(sum, *sl + 1, 2)->text, "Passing height of the block centre (m)");
  EXPECT_EQ(number(sum, *sl + 1, 4), 1.2);
  EXPECT_EQ(number(sum, *sl + 1, 6), 6.9);
  EXPECT_EQ(cell(sum, *sl + 2, 2)->text, "Translational energy (kJ)");
  EXPECT_EQ(number(sum, *sl + 2, 3), 560.0);
  EXPECT_EQ(number(sum, *sl + 2, 5), 950.0);
  EXPECT_EQ(number(sum, *sl + 2, 6), 1400.0);
  const auto never = find_row(sum, 0, "Screen 9");
  ASSERT_TRUE(never);
  EXPECT_EQ(number(sum, *never, 8), 600.0);
  EXPECT_NE(cell(sum, *never, 2)->text.find("no trajectory crossed this line"), std::string::npos);
  // How the trajectories ended: every reason with its count and share, and what the 10 that
  // left the profile mean for the runout.
  const auto stops = find_row(sum, 0, "Stop reason");
  ASSERT_TRUE(stops);
  const char* reasons[] = {"energy", "friction", "boundary", "time-limit", "impact-limit", "numerical"};
  const double counts_by_reason[] = {560, 30, 10, 0, 0, 0};
  for (std::size_t k = 0; k < 6; ++k) {
    EXPECT_EQ(cell(sum, *stops + 1 + k, 0)->text, reasons[k]);
    EXPECT_EQ(number(sum, *stops + 1 + k, 1), counts_by_reason[k]) << reasons[k];
    EXPECT_NEAR(*number(sum, *stops + 1 + k, 2), counts_by_reason[k] / 600, 1e-15) << reasons[k];
  }
  EXPECT_NE(cell(sum, *stops + 3, 3)->text.find("left the profile"), std::string::npos);
  EXPECT_NE(cell(sum, *stops + 7, 0)->text.find("10 trajectories left the profile; their runout is "
                                                "where they left it, so the runout percentiles are "
                                                "lower bounds"),
            std::string::npos)
      << cell(sum, *stops + 7, 0)->text;

  // The recommended barrier: its design values, then MEL_req and the class, as numbers.
  const auto rec = find_row(sum, 0, "Screen A");
  ASSERT_TRUE(rec);
  EXPECT_EQ(number(sum, *rec, 3), 60.0);
  EXPECT_EQ(number(sum, *rec, 7), 3704.4);
  EXPECT_EQ(number(sum, *rec, 8), 1066.9);
  EXPECT_EQ(number(sum, *rec, 10), 4.02);
  const auto req = find_row(sum, 0, "Screen A", *rec + 1);
  ASSERT_TRUE(req);
  EXPECT_EQ(number(sum, *req, 1), 1386.9);
  EXPECT_EQ(number(sum, *req, 3), 7.0);  // the class the fixture recommends

  // The barrier sheet: Table 4.1's row and the factors.
  const Sheet& bar = sheets["Screen A"];
  const auto t41 = find_row(bar, 1, "v_d = v_k γF (m/s)");
  ASSERT_TRUE(t41);
  EXPECT_EQ(number(bar, *t41 + 1, 1), 24.0);
  EXPECT_EQ(number(bar, *t41 + 1, 2), 3704.4);
  EXPECT_EQ(number(bar, *t41 + 1, 4), 1066.9);
  EXPECT_EQ(number(bar, *t41 + 1, 5), 1386.9);  // MEL_req (kJ)
  EXPECT_EQ(number(bar, *t41 + 1, 6), 4.02);
  const auto mel_row = find_row(bar, 0, "MEL_req");
  ASSERT_TRUE(mel_row);
  EXPECT_EQ(number(bar, *mel_row, 1), 1386.9);
  // The files the design read, for the record.
  const auto rules_row = find_row(bar, 0, "Rule set");
  ASSERT_TRUE(rules_row);
  EXPECT_EQ(cell(bar, *rules_row + 2, 1)->text, "read from firm-rules/thesis-2015.toml");
  const auto classes_row = find_row(bar, 0, "Energy class table");
  ASSERT_TRUE(classes_row);
  EXPECT_EQ(cell(bar, *classes_row, 1)->text, "etag027-classes — ETAG 027 energy classes");
  EXPECT_EQ(cell(bar, *classes_row + 1, 1)->text, "read from firm-rules/etag027-classes.toml");
  const auto gf = find_row(bar, 0, "γF");
  ASSERT_TRUE(gf);
  EXPECT_EQ(number(bar, *gf, 1), 1.16);
  EXPECT_EQ(cell(bar, *gf, 3)->text, "γF = 1.16 (given)");
  // The elongation factor the elongation check uses, and only that one.
  const auto gd = find_row(bar, 0, tpl.get("headings.factors", "gamma_d_MEL"));
  ASSERT_TRUE(gd);
  EXPECT_EQ(number(bar, *gd, 1), 1.3);
  EXPECT_FALSE(find_row(bar, 0, tpl.get("headings.factors", "gamma_d_SEL")));
  const auto ex = find_row(bar, 0, "P(h > h_i)");
  ASSERT_TRUE(ex);
  EXPECT_EQ(number(bar, *ex, 3), 0.025) << dump(bar, *ex);
  EXPECT_EQ(number(bar, *ex, 5), 0.025) << dump(bar, *ex);  // observed data: its column
  EXPECT_EQ(cell(bar, *find_row(bar, 0, "Probability"), 5)->text, "Observed, Weibull");
  const auto wk = find_row(bar, 0, "Weibull shape k");
  ASSERT_TRUE(wk);
  EXPECT_EQ(number(bar, *wk, 1), 3.5);  // speed
  EXPECT_EQ(number(bar, *wk, 2), 1.4);  // height
  const auto cnt = find_row(bar, 0, "Count");
  ASSERT_TRUE(cnt);
  EXPECT_EQ(number(bar, *cnt, 1), 400.0);
  // The chart data: the histogram bins count every crossing.
  const auto bins = find_row(bar, 0, "Bin from");
  ASSERT_TRUE(bins);
  double total = 0;
  for (std::size_t r2 = *bins + 1; r2 < *bins + 1 + 30; ++r2) {
    const auto c = number(bar, r2, 2);
    ASSERT_TRUE(c) << "row " << r2;
    total += *c;
  }
  EXPECT_EQ(total, 400.0);

  // Data sheets: capped and saying so; every number a number.
  const Sheet& tr = sheets["Trajectories"];
  ASSERT_GE(tr.size(), 2u);
  EXPECT_NE(tr[1][0].text.find("First 10 of 600"), std::string::npos) << tr[1][0].text;
  const auto th = find_row(tr, 0, "Trajectory");
  ASSERT_TRUE(th);
  EXPECT_EQ(tr.size(), *th + 1 + 10);
  // No floor contact columns outside a quarry run: the jump height follows the first impact.
  EXPECT_EQ(cell(tr, *th, 14)->text, "First impact z (m)");
  EXPECT_EQ(cell(tr, *th, 15)->text, "Max jump height (m)");
  for (std::size_t r2 = *th + 1; r2 < tr.size(); ++r2) {
    EXPECT_TRUE(number(tr, r2, 0)) << "row " << r2;
    EXPECT_TRUE(number(tr, r2, 9)) << "row " << r2;  // runout
    EXPECT_EQ(cell(tr, r2, 10)->text, "energy");
  }
  const Sheet& cr = sheets["Crossings"];
  const auto ch = find_row(cr, 0, "Trajectory");
  ASSERT_TRUE(ch);
  EXPECT_EQ(cr.size(), *ch + 1 + 400);
  EXPECT_EQ(cell(cr, *ch + 1, 1)->text, "Screen 1");
  EXPECT_EQ(number(cr, *ch + 1, 2), 60.0);
  EXPECT_TRUE(number(cr, *ch + 1, 11));

  // Inputs: the scenario text, one line per row, and the materials with their presets.
  const Sheet& in = sheets["Inputs"];
  EXPECT_TRUE(find_row(in, 1, "name = \"Small talus test\""));
  const auto talus = find_row(in, 0, "talus");
  ASSERT_TRUE(talus);
  EXPECT_TRUE(number(in, *talus, 2));
  // The roughness draw and its size reduction, as set.
  const auto rd = find_row(in, 0, "Roughness distribution of X");
  ASSERT_TRUE(rd);
  EXPECT_EQ(cell(in, *rd + 1, 0)->text, "uniform (Eq 3.4)");
  EXPECT_EQ(number(in, *rd + 1, 1), 0.4);
  EXPECT_EQ(number(in, *rd + 1, 2), 0.6);
  EXPECT_EQ(cell(in, *rd + 1, 3)->text, "off");
  EXPECT_EQ(number(in, *rd + 1, 4), 1.2);
  EXPECT_EQ(number(in, *rd + 1, 5), 0.25);
  EXPECT_EQ(number(in, *rd + 1, 6), 0.35);
  // The profile as read: every vertex (tests/data/small/profile.csv) with the material of the
  // segment that starts there; the last vertex has none.
  const auto pv = find_row(in, 0, "Profile vertices (each row's material is the segment that starts there)");
  ASSERT_TRUE(pv);
  const struct {
    double x, z;
    const char* material;
  } rows[] = {{0, 70, "talus"}, {50, 35, "talus"}, {100, 0, "road"}, {110, 0, "talus"}, {200, -2, ""}};
  for (std::size_t k = 0; k < std::size(rows); ++k) {
    const std::size_t row = *pv + 2 + k;  // under the title and the headings
    EXPECT_EQ(number(in, row, 0), rows[k].x) << k;
    EXPECT_EQ(number(in, row, 1), rows[k].z) << k;
    const auto m = cell(in, row, 2);
    EXPECT_EQ(m ? m->text : std::string(), rows[k].material) << k;
  }
  // Profile: the vertices as numbers.
  const Sheet& pr = sheets["Profile"];
  const auto ph = find_row(pr, 0, "x (m)");
  ASSERT_TRUE(ph);
  EXPECT_TRUE(number(pr, *ph + 1, 0));
  EXPECT_TRUE(number(pr, *ph + 1, 1));
}

// Probabilities of exceedance are percentages however small: 2.17e-5 was shown as "2.17E-05"
// in a column of percentages, which reads as 2.17e-5 % (a hundred times too small).
TEST(XlsxReport, SmallProbabilitiesOfExceedanceShowAsPercentages) {
  PIERRE_NEED_PROGRAM("soffice");
  TempDir dir;
  auto f = make_fixture();
  auto& ex = f->data.barriers.at(0).exceedance;
  ex.at(1).simulated_weibull = 2.17e-5;
  ex.at(1).simulated_empirical = 0.0;
  ex.at(3).simulated_weibull = 1.26e-6;
  for (auto& e : ex) e.observed_weibull.reset();  // no observed data: no Observed column
  // Requirements above class 7: the open-ended class 8, whose bounds are not a capacity.
  f->data.barriers.at(0).energy_class = design::EnergyClass{8, 1500, 4500, true};
  f->data.barriers.at(0).how["energy_class"] = "the smallest class of the table";
  // A check line's probability of exceedance in % (unit "%"): 0.00217 %, not "0.00".
  f->data.checks.push_back(
      line("Screen A", "exceedance.energy", 100 * 2.17e-5, 0.1, "%", design::CheckStatus::pass));
  // Runouts of which the longest ones left the profile at 85 m, the longest at rest 84.75 m: P99
  // and the max lean on the 85 m and are lower bounds, shown "≥ 85.00" (they read as runouts);
  // P95 = 84.5 m, below 84.75 m, is a runout.
  auto& ro = f->data.statistics.runout;
  ro = {600, 40.25, 84.5, 85, 85, 84.75};
  const fs::path xlsx = dir.path() / "report.xlsx";
  io::write_report(xlsx, f->data, io::load_report_template(kTemplate));
  // Every sheet, as shown.
  const auto [r, sheets] = export_sheets(xlsx, dir.path(), true);
  ASSERT_EQ(r.status, 0) << r.output;
  ASSERT_TRUE(sheets.count("Screen A")) << r.output;
  const Sheet* bar = &sheets.at("Screen A");
  const auto mel = find_row(*bar, 0, "P(E > MEL_req)");
  ASSERT_TRUE(mel) << r.output;
  EXPECT_EQ(cell(*bar, *mel, 3)->text, "0.0021700%") << dump(*bar, *mel);
  EXPECT_EQ(cell(*bar, *mel, 4)->text, "0%") << dump(*bar, *mel);
  const auto hmax = find_row(*bar, 0, "P(h > h_max)");
  ASSERT_TRUE(hmax);
  EXPECT_EQ(cell(*bar, *hmax, 3)->text, "0.0001260%") << dump(*bar, *hmax);
  const auto hi = find_row(*bar, 0, "P(h > h_i)");
  ASSERT_TRUE(hi);
  EXPECT_EQ(cell(*bar, *hi, 3)->text, "2.500%") << dump(*bar, *hi);
  // The Summary shows the open class as 8+ with its bounds as bounds, and says what the kit
  // must declare (it showed 8, MEL 4,500.0 and SEL 1,500.0 beside SEL_req 1,066.9 and a larger
  // MEL_req, as if the class fell short of its own requirement).
  const Sheet& sum = sheets.at("Summary");
  {
    const auto tpl = io::load_report_template(kTemplate);
    const std::pair<const char*, const char*> shown[] = {
        {"runout_p50", "40.25"}, {"runout_p95", "84.50"}, {"runout_p99", "≥ 85.00"}, {"runout_max", "≥ 85.00"}};
    for (auto [key, text] : shown) {
      const auto at = find_row(sum, 0, tpl.get("labels", key));
      ASSERT_TRUE(at) << key;
      EXPECT_EQ(cell(sum, *at, 2)->text, text) << dump(sum, *at);
    }
  }
  const auto classes = find_row(sum, 6, tpl_heading("candidate"));
  ASSERT_TRUE(classes);
  const auto rec = find_row(sum, 0, "Screen A", *classes);
  ASSERT_TRUE(rec);
  EXPECT_EQ(cell(sum, *rec, 3)->text, "8+") << dump(sum, *rec);
  EXPECT_EQ(cell(sum, *rec, 4)->text, "> 4,500.0") << dump(sum, *rec);
  EXPECT_EQ(cell(sum, *rec, 5)->text, "> 1,500.0") << dump(sum, *rec);
  bool declared = false;
  for (const auto& row : sum)
    for (const auto& c : row)
      declared = declared || c.text == "Screen A: class 8+, the smallest class of the table; the class is "
                                       "open-ended: the kit must declare MEL >= 1387 kJ and SEL >= 1067 kJ";
  EXPECT_TRUE(declared);
  {
    const auto ex_line = find_row(sum, 1, "exceedance.energy");
    ASSERT_TRUE(ex_line);
    const std::string shown = cell(sum, *ex_line, 3)->text;
    EXPECT_NEAR(std::strtod(shown.c_str(), nullptr), 100 * 2.17e-5, 0.01 * 100 * 2.17e-5)
        << dump(sum, *ex_line);
    EXPECT_EQ(cell(sum, *ex_line, 5)->text, "%");
  }
  const auto head = find_row(*bar, 0, "Probability");
  ASSERT_TRUE(head);
  EXPECT_EQ(cell(*bar, *head, 4)->text, "Simulated, empirical");
  const auto beyond = cell(*bar, *head, 5);
  EXPECT_TRUE(!beyond || beyond->text.empty()) << "an empty Observed column: " << beyond->text;
}

// A rule set that designs on MEL: the Summary's SEL_req is information, and says so (a class
// whose SEL is below it read as failing), while MEL_req stays a requirement; and the reverse.
TEST(XlsxReport, ACapacityTheRulesDoNotDesignOnIsInformation) {
  PIERRE_NEED_PROGRAM("soffice");
  TempDir dir;
  auto f = make_fixture();
  f->data.barriers.at(0).design_on = design::DesignOn::mel;
  f->data.barriers.push_back(f->data.barriers.at(0));
  f->data.barriers.back().spec.name = "Screen B";
  f->data.barriers.back().design_on = design::DesignOn::sel;
  const fs::path xlsx = dir.path() / "report.xlsx";
  io::write_report(xlsx, f->data, io::load_report_template(kTemplate));
  const auto [r, sheets] = export_sheets(xlsx, dir.path(), true);  // as shown
  ASSERT_EQ(r.status, 0) << r.output;
  const Sheet& sum = sheets.at("Summary");
  const auto classes = find_row(sum, 6, tpl_heading("candidate"));
  ASSERT_TRUE(classes);
  const auto a = find_row(sum, 0, "Screen A", *classes), b = find_row(sum, 0, "Screen B", *classes);
  ASSERT_TRUE(a && b);
  // Columns 1 and 2 of the class table: MEL_req and SEL_req (1,386.9 and 1,066.9 kJ in the
  // fixture).
  EXPECT_EQ(cell(sum, *a, 1)->text, "1,386.9") << dump(sum, *a);
  EXPECT_EQ(cell(sum, *a, 2)->text, "1,066.9 (info)") << dump(sum, *a);
  EXPECT_EQ(cell(sum, *b, 1)->text, "1,386.9 (info)") << dump(sum, *b);
  EXPECT_EQ(cell(sum, *b, 2)->text, "1,066.9") << dump(sum, *b);
}

// The Summary gives each barrier's design values, then in a table of its own what it must reach,
// the kit checked against it and the verdict of its check lines, coloured (a reviewer took the
// required class for the kit, whose verdict stood only in a grey note under the table).
TEST(XlsxReport, TheSummaryNamesEachCandidateAndItsVerdict) {
  PIERRE_NEED_PROGRAM("soffice");
  TempDir dir;
  auto f = make_fixture();
  f->data.barriers.push_back(f->data.barriers.at(0));
  f->data.barriers.back().spec.name = "Screen B";
  f->data.barriers.push_back(f->data.barriers.at(0));
  f->data.barriers.back().spec.name = "Screen C";
  f->data.barriers.back().spec.candidate.reset();
  // Screen D: a barrier of the scenario whose line gave no design, and Screen E one whose lines
  // are all N/A.
  f->scenario.barriers.push_back(f->data.barriers.at(0).spec);
  f->scenario.barriers.back().name = "Screen D";
  f->scenario.barriers.back().candidate->mel_kJ = 2000;
  f->data.barriers.push_back(f->data.barriers.at(0));
  f->data.barriers.back().spec.name = "Screen E";
  f->data.checks = {line("Screen A", "energy.mel", 3000, 1386.9, "kJ", design::CheckStatus::pass),
                    line("Screen A", "sample.size", 6.7, 5, "%", design::CheckStatus::warn),
                    line("Screen B", "energy.mel", 3000, 1386.9, "kJ", design::CheckStatus::pass),
                    line("Screen B", "height.interception", 3.5, 4.02, "m", design::CheckStatus::fail),
                    line("Screen B", "elongation", 5, 9, "m", design::CheckStatus::fail),
                    line("Screen B", "sample.size", 6.7, 5, "%", design::CheckStatus::warn),
                    line("Screen C", "reach", 445, 30, "", design::CheckStatus::pass),
                    line("Screen D", "reach", 0, 30, "", design::CheckStatus::fail),
                    line("Screen E", "observed.fit", std::nan(""), std::nan(""), "", design::CheckStatus::not_applicable)};
  const fs::path xlsx = dir.path() / "report.xlsx";
  io::write_report(xlsx, f->data, io::load_report_template(kTemplate));
  const auto [r, sheets] = export_sheets(xlsx, dir.path(), true);
  ASSERT_EQ(r.status, 0) << r.output;
  const Sheet& sum = sheets.at("Summary");
  // The design values: E_d and h_i as the fixture's barrier has them.
  // The design mass m_d stands beside them: E_d = ½ m_d v_d² is checkable by hand.
  const auto values = find_row(sum, 8, tpl_heading("e_d"));
  ASSERT_TRUE(values);
  EXPECT_EQ(cell(sum, *values, 7)->text, tpl_heading("m_d"));
  const auto a_values = find_row(sum, 0, "Screen A", *values);
  ASSERT_TRUE(a_values);
  EXPECT_EQ(cell(sum, *a_values, 6)->text, "24.00") << dump(sum, *a_values);     // v_d = 24.0
  EXPECT_EQ(cell(sum, *a_values, 7)->text, "3,704") << dump(sum, *a_values);     // m_d = 3704.4
  EXPECT_EQ(cell(sum, *a_values, 8)->text, "1,066.9") << dump(sum, *a_values);  // E_d_kJ = 1066.9
  EXPECT_EQ(cell(sum, *a_values, 10)->text, "4.02") << dump(sum, *a_values);     // h_i = 4.02
  // The class table: the kit, the verdict and the lines behind it.
  const auto classes = find_row(sum, 6, tpl_heading("candidate"));
  ASSERT_TRUE(classes);
  struct Expected {
    std::string name, kit, verdict, lines;
  };
  const std::string kit = "class 6, MEL 3000 kJ, SEL 1000 kJ, height 3.50 m";
  for (const Expected& e :
       {Expected{"Screen A", kit, "WARN", "WARN sample.size"},
        Expected{"Screen B", kit, "FAIL", "FAIL height.interception, elongation; WARN sample.size"},
        Expected{"Screen C", "none given (design only)", "PASS", ""},
        Expected{"Screen D", "class 6, MEL 2000 kJ, height 3.50 m", "FAIL", "FAIL reach"},
        Expected{"Screen E", kit, "N/A", ""}}) {
    const auto row = find_row(sum, 0, e.name, *classes);
    ASSERT_TRUE(row) << e.name;
    EXPECT_EQ(cell(sum, *row, 6)->text, e.kit) << dump(sum, *row);
    EXPECT_EQ(cell(sum, *row, 7)->text, e.verdict) << dump(sum, *row);
    const auto lines = cell(sum, *row, 8);
    EXPECT_EQ(lines ? lines->text : std::string(), e.lines) << dump(sum, *row);
  }
  // Screen D's design columns say why they are empty.
  const auto d = find_row(sum, 0, "Screen D", *classes);
  ASSERT_TRUE(d);
  EXPECT_EQ(cell(sum, *d, 1)->text, io::load_report_template(kTemplate).get("labels", "no_design"));
}

// The Summary states what the numbers rest on: the model and what it leaves out, the run's own
// trajectories and seed, how barriers are designed (a report with barriers only, as here: no
// quarry paragraph); a firm's layout may leave a paragraph out.
TEST(XlsxReport, TheSummaryStatesTheBasisOfTheResults) {
  PIERRE_NEED_PROGRAM("soffice");
  TempDir dir;
  const auto f = make_fixture();
  auto tpl = io::load_report_template(kTemplate);
  auto basis_of = [&](const io::ReportTemplate& layout) {
    const fs::path xlsx = dir.path() / "report.xlsx";
    io::write_report(xlsx, f->data, layout);
    const auto [r, sheets] = export_sheets(xlsx, dir.path(), true);
    EXPECT_EQ(r.status, 0) << r.output;
    std::vector<std::string> paragraphs;
    bool in = false;
    for (const auto& row : sheets.at("Summary")) {
      const std::string first = row.empty() ? "" : row[0].text;
      if (first == "Basis of the results") {
        in = true;
        continue;
      }
      if (in && first.empty()) break;  // the blank row before the next table
      if (in) paragraphs.push_back(first);
    }
    return paragraphs;
  };
  const auto basis = basis_of(tpl);
  ASSERT_EQ(basis.size(), 4u) << ::testing::PrintToString(basis);
  EXPECT_EQ(basis[0].rfind("Model: PIERRE 2, the stochastic lumped-mass rockfall model", 0), 0u);
  EXPECT_EQ(basis[1].rfind("Not modelled: motion out of the section's plane", 0), 0u);
  EXPECT_EQ(basis[2].rfind("Statistics: every number is computed from the 600 simulated "
                           "trajectories of seed 12345;", 0),
            0u)
      << basis[2];
  EXPECT_EQ(basis[3].rfind("Barriers: each is designed as its rule set states", 0), 0u);
  tpl.text["basis"]["barriers"] = "";
  const auto without = basis_of(tpl);
  ASSERT_EQ(without.size(), 3u);
  EXPECT_EQ(without[2], basis[2]);
}

// A barrier's sheet says what the passing height is (the centre of a point mass: a reviewer could
// not check h_i = h_d + f without it) and that E_d leaves out the rotation, with the rotational
// energy at the line (the fixture's: mean 28 kJ, max 70 kJ).
TEST(XlsxReport, ABarrierSheetDefinesThePassingHeightAndSaysEdIsTranslational) {
  PIERRE_NEED_PROGRAM("soffice");
  TempDir dir;
  auto f = make_fixture();
  const fs::path xlsx = dir.path() / "report.xlsx";
  io::write_report(xlsx, f->data, io::load_report_template(kTemplate));
  const auto [r, sheets] = export_sheets(xlsx, dir.path(), true);
  ASSERT_EQ(r.status, 0) << r.output;
  const Sheet& bar = sheets.at("Screen A");
  auto starting = [&](const std::string& prefix) -> std::optional<std::size_t> {
    for (std::size_t i = 0; i < bar.size(); ++i)
      if (!bar[i].empty() && bar[i][0].text.rfind(prefix, 0) == 0) return i;
    return std::nullopt;
  };
  const auto height = starting("Passing height: the vertical distance from the ground");
  ASSERT_TRUE(height);
  const auto stats = starting("Statistics of the first crossings");
  const auto boot = starting("Bootstrap confidence intervals");
  ASSERT_TRUE(stats && boot);
  EXPECT_GT(*height, *stats);  // under the statistics
  EXPECT_LT(*height, *boot);
  const auto ed = starting("E_d = ½ m_d v_d² is translational");
  ASSERT_TRUE(ed);
  EXPECT_NE(cell(bar, *ed, 0)->text.find("(mean 28.0 kJ, max 70.0 kJ, in the statistics above)"),
            std::string::npos)
      << cell(bar, *ed, 0)->text;
}

// Inputs, a barrier's inputs that the procedure resolved or defaulted: the design block's volume
// and density by a rule (`largest`), D_f by default, MEL and SEL from the candidate's class. Each
// shows the value used and where it comes from; they were blank, which a client cannot tell
// from a missing input.
TEST(XlsxReport, ResolvedBarrierInputsShowTheirValuesAndOrigins) {
  PIERRE_NEED_PROGRAM("soffice");
  TempDir dir;
  auto f = make_fixture();
  design::BarrierDesign& b = f->data.barriers.at(0);
  b.spec.design_block = design::DesignBlock{};  // largest, its own density
  b.spec.free_board_diameter.reset();
  ASSERT_TRUE(b.spec.candidate && b.spec.candidate->energy_class && !b.spec.candidate->mel_kJ &&
              !b.spec.candidate->sel_kJ);
  b.design_volume = 1.4375;
  b.design_density = 2650;
  b.free_board_diameter = 1.1875;
  b.how["volume"] = "the largest block thrown, by mass";
  b.how["density"] = "the heaviest block's";
  b.how["free_board_diameter"] = "the mean equivalent diameter of the blocks thrown";
  const fs::path xlsx = dir.path() / "report.xlsx";
  const auto tpl = io::load_report_template(kTemplate);
  io::write_report(xlsx, f->data, tpl);
  const auto [r, sheets] = export_sheets(xlsx, dir.path());
  ASSERT_EQ(r.status, 0) << r.output;
  ASSERT_TRUE(sheets.count("Inputs")) << r.output;
  const Sheet& in = sheets.at("Inputs");
  // The barrier's column (1) of a row named by the template.
  auto value = [&](std::string_view key) -> std::string {
    const auto k = find_row(in, 0, tpl.get("headings.barrier_inputs", key));
    if (!k) return "(no row " + std::string(key) + ")";
    const Field* c = cell(in, *k, 1);
    return c ? c->text : "";
  };
  // Not blank, the value used first, then where it comes from.
  auto expect_resolved = [&](std::string_view key, double used, const std::string& origin) {
    const std::string t = value(key);
    SCOPED_TRACE(std::string(key) + ": " + t);
    ASSERT_FALSE(t.empty());
    char* end = nullptr;
    const double v = std::strtod(t.c_str(), &end);
    EXPECT_NEAR(v, used, 1e-3 * used);
    EXPECT_NE(std::string_view(end).find(origin), std::string::npos);
  };
  expect_resolved("volume", b.design_volume, b.how["volume"]);
  expect_resolved("density", b.design_density, b.how["density"]);
  expect_resolved("free_board_diameter", b.free_board_diameter, b.how["free_board_diameter"]);
  expect_resolved("free_board_diameter", b.free_board_diameter, "default");
  const std::string cls = std::to_string(*b.spec.candidate->energy_class);
  expect_resolved("mel", b.candidate_mel_kJ, "class " + cls);
  expect_resolved("sel", b.candidate_sel_kJ, "class " + cls);
  // A given input stays a number.
  const auto height = find_row(in, 0, tpl.get("headings.barrier_inputs", "height"));
  ASSERT_TRUE(height);
  EXPECT_TRUE(number(in, *height, 1));
}

// The readers' notes (likely mistakes the run went on with) reach the client's report: on the
// Summary beside the run's settings, and on Inputs above the echoed scenario.
TEST(XlsxReport, InputNotesAreOnTheSummaryAndInputs) {
  PIERRE_NEED_PROGRAM("soffice");
  TempDir dir;
  auto f = make_fixture();
  io::InputNote n;
  n.file = "profile.csv";
  n.line = 5;
  n.field = "x";
  n.text = "profile segment 1 runs back in x: it is read as an overhang";
  f->scenario.notes.push_back(n);
  const fs::path xlsx = dir.path() / "report.xlsx";
  const auto tpl = io::load_report_template(kTemplate);
  io::write_report(xlsx, f->data, tpl);
  const auto [r, sheets] = export_sheets(xlsx, dir.path());
  ASSERT_EQ(r.status, 0) << r.output;
  const Sheet& sum = sheets.at("Summary");
  const auto k = find_row(sum, 0, tpl.get("labels", "input_notes"));
  ASSERT_TRUE(k);
  EXPECT_EQ(cell(sum, *k, 2)->text, "profile.csv:5: x: " + n.text);
  const Sheet& in = sheets.at("Inputs");
  EXPECT_TRUE(find_row(in, 0, tpl.get("labels", "input_notes") + ": profile.csv:5: x: " + n.text));
  // Without notes, no such line.
  f->scenario.notes.clear();
  io::write_report(xlsx, f->data, tpl);
  const auto [r2, plain] = export_sheets(xlsx, dir.path());
  ASSERT_EQ(r2.status, 0) << r2.output;
  EXPECT_FALSE(find_row(plain.at("Summary"), 0, tpl.get("labels", "input_notes")));
}

// The Profile sheet's title names what its chart holds: barriers stand at observation lines,
// so a run has both, lines alone, or neither.
TEST(XlsxReport, TheProfileTitleNamesWhatTheChartHolds) {
  PIERRE_NEED_PROGRAM("soffice");
  TempDir dir;
  auto f = make_fixture();
  const auto tpl = io::load_report_template(kTemplate);
  const fs::path xlsx = dir.path() / "report.xlsx";
  auto title = [&] {
    io::write_report(xlsx, f->data, tpl);
    const auto [r, sheets] = export_sheets(xlsx, dir.path());
    EXPECT_EQ(r.status, 0) << r.output;
    const Field* c = sheets.count("Profile") ? cell(sheets.at("Profile"), 0, 0) : nullptr;
    return c ? c->text : std::string("(no title)");
  };
  ASSERT_FALSE(f->data.barriers.empty());
  ASSERT_FALSE(f->scenario.scenario.lines.empty());
  EXPECT_EQ(title(), tpl.get("titles", "profile"));
  f->data.barriers.clear();
  EXPECT_EQ(title(), tpl.get("titles", "profile_lines"));
  f->scenario.scenario.lines.clear();
  EXPECT_EQ(title(), tpl.get("titles", "profile_plain"));
}

TEST(XlsxReport, LibreOfficePrintsToPdf) {
  PIERRE_NEED_PROGRAM("soffice");
  TempDir dir;
  const auto f = make_fixture();
  const auto tpl = io::load_report_template(kTemplate);
  const fs::path xlsx = dir.path() / "report.xlsx";
  io::write_report(xlsx, f->data, tpl);
  const Exec r = soffice("--convert-to pdf --outdir '" + dir.path().string() + "' '" +
                            xlsx.string() + "'",
                        dir.path());
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string pdf = read_file(dir.path() / "report.pdf");
  ASSERT_GT(pdf.size(), 20000u) << r.output;
  EXPECT_EQ(pdf.substr(0, 5), "%PDF-");
}

TEST(XlsxReport, FailedWriteLeavesNothingBehind) {
  TempDir dir;
  const auto f = make_fixture();
  auto tpl = io::load_report_template(kTemplate);
  const fs::path xlsx = dir.path() / "report.xlsx";
  // A sheet name Excel refuses (only a template edited in code can hold one).
  tpl.text["sheets"]["profile"] = "Pro[file]";
  try {
    io::write_report(xlsx, f->data, tpl);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("Pro[file]"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::is_empty(dir.path()));

  // An earlier report stays as it was.
  dir.write("report.xlsx", "earlier");
  EXPECT_THROW(io::write_report(xlsx, f->data, tpl), std::runtime_error);
  EXPECT_EQ(read_file(xlsx), "earlier");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator()), 1);

  // A date that cannot fix the creation time.
  auto g = make_fixture();
  g->data.date = "17/05/2024";
  EXPECT_THROW(io::write_report(dir.path() / "x.xlsx", g->data,
                                io::load_report_template(kTemplate)),
               std::runtime_error);
  EXPECT_FALSE(fs::exists(dir.path() / "x.xlsx"));

  // A folder that does not exist: libxlsxwriter cannot create the file.
  EXPECT_THROW(io::write_report(dir.path() / "no" / "such" / "report.xlsx", g->data, tpl),
               std::runtime_error);
}

// Every member of a zip, in order: name and text (minizip, as pierre reads the report).
std::vector<std::pair<std::string, std::string>> zip_parts(const fs::path& zip_file) {
  std::vector<std::pair<std::string, std::string>> parts;
  unzFile z = unzOpen64(zip_file.c_str());
  if (!z) return parts;
  for (int r = unzGoToFirstFile(z); r == UNZ_OK; r = unzGoToNextFile(z)) {
    char name[512];
    unz_file_info64 info;
    if (unzGetCurrentFileInfo64(z, &info, name, sizeof name, nullptr, 0, nullptr, 0) != UNZ_OK ||
        unzOpenCurrentFile(z) != UNZ_OK)
      break;
    std::string text(info.uncompressed_size, '\0');
    const int n = unzReadCurrentFile(z, text.data(), static_cast<unsigned>(text.size()));
    unzCloseCurrentFile(z);
    text.resize(n > 0 ? static_cast<std::size_t>(n) : 0);
    parts.emplace_back(name, std::move(text));
  }
  unzClose(z);
  return parts;
}

void write_zip(const fs::path& zip_file, const std::vector<std::pair<std::string, std::string>>& parts) {
  zipFile z = zipOpen64(zip_file.c_str(), APPEND_STATUS_CREATE);
  ASSERT_NE(z, nullptr);
  for (const auto& [name, text] : parts) {
    zip_fileinfo info{};
    ASSERT_EQ(zipOpenNewFileInZip64(z, name.c_str(), &info, nullptr, 0, nullptr, 0, nullptr,
                                    Z_DEFLATED, 1, 0),
              ZIP_OK);
    ASSERT_EQ(zipWriteInFileInZip(z, text.data(), static_cast<unsigned>(text.size())), ZIP_OK);
    ASSERT_EQ(zipCloseFileInZip(z), ZIP_OK);
  }
  ASSERT_EQ(zipClose(z, nullptr), ZIP_OK);
}

// The block groups are on a sheet of their own, their headings repeated on every printed page
// (the print titles; on Inputs the table ran over pages without them), and Inputs says where.
TEST(XlsxReport, TheBlockGroupsHaveASheetWithHeadingsOnEveryPage) {
  PIERRE_NEED_PROGRAM("soffice");
  PIERRE_NEED_PROGRAM("unzip");
  TempDir dir;
  const auto f = make_fixture();
  const fs::path xlsx = dir.path() / "report.xlsx";
  io::write_report(xlsx, f->data, io::load_report_template(kTemplate));
  const std::string wb = zip_entry(xlsx, "xl/workbook.xml", dir.path());
  EXPECT_NE(wb.find(">Blocks!$3:$3</definedName>"), std::string::npos) << wb;
  const auto [r, sheets] = export_sheets(xlsx, dir.path(), true);
  ASSERT_EQ(r.status, 0) << r.output;
  const Sheet& b = sheets.at("Blocks");
  ASSERT_GT(b.size(), 2u);
  EXPECT_EQ(cell(b, 0, 0)->text, "Block groups");
  EXPECT_EQ(cell(b, 2, 0)->text, "Block group");
  const auto& groups = f->scenario.block_groups;
  ASSERT_FALSE(groups.empty());
  EXPECT_EQ(b.size(), 3u + groups.size());
  for (std::size_t k = 0; k < groups.size(); ++k) {
    EXPECT_EQ(cell(b, 3 + k, 0)->text, groups[k].id);
    EXPECT_EQ(number(b, 3 + k, 7), static_cast<double>(groups[k].count));
    // The sphere of equal volume the model throws: D = (6 V / π)^(1/3), at the shown 0.00.
    const double d = std::cbrt(6.0 * groups[k].mass / groups[k].density / std::numbers::pi);
    EXPECT_NEAR(*number(b, 3 + k, 4), d, 0.005 + 1e-12) << groups[k].id;
  }
  const Sheet& in = sheets.at("Inputs");
  EXPECT_TRUE(find_row(in, 0, "On the sheet Blocks: a long table, on a sheet of its own so that "
                              "its headings are on every printed page."));
}

// The read-back that catches a part libxlsxwriter cut short (xlsx_parts_check.hpp) passes a
// whole report, and refuses what is not a workbook at all.
TEST(XlsxReport, AWrittenReportReadsBackWhole) {
  TempDir dir;
  const auto f = make_fixture();
  const fs::path xlsx = dir.path() / "report.xlsx";
  io::write_report(xlsx, f->data, io::load_report_template(kTemplate));
  EXPECT_EQ(io::detail::first_incomplete_part(xlsx), std::nullopt);
  // The same workbook with one XML part cut short, in a zip that is otherwise sound (its CRC is
  // that of the cut text, as libxlsxwriter writes it when its temporary file was cut).
  const std::vector<std::pair<std::string, std::string>> parts = zip_parts(xlsx);
  ASSERT_GT(parts.size(), 10u);
  int cut = 0;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const std::string& name = parts[k].first;
    if (!name.ends_with(".xml") && !name.ends_with(".rels")) continue;
    auto copy = parts;
    copy[k].second.resize(copy[k].second.size() * 2 / 3);
    const fs::path broken = dir.path() / "cut.xlsx";
    write_zip(broken, copy);
    EXPECT_EQ(io::detail::first_incomplete_part(broken), name);
    ++cut;
  }
  EXPECT_GT(cut, 10);
  write_zip(dir.path() / "uncut.xlsx", parts);
  EXPECT_EQ(io::detail::first_incomplete_part(dir.path() / "uncut.xlsx"), std::nullopt);
  dir.write("not-a-zip.xlsx", "PK but not a zip");
  EXPECT_EQ(io::detail::first_incomplete_part(dir.path() / "not-a-zip.xlsx"), "the archive");
  EXPECT_EQ(io::detail::first_incomplete_part(dir.path() / "missing.xlsx"), "the archive");
}

// Column widths: one <col> entry per column at most. A range set and then one column in it
// again gave overlapping entries, of which LibreOffice ignored the wider one (data sheets'
// text ran into the next column) and which OOXML does not allow.
TEST(XlsxReport, ColumnWidthEntriesDoNotOverlap) {
  PIERRE_NEED_PROGRAM("unzip");
  TempDir dir;
  auto f = make_fixture(50, 5);
  const fs::path xlsx = dir.path() / "report.xlsx";
  io::write_report(xlsx, f->data, io::load_report_template(kTemplate));
  int sheets = 0;
  for (const auto& n : zip_list(xlsx, dir.path())) {
    if (n.rfind("xl/worksheets/sheet", 0) != 0) continue;
    ++sheets;
    const std::string x = zip_entry(xlsx, n, dir.path());
    std::vector<std::pair<long, long>> cols;
    for (std::size_t k = x.find("<col "); k != std::string::npos; k = x.find("<col ", k + 1)) {
      const auto attr = [&](const char* a) {
        const std::size_t p = x.find(std::string(a) + "=\"", k) + std::string(a).size() + 2;
        return std::stol(x.substr(p, x.find('"', p) - p));
      };
      cols.emplace_back(attr("min"), attr("max"));
    }
    std::sort(cols.begin(), cols.end());
    for (std::size_t i = 1; i < cols.size(); ++i)
      EXPECT_GT(cols[i].first, cols[i - 1].second) << n << ": columns " << cols[i - 1].first << "-"
                                                   << cols[i - 1].second << " and " << cols[i].first
                                                   << "-" << cols[i].second << " overlap";
  }
  EXPECT_GE(sheets, 5);
}

// The height set on the row of the sheet `sheet` that holds the shared string `text` (its first
// cell holding it), 0 when the row has the default height; fails the test when there is none.
double row_height_of(const fs::path& xlsx, const std::string& sheet, const std::string& text,
                     const fs::path& tmp) {
  const std::string strings = zip_entry(xlsx, "xl/sharedStrings.xml", tmp);
  long index = 0, found = -1;
  for (std::size_t k = strings.find("<si>"); k != std::string::npos; k = strings.find("<si>", k + 1), ++index)
    if (found < 0 && strings.compare(k + 4, 4 + text.size(), "<t>" + text + "<") == 0) found = index;
  EXPECT_GE(found, 0) << text;
  const std::string wb = zip_entry(xlsx, "xl/workbook.xml", tmp);
  int number = 0, at = 0;
  for (auto p = wb.find("<sheet name=\""); p != std::string::npos; p = wb.find("<sheet name=\"", p + 1)) {
    ++number;
    if (wb.compare(p + 13, sheet.size() + 1, sheet + "\"") == 0) at = number;
  }
  EXPECT_GT(at, 0) << sheet;
  const std::string x = zip_entry(xlsx, "xl/worksheets/sheet" + std::to_string(at) + ".xml", tmp);
  const std::size_t v = x.find("<v>" + std::to_string(found) + "</v>");
  EXPECT_NE(v, std::string::npos) << text;
  if (found < 0 || v == std::string::npos) return 0;
  const std::size_t row = x.rfind("<row ", v);
  const std::size_t ht = x.find("ht=\"", row);
  return ht < x.find('>', row) ? std::stod(x.substr(ht + 4)) : 0;
}

// A long note stays inside the printed page: merged over the print area's columns (Summary A:J;
// a barrier sheet's "how it was obtained" D:I), wrapped, its row as high as its lines. In one
// cell, the energy class's note and the partial factors' derivations ran off the page.
// A wrapped cell's row is as tall as its text wraps word by word: the rule of a quarry's
// bench.retention line, 56 characters in the Summary's Rule column (26 wide, about 30 characters
// a line), wraps to three lines ("quarry-thesis-2015 docs/quarry.md" does not fit one), not the
// two its characters alone gave, which clipped "retention)".
TEST(XlsxReport, AWrappedRowIsAsTallAsItsWordsWrap) {
  PIERRE_NEED_PROGRAM("unzip");
  TempDir dir;
  auto f = make_fixture();
  design::CheckLine l = line("Preg 2", "bench.retention", 57.2, 90, "%", design::CheckStatus::fail);
  l.what = "short";
  l.reason = "short";
  l.rule = "quarry-thesis-2015 docs/quarry.md (catch-bench retention)";
  f->data.checks = {l};
  const fs::path xlsx = dir.path() / "report.xlsx";
  io::write_report(xlsx, f->data, io::load_report_template(kTemplate));
  EXPECT_GE(row_height_of(xlsx, "Summary", l.rule, dir.path()), 3 * 15.0);
}

// The Summary prints every column of its tables: the barriers' design values reach K (h_i, after
// m_d was added), and the print area with them (it stopped at J, and h_i was not printed).
TEST(XlsxReport, TheSummaryPrintsEveryColumnOfItsTables) {
  PIERRE_NEED_PROGRAM("unzip");
  TempDir dir;
  auto f = make_fixture();
  const fs::path xlsx = dir.path() / "report.xlsx";
  io::write_report(xlsx, f->data, io::load_report_template(kTemplate));
  const std::string wb = zip_entry(xlsx, "xl/workbook.xml", dir.path());
  const std::size_t area = wb.find(">Summary!$A$1:$");
  ASSERT_NE(area, std::string::npos) << wb;
  EXPECT_EQ(wb.substr(area + 15, 2), "K$") << wb.substr(area, 40);
}

// The Inputs sheet heads each barrier's column with its name: a long one wraps in a row as
// tall as it needs (the row kept its default height and clipped it: new-user review).
TEST(XlsxReport, ALongBarrierNameIsNotClippedOnInputs) {
  PIERRE_NEED_PROGRAM("unzip");
  TempDir dir;
  auto f = make_fixture();
  const std::string name = "Rockfall barrier above the north portal";  // 40 characters, 3 lines
  f->data.barriers.at(0).spec.name = name;
  // A name longer in bytes (two-byte letters: 49 bytes) that wraps to fewer lines (2) does not
  // decide the height.
  f->data.barriers.push_back(f->data.barriers.at(0));
  f->data.barriers.back().spec.name = "ÄÖÜÄÖÜÄÖÜÄÖÜ ÄÖÜÄÖÜÄÖÜÄÖÜ";
  const fs::path xlsx = dir.path() / "report.xlsx";
  io::write_report(xlsx, f->data, io::load_report_template(kTemplate));
  EXPECT_GE(row_height_of(xlsx, "Inputs", name, dir.path()), 3 * 15.0);
}

// A run without barriers or quarries: the Summary says there are no checks, without a check
// table's headings over nothing (a reviewer found them under the sentence).
TEST(XlsxReport, NoChecksNoCheckTable) {
  PIERRE_NEED_PROGRAM("soffice");
  TempDir dir;
  auto f = make_fixture();
  f->data.barriers.clear();
  f->data.checks.clear();
  const fs::path xlsx = dir.path() / "report.xlsx";
  io::write_report(xlsx, f->data, io::load_report_template(kTemplate));
  const auto [r, sheets] = export_sheets(xlsx, dir.path(), true);
  ASSERT_EQ(r.status, 0) << r.output;
  const Sheet& sum = sheets.at("Summary");
  const auto tpl = io::load_report_template(kTemplate);
  EXPECT_TRUE(find_row(sum, 0, tpl.get("labels", "no_checks")));
  // The runout percentiles say what they are measured from (a quarry run's say more).
  EXPECT_TRUE(find_row(sum, 0, tpl.get("labels", "runout_note")));
  EXPECT_FALSE(find_row(sum, 0, "Subject"));
}

// A barrier's histograms are of the sample at its observation line, and their titles name the
// line ("Speed at Screen 1"), not the barrier ("Speed at Screen A" read as the barrier's speed).
TEST(XlsxReport, BarrierHistogramsNameTheLineTheySample) {
  PIERRE_NEED_PROGRAM("unzip");
  TempDir dir;
  auto f = make_fixture();
  const fs::path xlsx = dir.path() / "report.xlsx";
  io::write_report(xlsx, f->data, io::load_report_template(kTemplate));
  std::string titles;
  for (const auto& n : zip_list(xlsx, dir.path()))
    if (n.rfind("xl/charts/chart", 0) == 0) titles += zip_entry(xlsx, n, dir.path());
  for (const char* t : {"Speed at Screen 1<", "Passing height at Screen 1<", "Translational energy at Screen 1<"})
    EXPECT_NE(titles.find(t), std::string::npos) << t;
  EXPECT_EQ(titles.find("at Screen A<"), std::string::npos);
}

// Every printed page is headed by the project and the document control (reference, revision)
// with the report's date, an & of theirs doubled (a single one is a code to Excel); the Summary
// lists the document control given.
TEST(XlsxReport, EveryPageIsHeadedByTheProjectAndTheDocument) {
  PIERRE_NEED_PROGRAM("unzip");
  TempDir dir;
  auto f = make_fixture();
  f->scenario.document = {"P-17 & Co", "B", "A. Engineer", ""};
  const fs::path xlsx = dir.path() / "report.xlsx";
  io::write_report(xlsx, f->data, io::load_report_template(kTemplate));
  int sheets = 0;
  const std::string want = "<oddHeader>&amp;L" + f->scenario.scenario.name +
                           "&amp;RP-17 &amp;&amp; Co  ·  rev. B  ·  2024-05-17</oddHeader>";
  for (const auto& n : zip_list(xlsx, dir.path())) {
    if (n.rfind("xl/worksheets/sheet", 0) != 0) continue;
    ++sheets;
    EXPECT_NE(zip_entry(xlsx, n, dir.path()).find(want), std::string::npos) << n;
  }
  EXPECT_GE(sheets, 5);
  const std::string strings = zip_entry(xlsx, "xl/sharedStrings.xml", dir.path());
  for (const char* t : {"<t>Reference</t>", "<t>Revision</t>", "<t>Prepared by</t>", "<t>A. Engineer</t>"})
    EXPECT_NE(strings.find(t), std::string::npos) << t;
  EXPECT_EQ(strings.find("<t>Checked by</t>"), std::string::npos);  // not given: not listed

  // Long values are cut, never the date or the revision, within Excel's 255 characters (an
  // 80-character reference lost both: the whole text was cut at 50 bytes).
  f->scenario.scenario.name = std::string(150, 'P');
  f->scenario.document = {std::string(40, '&') + std::string(40, 'R'), "B", "", ""};
  io::write_report(xlsx, f->data, io::load_report_template(kTemplate));
  const std::string x = zip_entry(xlsx, "xl/worksheets/sheet1.xml", dir.path());
  const std::size_t a = x.find("<oddHeader>"), b = x.find("</oddHeader>");
  ASSERT_NE(a, std::string::npos);
  std::string header = x.substr(a + 11, b - a - 11);
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"&amp;", "&"}, {"&lt;", "<"}})
    for (std::size_t k; (k = header.find(from)) != std::string::npos;) header.replace(k, from.size(), to);
  EXPECT_LE(header.size(), 255u) << header;
  EXPECT_NE(header.find("rev. B  ·  2024-05-17"), std::string::npos) << header;
  EXPECT_NE(header.find("&&&&"), std::string::npos) << header;  // the reference's &s, doubled
}

// A check whose rule the rule set marks "(verify)" (design-checks.md: read from a secondary
// source) is explained under the check table, for a client who meets the mark; a table
// without one has no such note.
TEST(XlsxReport, AVerifyMarkIsExplainedUnderTheChecks) {
  PIERRE_NEED_PROGRAM("unzip");
  TempDir dir;
  auto f = make_fixture();
  const fs::path xlsx = dir.path() / "report.xlsx";
  const std::string note = "<t>(verify): the rule set marks this value as read from a secondary source";
  io::write_report(xlsx, f->data, io::load_report_template(kTemplate));
  EXPECT_EQ(zip_entry(xlsx, "xl/sharedStrings.xml", dir.path()).find(note), std::string::npos);
  design::CheckLine l = line("Screen A", "energy.mel", 3000, 1386.9, "kJ", design::CheckStatus::pass);
  l.rule = "peila-ronco-2009 §3 (MEL_req = γE,MEL · ½ m_d v_d²) (verify)";
  f->data.checks.push_back(l);
  f->data.barriers.at(0).checks = {l};
  io::write_report(xlsx, f->data, io::load_report_template(kTemplate));
  const std::string strings = zip_entry(xlsx, "xl/sharedStrings.xml", dir.path());
  const std::size_t at = strings.find(note);
  ASSERT_NE(at, std::string::npos);
  // Under the Summary's table and under the barrier sheet's: the one shared string (its index:
  // the <si> entries before it) in both sheets.
  long index = -1;
  for (std::size_t p = strings.find("<si>"); p < at; p = strings.find("<si>", p + 1)) ++index;
  ASSERT_GE(index, 0);
  const std::string v = "<v>" + std::to_string(index) + "</v>";
  EXPECT_NE(zip_entry(xlsx, "xl/worksheets/sheet1.xml", dir.path()).find(v), std::string::npos);
  EXPECT_NE(zip_entry(xlsx, "xl/worksheets/sheet2.xml", dir.path()).find(v), std::string::npos);
}

TEST(XlsxReport, LongNotesStayInsideThePrintArea) {
  PIERRE_NEED_PROGRAM("unzip");
  TempDir dir;
  auto f = make_fixture();
  std::string words;
  for (int i = 0; i < 40; ++i) words += "a reason in many words ";  // 920 characters
  f->data.barriers.at(0).how["energy_class"] = words;
  f->data.barriers.at(0).gamma_F.how = words;
  const fs::path xlsx = dir.path() / "report.xlsx";
  io::write_report(xlsx, f->data, io::load_report_template(kTemplate));
  // The row of the cell holding `text` (a shared string's index in its <c>), its merged range
  // and its height.
  const std::string strings = zip_entry(xlsx, "xl/sharedStrings.xml", dir.path());
  auto string_index = [&](const std::string& prefix) {
    long index = 0;
    for (std::size_t k = strings.find("<si>"); k != std::string::npos;
         k = strings.find("<si>", k + 1), ++index)
      if (strings.find("<t>" + prefix, k) == k + 4 || strings.find("<t xml:space=\"preserve\">" + prefix, k) == k + 4)
        return index;
    return -1L;
  };
  auto expect_paragraph = [&](const std::string& sheet, const std::string& prefix, char c0,
                              char c1, double min_height) {
    SCOPED_TRACE(sheet + ": " + prefix);
    const long si = string_index(prefix);
    ASSERT_GE(si, 0) << "no such text";
    const std::string x = zip_entry(xlsx, sheet, dir.path());
    const std::size_t v = x.find("<v>" + std::to_string(si) + "</v>");
    ASSERT_NE(v, std::string::npos);
    const std::size_t c = x.rfind("<c r=\"", v);
    const std::string ref = x.substr(c + 6, x.find('"', c + 6) - c - 6);  // e.g. "A23"
    ASSERT_EQ(ref[0], c0) << ref;
    const std::string row = ref.substr(1);
    EXPECT_NE(x.find("<mergeCell ref=\"" + ref + ":" + c1 + row + "\"/>"), std::string::npos)
        << "not merged " << ref << ":" << c1 << row;
    const std::size_t r = x.find("<row r=\"" + row + "\"");
    ASSERT_NE(r, std::string::npos);
    const std::size_t ht = x.find("ht=\"", r);
    ASSERT_LT(ht, x.find('>', r)) << "no height of its own";
    EXPECT_GE(std::stod(x.substr(ht + 4)), min_height);
  };
  // 920 characters over 196 (Summary) and 84 (D:I of 14) units: 5 and 10 lines of 15 pt at least.
  expect_paragraph("xl/worksheets/sheet1.xml", "Screen A: class", 'A', 'J', 5 * 15.0);
  expect_paragraph("xl/worksheets/sheet2.xml", words.substr(0, 30), 'D', 'I', 10 * 15.0);
}

// The profile is drawn at one scale: metres per pixel of the plot area (taken as 85 % of the
// chart's width and 68 % of its height) equal across and up, up to the round numbers the axis
// bounds are put on (a half-decade step: at most a factor 1.5 either way), and the axes hold
// the whole section. (The vertical axis used to fill the height: a 32° slope looked 15°.) The
// chart is as tall as the section needs for its width to set the scale: the horizontal axis
// ends at the first tick beyond the section. (A chart of fixed shape drew Vaujany's 486 m on
// 0–750 m.)
TEST(XlsxReport, TheProfileIsDrawnAtOneScale) {
  PIERRE_NEED_PROGRAM("unzip");
  TempDir dir;
  auto f = make_fixture(50, 5);
  const auto tpl = io::load_report_template(kTemplate);
  const fs::path xlsx = dir.path() / "report.xlsx";
  io::write_report(xlsx, f->data, tpl);
  std::string chart, chart_name;
  for (const auto& n : zip_list(xlsx, dir.path()))
    if (n.rfind("xl/charts/chart", 0) == 0) {
      const std::string x = zip_entry(xlsx, n, dir.path());
      if (x.find(tpl.get("chart.profile", "title")) != std::string::npos) {
        chart = x;
        chart_name = n.substr(std::string("xl/charts/").size());
      }
    }
  ASSERT_FALSE(chart.empty());
  // The chart's height as Excel places it: its anchor, from a row and offset to another, on rows
  // of 20 px (the Profile sheet sets none of its own there), 9525 EMU a pixel.
  std::string drawing;
  for (const auto& n : zip_list(xlsx, dir.path()))
    if (n.rfind("xl/drawings/_rels/", 0) == 0 &&
        zip_entry(xlsx, n, dir.path()).find("../charts/" + chart_name + "\"") != std::string::npos)
      drawing = zip_entry(xlsx, "xl/drawings/" + n.substr(18, n.size() - 18 - 5), dir.path());
  ASSERT_EQ(drawing.find("<xdr:graphicFrame", drawing.find("<xdr:graphicFrame") + 1), std::string::npos)
      << "one chart on the Profile sheet";
  auto anchor = [&](const char* end, const char* what) {
    const std::size_t at = drawing.find(std::string("<xdr:") + end + ">");
    const std::size_t k = drawing.find(std::string("<xdr:") + what + ">", at) + std::string(what).size() + 6;
    return std::stod(drawing.substr(k, drawing.find('<', k) - k));
  };
  const double chart_px = (anchor("to", "row") - anchor("from", "row")) * 20 +
                          (anchor("to", "rowOff") - anchor("from", "rowOff")) / 9525;
  auto bound = [&](const char* pos, const char* which) {  // pos "b" (x) or "l" (z)
    const std::size_t ax = chart.find(std::string("<c:axPos val=\"") + pos + "\"/>");
    const std::size_t start = chart.rfind("<c:valAx>", ax);
    const std::size_t k = chart.find(std::string("<c:") + which + " val=\"", start) + std::string(which).size() + 9;
    return std::stod(chart.substr(k, chart.find('"', k) - k));
  };
  const double x0 = bound("b", "min"), x1 = bound("b", "max"), z0 = bound("l", "min"), z1 = bound("l", "max");
  const auto& prof = f->scenario.scenario.profile;
  for (const auto& v : prof.vertices()) {
    EXPECT_GE(v.x, x0);
    EXPECT_LE(v.x, x1);
    EXPECT_GE(v.z, z0);
    EXPECT_LE(v.z, z1);
  }
  const double across = (x1 - x0) / (1.6 * tpl.chart_width * 0.85), up = (z1 - z0) / (chart_px * 0.68);
  EXPECT_LT(std::max(across, up) / std::min(across, up), 1.5) << across << " m/px across, " << up << " m/px up";
  const auto ext = std::minmax_element(prof.vertices().begin(), prof.vertices().end(),
                                       [](const auto& a, const auto& b) { return a.x < b.x; });
  const double xmin = ext.first->x, xmax = ext.second->x;
  const double tick = std::pow(10.0, std::floor(std::log10(xmax - xmin))) / 2;  // 50 m on 200 m
  EXPECT_DOUBLE_EQ(x1, std::ceil(xmax / tick) * tick) << "a chart " << chart_px << " px high";
  EXPECT_DOUBLE_EQ(x0, std::floor(xmin / tick) * tick);
  // The barriers and the observation lines are named on the chart, at their tops: the label of
  // point 1 (a line's top, after its foot) carries the name, the foot's is deleted.
  for (const auto& b : f->data.barriers)
    EXPECT_NE(chart.find("<a:t>" + b.spec.name + "</a:t>"), std::string::npos) << b.spec.name;
  for (const auto& l : f->scenario.scenario.lines)
    EXPECT_NE(chart.find("<a:t>" + l.name + "</a:t>"), std::string::npos) << l.name;
  EXPECT_NE(chart.find("<c:dLbl><c:idx val=\"0\"/><c:delete val=\"1\"/></c:dLbl><c:dLbl><c:idx val=\"1\"/>"),
            std::string::npos);
}

TEST(XlsxReport, BarrierSheetNamesAreValidAndDistinct) {
  PIERRE_NEED_PROGRAM("unzip");
  TempDir dir;
  auto f = make_fixture(50, 5);
  const auto tpl = io::load_report_template(kTemplate);
  auto b = f->data.barriers[0];
  b.spec.name = "summary";  // collides with a fixed sheet (names are case-insensitive)
  f->data.barriers.push_back(b);
  b.spec.name = "A very long barrier name: with [forbidden] characters/and more";
  f->data.barriers.push_back(b);
  f->data.barriers.push_back(b);
  b.spec.name = "History";  // reserved by Excel
  f->data.barriers.push_back(b);
  // Names a formula reads as a cell (libxlsxwriter leaves them unquoted: "B1!$A$1").
  for (const char* name : {"B1", "r1c1", "2024", "C"}) {
    b.spec.name = name;
    f->data.barriers.push_back(b);
  }
  // The sheet's heading "Barrier {name}" would repeat the word: "Barrier barrier North".
  b.spec.name = "barrier North";
  f->data.barriers.push_back(b);
  const fs::path xlsx = dir.path() / "report.xlsx";
  io::write_report(xlsx, f->data, tpl);
  const std::string wb = zip_entry(xlsx, "xl/workbook.xml", dir.path());
  const std::string strings = zip_entry(xlsx, "xl/sharedStrings.xml", dir.path());
  EXPECT_EQ(strings.find("Barrier barrier North"), std::string::npos);
  EXPECT_NE(strings.find(">Barrier North<"), std::string::npos);  // the template's word and case
  EXPECT_NE(strings.find(">Barrier C<"), std::string::npos);  // a name without the word keeps it
  EXPECT_NE(wb.find("<sheet name=\"summary (2)\""), std::string::npos) << wb;
  EXPECT_NE(wb.find("<sheet name=\"History (2)\""), std::string::npos) << wb;
  EXPECT_NE(wb.find("<sheet name=\"A very long barrier name_ with\""), std::string::npos) << wb;
  EXPECT_NE(wb.find("<sheet name=\"A very long barrier name_ w (2)\""), std::string::npos) << wb;
  for (const char* name : {"Barrier B1", "Barrier r1c1", "Barrier 2024", "Barrier C"})
    EXPECT_NE(wb.find("<sheet name=\"" + std::string(name) + "\""), std::string::npos) << name;
  // Every sheet a formula names (chart ranges, print areas) is one no formula reads as a cell.
  std::size_t charts = 0;
  std::vector<std::string> formulas;
  for (const auto& n : zip_list(xlsx, dir.path()))
    if (n.rfind("xl/charts/chart", 0) == 0) {
      ++charts;
      const std::string x = zip_entry(xlsx, n, dir.path());
      for (std::size_t k = x.find("<c:f>"); k != std::string::npos; k = x.find("<c:f>", k + 1))
        formulas.push_back(x.substr(k + 5, x.find("</c:f>", k) - k - 5));
    }
  for (std::size_t k = wb.find("<definedName"); k != std::string::npos; k = wb.find("<definedName", k + 1)) {
    const std::size_t a = wb.find('>', k) + 1;
    formulas.push_back(wb.substr(a, wb.find("</definedName>", a) - a));
  }
  ASSERT_FALSE(formulas.empty());
  for (const auto& f : formulas) {
    const std::string sheet = f.substr(0, f.find('!'));
    if (sheet.front() == '\'') continue;  // quoted
    EXPECT_FALSE(io::sheet_name_reads_as_reference(sheet)) << f;
  }
  EXPECT_EQ(charts, 10u * 6u + 1u);
}

}  // namespace
