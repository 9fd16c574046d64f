// The report template reader (templates/report.toml): the shipped template loads with every
// key the writer uses; each kind of mistake is an InputError naming the file, the line, the
// dotted field and what was found.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "pierre/io/report_template.hpp"
#include "test_files.hpp"

namespace {

using pierre::io::InputError;
using pierre::io::load_report_template;
using pierre::test::read_file;
using pierre::test::TempDir;

const std::filesystem::path kTemplate = PIERRE_SOURCE_DIR "/templates/report.toml";

// The shipped template with the first occurrence of `from` replaced by `to`.
std::string shipped_with(const std::string& from, const std::string& to) {
  std::string s = read_file(kTemplate);
  const auto p = s.find(from);
  EXPECT_NE(p, std::string::npos) << from;
  if (p != std::string::npos) s.replace(p, from.size(), to);
  return s;
}

// 1-based line of the first occurrence of `needle` in `s`.
long line_of(const std::string& s, const std::string& needle) {
  const auto p = s.find(needle);
  EXPECT_NE(p, std::string::npos) << needle;
  return 1 + static_cast<long>(std::count(s.begin(), s.begin() + static_cast<long>(p), '\n'));
}

TEST(ReportTemplate, ShippedTemplateHasEveryKey) {
  const auto t = load_report_template(kTemplate);
  for (const auto& [section, keys] : pierre::io::report_template_sections())
    for (const auto& k : keys) EXPECT_NO_THROW((void)t.get(section, k)) << section << "." << k;
  for (const auto& k : pierre::io::report_template_colours())
    EXPECT_NO_THROW((void)t.colour(k)) << k;
  EXPECT_EQ(t.get("sheets", "summary"), "Summary");
  EXPECT_EQ(t.get("headings.design", "mel_req"), "MEL_req (kJ)");
  EXPECT_EQ(t.colour("fail_fill"), 0xFFC7CEu);
  EXPECT_EQ(t.trajectory_rows, 10000u);
  EXPECT_EQ(t.order.size(), 8u);
  EXPECT_EQ(t.order.front(), "summary");
  EXPECT_THROW((void)t.get("sheets", "nope"), std::out_of_range);
}

struct Bad {
  std::string name, from, to;
  long line;           // 0: the line of `line_needle` in the edited template
  std::string line_needle;
  std::string field;
  std::string found;  // substring of found()
};

void PrintTo(const Bad& b, std::ostream* os) { *os << b.name; }

class ReportTemplateError : public ::testing::TestWithParam<Bad> {};

TEST_P(ReportTemplateError, NamesFileLineAndField) {
  const Bad& b = GetParam();
  TempDir dir;
  const std::string text = shipped_with(b.from, b.to);
  const auto file = dir.write("report.toml", text);
  try {
    (void)load_report_template(file);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    SCOPED_TRACE(e.what());
    EXPECT_EQ(e.file(), file);
    EXPECT_EQ(e.line(), b.line ? b.line : line_of(text, b.line_needle));
    EXPECT_EQ(e.field(), b.field);
    EXPECT_NE(e.found().find(b.found), std::string::npos) << e.found();
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, ReportTemplateError,
    ::testing::Values(
        Bad{"unknown_key", "mel_req = \"MEL_req (kJ)\"\nh_i", "mel_req = \"MEL_req (kJ)\"\nmell = 1\nh_i",
            0, "mell = 1", "headings.design.mell", "unknown key"},
        Bad{"bad_colour", "fail_fill = \"#FFC7CE\"", "fail_fill = \"red\"", 0, "fail_fill",
            "colours.fail_fill", "\"red\""},
        Bad{"bad_sheet_name", "profile = \"Profile\"", "profile = \"Pro[file]\"", 0,
            "profile = \"Pro[file]\"", "sheets.profile", "Pro[file]"},
        Bad{"sheet_name_a_cell", "profile = \"Profile\"", "profile = \"P1\"", 0,
            "profile = \"P1\"", "sheets.profile", "P1"},
        Bad{"order_twice", "\"crossings\"]", "\"summary\"]", 0, "order =", "sheets.order",
            "an array"},
        Bad{"order_unknown", "\"crossings\"]", "\"crossing\"]", 0, "order =", "sheets.order",
            "an array"},
        Bad{"heading_not_string", "count = \"Crossings\"", "count = 3", 0, "count = 3",
            "headings.lines.count", "3"},
        Bad{"rows_not_integer", "print = 200", "print = 2.5", 0, "print = 2.5", "rows.print",
            "2.5"},
        Bad{"missing_table", "[chart.profile]", "[chart.profil]", 0, "[chart.profil]",
            "chart.profil", "unknown key"},
        Bad{"syntax", "[sheets]", "[sheets", 0, "[sheets", "TOML syntax", ""},
        // Found by running the real report writer: each crashed (&G) or ended in exit 3 after a
        // whole simulation while validate passed the layout.
        Bad{"footer_picture", "footer = \"&L&A&Rpage &P of &N\"", "footer = \"&L&g\"", 0,
            "footer = \"&L&g\"", "page.footer", "&L&g"},
        Bad{"footer_too_long", "footer = \"&L&A&Rpage &P of &N\"",
            "footer = \"" + std::string(256, 'x') + "\"", 0, "footer = \"xxx", "page.footer", "xxx"},
        Bad{"sheet_names_differ_in_case", "inputs = \"Inputs\"", "inputs = \"SUMMARY\"", 0,
            "inputs = \"SUMMARY\"", "sheets.inputs", "SUMMARY"}));

// The program carries the layout it was built with: the text of templates/report.toml.
TEST(ReportTemplate, BuiltInLayoutIsTheShippedFile) {
  EXPECT_EQ(pierre::io::shipped_report_template_text(), read_file(kTemplate));
  EXPECT_TRUE(load_report_template(kTemplate).built_in_keys.empty());
}

// A firm's copy made before keys were added: what it leaves out (a key, a whole table) comes
// from the built-in layout and is listed; what it holds is its own.
TEST(ReportTemplate, KeysACopyLeavesOutComeFromTheBuiltInLayout) {
  std::string text = shipped_with("summary = \"Summary\"\n", "");
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
           {"status = \"Status\"\n", ""},
           {"[chart.profile]", "[chart.profile_gone]"},
           {"profile = \"Profile\"", "profile = \"Section\""}}) {
    const auto p = text.find(from);
    ASSERT_NE(p, std::string::npos) << from;
    text.replace(p, from.size(), to);
  }
  // [chart.profile_gone] would be an unknown table: drop its keys with it.
  const auto gone = text.find("[chart.profile_gone]");
  text.erase(gone, text.find("\n[", gone + 1) - gone);
  TempDir dir;
  const auto t = load_report_template(dir.write("report.toml", text));
  const auto shipped = load_report_template(kTemplate);
  EXPECT_EQ(t.get("sheets", "summary"), shipped.get("sheets", "summary"));
  EXPECT_EQ(t.get("headings.checks", "status"), shipped.get("headings.checks", "status"));
  EXPECT_EQ(t.get("chart.profile", "title"), shipped.get("chart.profile", "title"));
  EXPECT_EQ(t.get("sheets", "profile"), "Section");  // its own value kept
  std::vector<std::string> keys = t.built_in_keys;
  std::sort(keys.begin(), keys.end());
  EXPECT_EQ(keys, (std::vector<std::string>{"chart.profile", "headings.checks.status",
                                            "sheets.summary"}));
}

