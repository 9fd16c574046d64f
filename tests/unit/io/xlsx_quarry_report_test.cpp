// report.xlsx with a quarry design (design-checks.md §2), opened for real: a QuarryDesign from
// design::design_quarry on hand-made sections (a lone face with observed values, work areas and
// a bench; two faces pooled by a group), written with their profiles and a few paths, then
// LibreOffice (headless) exports every sheet to CSV and the workbook to PDF. The tests check
// the quarry sheets (one per row, named by the template, in the template's order), key cells
// against the design's numbers (RD and ID P95 in m and / H, the governing distances), the
// Summary's quarry table, average rows and every quarry check line, that numbers are numbers,
// and the charts in the zip (scatter series with x and y values).
//
// Without `soffice` the tests that need it are skipped with a message.
#include <gtest/gtest.h>

#include <boost/math/special_functions/erf.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "pierre/design/quarry_zones.hpp"
#include "pierre/io/report_template.hpp"
#include "pierre/io/xlsx_report.hpp"
#include "support/builders.hpp"
#include "support/workbook_reader.hpp"
#include "test_files.hpp"
#include "support/seeded_samples.hpp"

namespace {

namespace fs = std::filesystem;
using namespace pierre;
using namespace pierre::test;

const fs::path kTemplate = PIERRE_SOURCE_DIR "/templates/report.toml";
constexpr double kInf = std::numeric_limits<double>::infinity();

// ---- reading the sheets (the rest is in support/workbook_reader.hpp) -------------------

// The first row with `a` in column 0 and `b` in column 1.
std::optional<std::size_t> find_row2(const Sheet& s, const std::string& a, const std::string& b,
                                     std::size_t from = 0) {
  for (std::size_t r = from; r < s.size(); ++r)
    if (s[r].size() > 1 && s[r][0].text == a && s[r][1].text == b) return r;
  return std::nullopt;
}

// A number as a text in the report writes it: %.4g.
std::string format_g(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4g", v);
  return b;
}

void expect_number(const Sheet& s, std::size_t r, std::size_t c, double want) {
  const auto v = number(s, r, c);
  ASSERT_TRUE(v) << "row " << r << " col " << c << ": " << dump(s, r);
  EXPECT_NEAR(*v, want, 1e-9 * std::max(1.0, std::abs(want))) << dump(s, r);
}

// ---- the quarry ------------------------------------------------------------------------

// A quarry face of height H at x = 10 (a 4 m bench halfway up) over a 150 m floor.
geometry::Profile face(double H) {
  return test::make_profile({{0, H}, {10, H}, {12, H / 2}, {16, H / 2}, {18, 0}, {168, 0}});
}

// Log-normal runouts / H (median e^-0.9 ≈ 0.41, σ 0.5) by inversion of a seeded sequence, with
// a few zeros (stopped on the bench) and blocks beyond the profile.
std::vector<double> runouts(std::size_t n, double H, std::uint64_t seed) {
  std::mt19937_64 g(seed);
  std::vector<double> v;
  for (std::size_t i = 0; i < n; ++i) {
    const double u = test::seeded_uniform(g);
    v.push_back(H * std::exp(-0.9 - 0.5 * std::sqrt(2.0) * boost::math::erfc_inv(2 * u)));
  }
  for (std::size_t i = 0; i < n / 40; ++i) v[i * 37 % n] = 0;
  v[5] = kInf;
  v[17] = kInf;
  return v;
}

// Distances from runouts (m; +inf: left the profile), the first impact at a fifth of each.
design::QuarryDistances distances(const std::vector<double>& rd, const design::QuarryGeometry& g) {
  design::QuarryDistances d;
  std::uint64_t k = 0;
  for (double r : rd) {
    sim::TrajectorySummary t;
    t.trajectory = k++;
    t.start = {10.5, g.crest.z + 0.5};
    t.duration = 4;
    if (std::isinf(r)) {
      t.stop = {g.toe.x + g.floor_length, 0};
      t.stop_reason = sim::StopReason::boundary;
    } else if (r == 0) {
      t.stop = {14, g.crest.z / 2};
      t.stop_reason = sim::StopReason::energy;
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

struct Fixture {
  std::vector<std::string> names;
  std::vector<geometry::Profile> profiles;
  io::ReportData data;
};

std::unique_ptr<Fixture> make_fixture() {
  auto f = std::make_unique<Fixture>();
  f->names = {"Face A", "East 1", "East 2"};
  const double heights[] = {20, 15, 15};
  design::QuarryRuleSet rules;
  rules.name = "quarry-thesis-2015";
  rules.title = "Mitchell (2015) chapter 6";
  rules.source = "Mitchell, PhD thesis, 2015, §6.3";
  std::vector<design::QuarrySectionInput> in;
  for (std::size_t i = 0; i < 3; ++i) {
    f->profiles.push_back(face(heights[i]));
    design::QuarrySectionInput s;
    s.spec.name = f->names[i];
    s.spec.rules = rules.name;
    s.rules = rules;
    s.geometry = *design::quarry_geometry(f->profiles.back(), {});
    s.distances = distances(runouts(400, heights[i], 11 + i), s.geometry);
    if (i > 0) s.spec.group = "East";
    in.push_back(std::move(s));
  }
  auto& a = in[0];
  a.spec.work_areas = {{"crusher", 60}, {"office", 8}};
  a.spec.bench_width = 12;
  a.spec.observed_source = "field survey 2014 (hand-made for the test)";
  for (int i = 0; i < 25; ++i) {
    a.observed.rd.metres.push_back(20 * std::exp(-1.0 + 0.06 * i));
    a.observed.rd.heights.push_back(20);
    a.observed.id.metres.push_back(4 * std::exp(-1.0 + 0.05 * i));
    a.observed.id.heights.push_back(20);
  }
  auto out = design::design_quarry(in, 7);
  if (!out.design) throw std::runtime_error(out.error);

  auto& d = f->data;
  d.pierre_version = "0.1.0-test";
  d.date = "2024-05-17";
  d.seed = 99;
  d.throws = 400;
  d.rule_sets = {"quarry-thesis-2015 — Mitchell (2015) chapter 6"};
  d.quarry = std::move(*out.design);
  // The caller passes only some of the quarry's check lines: Summary must show them all.
  d.checks.assign(d.quarry->checks.begin(), d.quarry->checks.begin() + 2);
  for (std::size_t i = 0; i < 3; ++i) {
    io::ReportData::QuarrySectionView v;
    v.name = f->names[i];
    v.profile = &f->profiles[i];
    v.seed = 20150601 + i;
    for (int p = 0; p < 4; ++p) {
      std::vector<geometry::Vec2> path;
      const double H = heights[i], reach = 10.0 + 12 * p;
      for (int k = 0; k <= 30; ++k) {
        const double x = 10.5 + (reach + 8) * k / 30.0;
        const double t = (x - 10.5) / (reach + 8);
        path.push_back({x, std::max(0.0, H + 0.5 - (H + 0.5) * t * t) + 1.5 * std::sin(6 * t) * (1 - t)});
      }
      v.paths.push_back(path);
    }
    d.quarry_sections.push_back(v);
  }
  // Three trajectories of a section: one that reached the floor, one that stayed on the bench,
  // one that left the section at its runout end (x 168).
  for (int k = 0; k < 3; ++k) {
    sim::TrajectorySummary t;
    t.trajectory = static_cast<std::uint64_t>(k);
    t.start = {10.5, 20.5};
    t.has_first_impact = true;
    t.first_impact = {11.0, 19.0};
    t.has_floor_contact = k != 1;
    t.floor_contact = {26.25, 0};
    t.stop = k == 0 ? geometry::Vec2{40, 0} : k == 1 ? geometry::Vec2{14, 10} : geometry::Vec2{168, 0};
    t.stop_reason = k == 2 ? sim::StopReason::boundary : sim::StopReason::energy;
    t.max_jump_height = 3.5 + k;
    d.trajectories.push_back(t);
    d.trajectory_sections.push_back(0);
  }
  d.total_trajectories = 3;
  d.statistics.runout = {1200, 14.5, 26.0, 31.0, 44.0};  // m from the release points, pooled
  return f;
}

const std::vector<std::string> kOrder = {"Summary", "Quarry Face A", "Quarry East",  "Profile",
                                         "Inputs",  "Blocks",        "Trajectories", "Crossings"};

TEST(XlsxQuarryReport, SheetsAndChartsInTheWorkbook) {
  PIERRE_NEED_PROGRAM("unzip");
  TempDir dir;
  const auto f = make_fixture();
  const auto tpl = io::load_report_template(kTemplate);
  const fs::path xlsx = dir.path() / "report.xlsx";
  io::write_report(xlsx, f->data, tpl);

  std::vector<std::string> charts;
  for (const auto& n : zip_list(xlsx, dir.path()))
    if (n.rfind("xl/charts/chart", 0) == 0) charts.push_back(n);
  // Face A: its section + RD and ID histograms and CDFs (5); East: 2 sections + 4. No
  // scenario profile here.
  EXPECT_EQ(charts.size(), 11u);
  std::size_t with_markers = 0, with_bench = 0;
  const std::string bench = "<c:v>" + tpl.get("headings.quarry_chart", "bench") + "</c:v>";
  for (const auto& c : charts) {
    SCOPED_TRACE(c);
    const std::string xml = zip_entry(xlsx, c, dir.path());
    EXPECT_NE(xml.find("<c:scatterChart>"), std::string::npos);
    const auto series = occurrences(xml, "<c:ser>");
    EXPECT_GE(series, 2u);
    EXPECT_EQ(occurrences(xml, "<c:xVal>"), series);
    EXPECT_EQ(occurrences(xml, "<c:yVal>"), series);
    if (xml.find("<c:symbol val=\"triangle\"/>") != std::string::npos) {
      ++with_markers;
      // Each named, so that two work areas are not two like triangles.
      EXPECT_NE(xml.find("<a:t>crusher</a:t>"), std::string::npos);
      EXPECT_NE(xml.find("<a:t>office</a:t>"), std::string::npos);
      // Face A plans a catch bench: its edge is drawn, dotted, where bench.retention counts.
      EXPECT_NE(xml.find(bench), std::string::npos);
      EXPECT_NE(xml.find("<a:prstDash val=\"sysDot\"/>"), std::string::npos);
    }
    with_bench += xml.find(bench) != std::string::npos;
  }
  EXPECT_EQ(with_markers, 1u);  // the work areas of Face A, as points
  EXPECT_EQ(with_bench, 1u);    // the East sections plan no bench

  const std::string wb = zip_entry(xlsx, "xl/workbook.xml", dir.path());
  std::vector<std::string> order;
  for (auto p = wb.find("<sheet name=\""); p != std::string::npos;
       p = wb.find("<sheet name=\"", p + 1)) {
    const auto b = p + 13;
    order.push_back(wb.substr(b, wb.find('"', b) - b));
  }
  EXPECT_EQ(order, kOrder);
}

// Every number between `open` and the next '<' after each occurrence of `open`.
std::vector<long> numbers_after(const std::string& xml, const std::string& open) {
  std::vector<long> out;
  for (auto p = xml.find(open); p != std::string::npos; p = xml.find(open, p + 1))
    out.push_back(std::stol(xml.substr(p + open.size())));
  return out;
}

// Printed, a quarry sheet's charts start on a new page, and a page holds what a lone section's
// does (its section, RD and ID): a group of two sections puts its RD and ID charts on a page of
// their own, instead of cutting the ID charts in two at the page's foot (seen on Pauliberg).
TEST(XlsxQuarryReport, PageBreaksFallBetweenChartsNotThroughThem) {
  PIERRE_NEED_PROGRAM("unzip");
  TempDir dir;
  const auto f = make_fixture();
  const fs::path xlsx = dir.path() / "report.xlsx";
  io::write_report(xlsx, f->data, io::load_report_template(kTemplate));
  // Sheets 2 and 3 are "Quarry Face A" and "Quarry East" (kOrder), drawings 1 and 2 theirs.
  for (int k : {1, 2}) {
    SCOPED_TRACE(kOrder[static_cast<std::size_t>(k)]);
    const auto breaks = numbers_after(
        zip_entry(xlsx, "xl/worksheets/sheet" + std::to_string(k + 1) + ".xml", dir.path()),
        "<brk id=\"");
    const std::string drawing =
        zip_entry(xlsx, "xl/drawings/drawing" + std::to_string(k) + ".xml", dir.path());
    const auto from = numbers_after(drawing, "<xdr:from><xdr:col>0</xdr:col><xdr:colOff>38100</xdr:colOff><xdr:row>");
    const auto all_from = numbers_after(drawing, "</xdr:colOff><xdr:row>");  // from and to rows
    ASSERT_FALSE(from.empty());
    const std::size_t sections = k == 1 ? 1 : 2;
    ASSERT_EQ(from.size(), sections + 2);  // the sections, then RD and ID (histogram | CDF)
    if (k == 1) {
      EXPECT_EQ(breaks, (std::vector<long>{from[0]}));
    } else {
      EXPECT_EQ(breaks, (std::vector<long>{from[0], from[sections]}));
    }
    // No chart spans a break: each anchor's rows [from, to] hold no break but at its top.
    for (std::size_t a = 0; a + 1 < all_from.size(); a += 2)
      for (long b : breaks) EXPECT_FALSE(all_from[a] < b && b <= all_from[a + 1]) << b;
  }
}

TEST(XlsxQuarryReport, LibreOfficeReadsTheQuarrySheets) {
  PIERRE_NEED_PROGRAM("soffice");
  TempDir dir;
  const auto f = make_fixture();
  // Three fit lines that WARN: Face A's RD fit rejected (p below 0.05), East's ID fit from 5
  // values, and East's RD fit from enough values at a good p (a doubted input's WARN): the
  // notes under the exceedance tables say the first two, and nothing of the third.
  {
    auto& dq = *f->data.quarry;
    auto warn = [&](const std::string& subject, const char* id) {
      for (auto& l : dq.checks)
        if (l.subject == subject && l.id == id) l.status = design::CheckStatus::warn;
    };
    if (dq.rows.size() == 2 && dq.rows[0].rd.ks && dq.rows[1].id.ks && dq.rows[1].rd.ks) {
      dq.rows[0].rd.ks->p_value = 0.01;
      dq.rows[1].id.ks->p_value = 0.8;
      dq.rows[1].id.ks->observed = 5;
      dq.rows[1].rd.ks->p_value = 0.7;
      dq.rows[1].rd.ks->observed = std::max<std::size_t>(dq.rows[1].rd.ks->observed, 40);
      warn(dq.rows[0].name, "fit.RD");
      warn(dq.rows[1].name, "fit.ID");
      warn(dq.rows[1].name, "fit.RD");
    }
  }
  const auto& q = *f->data.quarry;
  const auto tpl = io::load_report_template(kTemplate);
  const fs::path xlsx = dir.path() / "report.xlsx";
  io::write_report(xlsx, f->data, tpl);

  auto [r, sheets] = export_sheets(xlsx, dir.path());
  ASSERT_EQ(r.status, 0) << r.output;
  for (const auto& s : kOrder) EXPECT_TRUE(sheets.count(s)) << "no sheet " << s << "\n" << r.output;
  ASSERT_TRUE(sheets.count("Quarry Face A") && sheets.count("Quarry East") && sheets.count("Summary"));
  // The Summary's basis says how the quarry zones are set, and (no barriers) not how barriers are.
  std::size_t quarry_basis = 0, barrier_basis = 0;
  for (const auto& row : sheets["Summary"])
    if (!row.empty()) {
      quarry_basis += row[0].text.rfind("Quarry danger zones: the first-impact distance ID", 0) == 0;
      barrier_basis += row[0].text.rfind("Barriers: each is designed", 0) == 0;
    }
  EXPECT_EQ(quarry_basis, 1u);
  EXPECT_EQ(barrier_basis, 0u);

  ASSERT_EQ(q.rows.size(), 2u);
  ASSERT_EQ(q.rows[0].name, "Face A");
  ASSERT_EQ(q.rows[1].name, "East");
  std::size_t notes_seen = 0;  // doubtful-fit notes: the fixture has some, so the check bites
  for (std::size_t ri = 0; ri < 2; ++ri) {
    const auto& row = q.rows[ri];
    SCOPED_TRACE(row.name);
    const Sheet& s = sheets[ri == 0 ? "Quarry Face A" : "Quarry East"];
    ASSERT_FALSE(s.empty());
    EXPECT_EQ(cell(s, 0, 0)->text, "Quarry danger zones: " + row.name);
    // Tables 6.2 / 6.3: RD and ID, calculated, in m (P50 col 5 … max col 8) and / H (9 … 12).
    const auto rd = find_row2(s, "RD, runout distance from the toe", "Calculated");
    ASSERT_TRUE(rd);
    expect_number(s, *rd, 2, static_cast<double>(row.rd.count));
    expect_number(s, *rd, 3, static_cast<double>(row.rd.zeros));
    expect_number(s, *rd, 4, static_cast<double>(row.rd.censored));
    expect_number(s, *rd, 5, row.rd.p50);
    expect_number(s, *rd, 6, row.rd.p95);
    expect_number(s, *rd, 7, row.rd.p99);
    expect_number(s, *rd, 9, row.rd.p50_h);
    expect_number(s, *rd, 10, row.rd.p95_h);
    // The maximum is beyond the profile (two blocks left it): said in words.
    EXPECT_EQ(cell(s, *rd, 8)->text, "beyond the profile");
    const auto id = find_row2(s, "ID, first-impact distance from the toe", "Calculated");
    ASSERT_TRUE(id);
    expect_number(s, *id, 6, row.id.p95);
    expect_number(s, *id, 10, row.id.p95_h);
    expect_number(s, *id, 8, row.id.max);
    // A group's sections on their own, named in the source column (per section and pooled).
    for (std::size_t k : row.sections) {
      const auto& sec = q.sections[k];
      const auto own = find_row2(s, "RD, runout distance from the toe", sec.spec.name);
      if (row.sections.size() == 1) {
        EXPECT_FALSE(own) << sec.spec.name;  // a lone section is its row
        continue;
      }
      ASSERT_TRUE(own) << sec.spec.name;
      expect_number(s, *own, 2, static_cast<double>(sec.rd.count));
      expect_number(s, *own, 6, sec.rd.p95);
      const auto own_id = find_row2(s, "ID, first-impact distance from the toe", sec.spec.name);
      ASSERT_TRUE(own_id) << sec.spec.name;
      expect_number(s, *own_id, 6, sec.id.p95);
    }
    // A doubtful log-normal fit (its fit.* line WARNs) is said under the exceedance table, with
    // why: a p-value below the rule set's, or too few values for one to say anything.
    for (const auto& [what, id, st] : {std::tuple{"RD", "fit.RD", &row.rd}, std::tuple{"ID", "fit.ID", &row.id}}) {
      bool warns = false;
      for (const auto& l : q.checks) warns |= l.subject == row.name && l.id == id && l.status == design::CheckStatus::warn;
      if (!st->ks) continue;
      char p[32];
      std::snprintf(p, sizeof p, "%.3g", st->ks->p_value);
      const bool rejected = st->ks->p_value < 0.05, few = st->ks->observed < 30;  // the thesis rules
      const std::string why = rejected ? std::string("KS p = ") + p + " < 0.05"
                                       : "from only " + std::to_string(st->ks->observed) +
                                             " values above zero, where KS p = " + p + " says little";
      const std::string note = std::string(what) + ": the log-normal fit is doubtful (" + why +
                               "): read the empirical distances, not the fitted ones.";
      EXPECT_EQ(find_row(s, 0, note).has_value(), warns && (rejected || few)) << note;
      notes_seen += find_row(s, 0, note).has_value();
    }
    // The governing distances, / H and in m.
    // The row's time of travel, from its trajectories (every one takes 4 s here).
    const auto travel = find_row(s, 0, tpl.get("labels", "travel_time"));
    ASSERT_TRUE(travel);
    EXPECT_EQ(row.duration.count, row.thrown);
    EXPECT_EQ(cell(s, *travel, 1)->text,
              "P50 4, P95 4, max 4 over " + std::to_string(row.thrown) + " trajectories");
    const auto gov = find_row(s, 0, "RD_gov (danger zone)");
    ASSERT_TRUE(gov);
    expect_number(s, *gov, 1, row.rd_gov.value_h);
    expect_number(s, *gov, 2, row.rd_gov.value_h * row.height);
    EXPECT_EQ(cell(s, *gov, 3)->text, row.rd_gov.how);
    // The fits: p0 and the log-normal's parameters.
    const auto fits = find_row(s, 0, "Distance", *find_row(s, 0, "Log-normal fits of the distances / H (zeros as a point mass) and the observed"));
    ASSERT_TRUE(fits);
    ASSERT_TRUE(row.rd.fit);
    expect_number(s, *fits + 1, 2, row.rd.fit->positive.mu);
    expect_number(s, *fits + 1, 3, row.rd.fit->positive.sigma);
    // Geometry of each section: toe and H.
    for (std::size_t k : row.sections) {
      const auto& sec = q.sections[k];
      const auto g = find_row(s, 0, sec.spec.name, *find_row(s, 0, "Section"));
      ASSERT_TRUE(g) << sec.spec.name;
      expect_number(s, *g, 4, sec.geometry.toe.x);
      expect_number(s, *g, 7, sec.geometry.height);
      EXPECT_EQ(cell(s, *g, 6)->text, "found");
      for (const auto& v : f->data.quarry_sections)  // the section's own seed: its run repeats
        if (v.name == sec.spec.name) expect_number(s, *g, 12, static_cast<double>(v.seed));
    }
  }
  // Face A: observed beside calculated, the zones and the work-area checks.
  {
    const Sheet& s = sheets["Quarry Face A"];
    const auto& row = q.rows[0];
    ASSERT_TRUE(row.observed_rd);
    const auto obs = find_row2(s, "RD, runout distance from the toe", "Observed");
    ASSERT_TRUE(obs);
    expect_number(s, *obs, 2, 25);
    expect_number(s, *obs, 6, row.observed_rd->p95);
    expect_number(s, *obs, 10, row.observed_rd->p95_h);
    const auto zones = find_row(s, 0, "Face A", *find_row(s, 0, "Zones from the toe, catch bench and work areas"));
    ASSERT_TRUE(zones);
    expect_number(s, *zones, 1, q.sections[0].danger_zone);
    expect_number(s, *zones, 2, q.sections[0].first_impact_zone);
    expect_number(s, *zones, 3, 12);
    expect_number(s, *zones, 4, *q.sections[0].bench_retention);
    expect_number(s, *zones, 5, *q.sections[0].ritchie_width);
    const auto office = find_row(s, 0, "zone.office");
    ASSERT_TRUE(office);
    EXPECT_EQ(cell(s, *office, 4)->text, "FAIL");
    expect_number(s, *office, 1, 8);
  }
  // Inputs: a row per section with its inputs as used (rule set, crest and toe given or found,
  // H, bench width, work areas with their distances, the probabilities of exceedance asked for);
  // before, they were only in the echoed scenario text.
  {
    const Sheet& s = sheets["Inputs"];
    const auto title = find_row(s, 0, tpl.get("titles", "quarry_inputs"));
    ASSERT_TRUE(title) << "no table of the quarry sections' inputs";
    for (const auto& sec : q.sections) {
      SCOPED_TRACE(sec.spec.name);
      const auto k = find_row(s, 0, sec.spec.name, *title);
      ASSERT_TRUE(k);
      EXPECT_EQ(cell(s, *k, 1)->text, sec.spec.group.empty() ? tpl.get("labels", "none") : sec.spec.group);
      EXPECT_EQ(cell(s, *k, 2)->text, sec.spec.rules);
      expect_number(s, *k, 3, sec.geometry.crest.x);
      EXPECT_EQ(cell(s, *k, 4)->text, design::to_string(sec.geometry.crest_origin));
      expect_number(s, *k, 5, sec.geometry.toe.x);
      EXPECT_EQ(cell(s, *k, 6)->text, design::to_string(sec.geometry.toe_origin));
      expect_number(s, *k, 7, sec.geometry.height);
      EXPECT_EQ(cell(s, *k, 8)->text, design::to_string(sec.geometry.height_origin));
      if (sec.spec.bench_width)
        expect_number(s, *k, 9, *sec.spec.bench_width);
      const std::string areas = cell(s, *k, 10)->text;
      for (const auto& w : sec.spec.work_areas) {
        EXPECT_NE(areas.find(w.name), std::string::npos) << areas;
        EXPECT_NE(areas.find(format_g(w.distance) + " m"), std::string::npos) << areas;
      }
      const std::string asked = cell(s, *k, 11)->text;
      ASSERT_FALSE(sec.spec.exceedance.empty());
      for (double p : sec.spec.exceedance)
        EXPECT_NE(asked.find(format_g(100 * p) + " %"), std::string::npos) << asked;
    }
    ASSERT_FALSE(q.sections[0].spec.work_areas.empty());  // the test needs some
  }
  // Profile: a quarry's sections are drawn on their rows' sheets; the title says what the sheet
  // holds, not a slope scenario's "observation lines and barriers" that a quarry has none of.
  {
    const Sheet& s = sheets["Profile"];
    ASSERT_FALSE(s.empty());
    const std::string title = cell(s, 0, 0)->text;
    EXPECT_FALSE(title.empty());
    EXPECT_EQ(title.find("observation lines"), std::string::npos) << title;
    EXPECT_EQ(title.find("barriers"), std::string::npos) << title;
  }
  // Trajectories: the floor contact follows the first impact, as in trajectories.csv, then ID
  // and RD from the toe; the contact and ID are empty for a block that never reached the floor.
  // Face A's toe is the foot of its lower face, (18, 0): ID = 26.25 − 18, RD = 40 − 18, and the
  // block held on the bench (stopped at x 14) has RD 0, the one that left has none to give.
  {
    ASSERT_EQ(q.sections[0].geometry.toe.x, 18.0);
    const Sheet& s = sheets["Trajectories"];
    const auto head = find_row(s, 0, "Quarry section");
    ASSERT_TRUE(head) << dump(s, 2);
    EXPECT_EQ(cell(s, *head, 15)->text, "First impact z (m)");
    EXPECT_EQ(cell(s, *head, 16)->text, "Floor contact x (m)");
    EXPECT_EQ(cell(s, *head, 17)->text, "Floor contact z (m)");
    EXPECT_EQ(cell(s, *head, 18)->text, "ID from the toe (m)");
    EXPECT_EQ(cell(s, *head, 19)->text, "RD from the toe (m)");
    EXPECT_EQ(cell(s, *head, 20)->text, "Max jump height (m)");
    ASSERT_EQ(s.size(), *head + 4);
    expect_number(s, *head + 1, 16, 26.25);
    expect_number(s, *head + 1, 17, 0.0);
    expect_number(s, *head + 1, 18, 8.25);
    expect_number(s, *head + 1, 19, 22.0);
    expect_number(s, *head + 1, 20, 3.5);
    for (int c : {16, 18}) {
      const auto* empty = cell(s, *head + 2, c);
      EXPECT_TRUE(!empty || empty->text.empty()) << dump(s, *head + 2);
    }
    expect_number(s, *head + 2, 19, 0.0);
    expect_number(s, *head + 2, 20, 4.5);
    EXPECT_EQ(cell(s, *head + 3, 19)->text, "beyond the profile") << dump(s, *head + 3);
  }
  // Crossings: a quarry scenario has no observation lines, and the sheet says why it is empty
  // (it said "All 0 rows").
  {
    const Sheet& s = sheets["Crossings"];
    ASSERT_GE(s.size(), 2u);
    EXPECT_EQ(s[1][0].text.rfind("No rows: the CSV file crossings.csv holds none", 0), 0u) << s[1][0].text;
    // and has no headings over nothing (they printed as an empty table)
    for (const auto& row : s)
      for (const auto& c : row) EXPECT_NE(c.text, "Trajectory");
  }
  // Summary: Tables 6.2/6.3's rows, the average rows and every quarry check line.
  {
    const Sheet& s = sheets["Summary"];
    for (std::size_t ri = 0; ri < 2; ++ri) {
      const auto& row = q.rows[ri];
      const auto line = find_row2(s, row.name, "Calculated");
      ASSERT_TRUE(line) << row.name;
      expect_number(s, *line, 2, row.height);
      expect_number(s, *line, 4, row.rd_gov.value_h * row.height);
      expect_number(s, *line, 7, row.rd.p95_h);
      expect_number(s, *line, 10, row.id.p95_h);
    }
    const auto obs = find_row2(s, "Face A", "Observed");
    ASSERT_TRUE(obs);
    expect_number(s, *obs, 7, q.rows[0].observed_rd->p95_h);
    const auto avg = find_row2(s, "Average (normalized by H)", "Calculated");
    ASSERT_TRUE(avg);
    expect_number(s, *avg, 6, q.average.rd50_h);
    expect_number(s, *avg, 7, q.average.rd95_h);
    expect_number(s, *avg, 11, q.average.idmax_h);
    const auto avg_obs = find_row2(s, "Average (normalized by H)", "Observed");
    ASSERT_TRUE(avg_obs);
    expect_number(s, *avg_obs, 7, q.average.obs_rd95_h);
    // The average rows are means of the rows' ratios: no number thrown of their own (column 3
    // blank), and the line under them says so, naming how many rows were averaged.
    for (std::size_t k : {*avg, *avg_obs}) {
      const Field* thrown = cell(s, k, 3);
      EXPECT_TRUE(!thrown || thrown->text.empty()) << dump(s, k);
    }
    const std::size_t note_row = std::max(*avg, *avg_obs) + 1;
    const Field* note = cell(s, note_row, 0);
    ASSERT_TRUE(note && !note->text.empty()) << dump(s, note_row);
    EXPECT_NE(note->text.find(std::to_string(q.average.rows)), std::string::npos) << note->text;
    // Every section pooled (thesis Fig 6.5): all blocks, each distance over its own H; no H
    // and no zone of its own, and the note under it says why.
    const auto all = find_row2(s, tpl.get("labels", "quarry_all"), "Calculated");
    ASSERT_TRUE(all);
    expect_number(s, *all, 3, static_cast<double>(q.rows[0].thrown + q.rows[1].thrown));
    expect_number(s, *all, 6, q.all_rd_statistics.p50_h);
    expect_number(s, *all, 7, q.all_rd_statistics.p95_h);
    expect_number(s, *all, 11, q.all_id_statistics.max_h);
    ASSERT_NE(q.all_rd_statistics.p95_h, q.rows[0].rd.p95_h);  // a pool, not a row
    for (int c : {2, 4, 5}) {
      const Field* blank = cell(s, *all, c);
      EXPECT_TRUE(!blank || blank->text.empty()) << dump(s, *all);
    }
    EXPECT_EQ(cell(s, *all + 1, 0)->text, tpl.get("labels", "quarry_all_note"));
    // The runouts from the release points, pooled over the sections, are said not to be the
    // zones (a client read their P95 as the danger zone).
    const auto p95 = find_row(s, 0, tpl.get("labels", "runout_p95"));
    ASSERT_TRUE(p95);
    expect_number(s, *p95, 2, 26.0);
    const auto pooled = find_row(s, 0, tpl.get("labels", "runout_max"));
    ASSERT_TRUE(pooled);
    EXPECT_EQ(cell(s, *pooled + 1, 0)->text.rfind("The runouts above are horizontal distances from "
                                                   "each block's release point, pooled over 3 "
                                                   "section(s): they are not the danger zones",
                                                   0),
              0u)
        << dump(s, *pooled + 1);
    const auto head = find_row(s, 0, "Subject");
    ASSERT_TRUE(head);
    for (const auto& l : q.checks) {
      bool found = false;
      for (std::size_t k = *head + 1; k < s.size() && !found; ++k)
        found = s[k].size() > 7 && s[k][0].text == l.subject && s[k][1].text == l.id &&
                s[k][7].text == design::to_string(l.status);
      EXPECT_TRUE(found) << l.subject << " " << l.id;
    }
  }
  EXPECT_EQ(notes_seen, 2u);

  // The PDF: every sheet printed (look at it: pdftoppm -png -r 50 report.pdf page).
  const Exec p = soffice("--convert-to pdf --outdir '" + dir.path().string() + "' '" +
                             xlsx.string() + "'",
                         dir.path());
  ASSERT_EQ(p.status, 0) << p.output;
  const fs::path pdf = dir.path() / "report.pdf";
  ASSERT_TRUE(fs::is_regular_file(pdf));
  EXPECT_GT(fs::file_size(pdf), 20000u);
  if (const char* keep = std::getenv("PIERRE_KEEP_REPORT"); keep && *keep) {
    fs::copy_file(pdf, fs::path(keep) / "quarry-report.pdf", fs::copy_options::overwrite_existing);
    fs::copy_file(xlsx, fs::path(keep) / "quarry-report.xlsx", fs::copy_options::overwrite_existing);
  }
}

}  // namespace