// A firm's copy made before the Summary's observation lines were laid out a row per quantity:
// its headings of the old columns (speed_mean, …) are keys this version dropped. They are read
// and listed, not an error, and the new keys come from the built-in layout; a key that no
// layout ever had is still an error.
TEST(ReportTemplate, KeysAnEarlierLayoutHadAreIgnoredAndListed) {
  const std::string old_lines =
      "[headings.lines]\nname = \"Line\"\nchainage = \"Chainage (m)\"\ncount = \"Crossings\"\n"
      "not_reached = \"Not reached\"\nspeed_mean = \"Mean speed (m/s)\"\n"
      "speed_p95 = \"P95 speed (m/s)\"\nheight_p95 = \"P95 passing height (m)\"\n"
      "energy_p95 = \"P95 energy (kJ)\"\nenergy_max = \"Max energy (kJ)\"\n\n";
  std::string text = read_file(kTemplate);
  const auto at = text.find("[headings.lines]");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, text.find("\n[", at + 1) + 1 - at, old_lines);
  TempDir dir;
  const auto t = load_report_template(dir.write("report.toml", text));
  EXPECT_EQ(t.get("headings.lines", "name"), "Line");  // its own value kept
  EXPECT_EQ(t.get("headings.lines", "p50"), load_report_template(kTemplate).get("headings.lines", "p50"));
  EXPECT_EQ(t.retired_keys,
            (std::vector<std::string>{"headings.lines.energy_max", "headings.lines.energy_p95",
                                      "headings.lines.height_p95", "headings.lines.speed_mean",
                                      "headings.lines.speed_p95"}));
  EXPECT_TRUE(load_report_template(kTemplate).retired_keys.empty());
  // A retired key of one table is unknown in another.
  const std::string moved = shipped_with("[headings.checks]\n", "[headings.checks]\nspeed_mean = \"x\"\n");
  try {
    load_report_template(dir.write("moved.toml", moved));
    ADD_FAILURE() << "speed_mean under [headings.checks] was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("headings.checks.speed_mean"), std::string::npos) << e.what();
  }
}

// A copy's sheet order made before a sheet was added: the sheet goes in after the one it
// follows in the built-in order, the copy's own order of the rest is kept, and it is listed.
TEST(ReportTemplate, SheetsACopysOrderLeavesOutGoInAfterTheirBuiltInPredecessor) {
  const std::string text = shipped_with(
      "order = [\"summary\", \"barriers\", \"quarries\", \"profile\", \"inputs\", \"blocks\", "
      "\"trajectories\", \"crossings\"]",
      "order = [\"crossings\", \"summary\", \"barriers\", \"profile\", \"trajectories\"]");
  TempDir dir;
  const auto t = load_report_template(dir.write("report.toml", text));
  EXPECT_EQ(t.order, (std::vector<std::string>{"crossings", "summary", "barriers", "quarries",
                                               "profile", "inputs", "blocks", "trajectories"}));
  EXPECT_EQ(t.built_in_keys,
            (std::vector<std::string>{"sheets.order: quarries", "sheets.order: inputs",
                                      "sheets.order: blocks"}));
  // The first sheet of the built-in order, left out, goes first.
  const auto first = load_report_template(dir.write(
      "first.toml", shipped_with("order = [\"summary\", ", "order = [")));
  EXPECT_EQ(first.order, load_report_template(kTemplate).order);
  EXPECT_EQ(first.built_in_keys, (std::vector<std::string>{"sheets.order: summary"}));
}

// The copy's sheet name equal to one the built-in layout filled in: the error is at the copy's
// own key and line, not at a line of the built-in text.
TEST(ReportTemplate, ANameClashingWithABuiltInNameIsTheCopysKeysError) {
  // sheets.crossings comes after sheets.summary: the clash is met at the built-in key.
  std::string text = shipped_with("crossings = \"Crossings\"\n", "");
  const std::string from = "summary = \"Summary\"", to = "summary = \"Crossings\"";
  const auto p = text.find(from);
  ASSERT_NE(p, std::string::npos);
  text.replace(p, from.size(), to);
  TempDir dir;
  const auto file = dir.write("report.toml", text);
  try {
    (void)load_report_template(file);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), file);
    EXPECT_EQ(e.line(), line_of(text, to));
    EXPECT_EQ(e.field(), "sheets.summary");
    EXPECT_NE(std::string(e.what()).find("built-in"), std::string::npos) << e.what();
  }
}

// The order's error names the entry at fault.
TEST(ReportTemplate, AnOrderErrorNamesTheEntry) {
  TempDir dir;
  for (const auto& [to, says] : std::vector<std::pair<std::string, std::string>>{
           {"\"summary\"]", "\"summary\" is there twice"},
           {"\"crossing\"]", "\"crossing\" is not a sheet of the report"}}) {
    try {
      (void)load_report_template(dir.write("r.toml", shipped_with("\"crossings\"]", to)));
      FAIL() << "no InputError for " << to;
    } catch (const InputError& e) {
      EXPECT_NE(e.expected().find(says), std::string::npos) << e.expected();
    }
  }
}

TEST(ReportTemplate, AnEmptyCopyIsTheBuiltInLayout) {
  TempDir dir;
  const auto t = load_report_template(dir.write("report.toml", "# nothing restyled yet\n"));
  const auto shipped = load_report_template(kTemplate);
  EXPECT_EQ(t.text, shipped.text);
  EXPECT_EQ(t.colours, shipped.colours);
  EXPECT_EQ(t.order, shipped.order);
  EXPECT_EQ(t.built_in_keys.size(), 11u);  // the eleven top-level tables
}

TEST(ReportTemplate, MissingFile) {
  TempDir dir;
  try {
    (void)load_report_template(dir.path() / "nope.toml");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 0);
    EXPECT_EQ(e.found(), "no such file");
  }
}

}  // namespace
