// Every input error of the scenario format (docs/scenario-format.md): each case writes a bad
// input, loads it, and asserts the file, the line, the field and the value found that the
// InputError carries, and the message format "<file>:<line>: <field>: found <value>, expected".
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "pierre/io/scenario_reader.hpp"
#include "test_files.hpp"

namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using pierre::io::InputError;
using pierre::io::load_scenario;
using pierre::test::base_lines;
using pierre::test::TempDir;

const std::filesystem::path kRules = PIERRE_SOURCE_DIR "/rules";

// The InputError of a scenario written as `text` in `dir` (a failure when there is none).
InputError scenario_error(TempDir& dir, const std::string& text) {
  try {
    (void)load_scenario(dir.write("s.toml", text), kRules);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError for:\n" << text;
  return InputError("", 0, "", "", "");
}

struct Case {
  std::string name;
  std::vector<std::pair<int, std::string>> replace;  // base line → new text
  std::vector<std::pair<std::string, std::string>> files;  // other files in the folder
  std::string file;   // file named by the error
  long line;
  std::string field;
  std::string found;  // a substring of found()
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

std::string scenario_text(const Case& c) { return pierre::test::base_with(c.replace); }

class ScenarioError : public ::testing::TestWithParam<Case> {};

TEST_P(ScenarioError, NamesFileLineFieldAndValue) {
  const Case& c = GetParam();
  TempDir dir;
  const auto scenario = dir.write("s.toml", scenario_text(c));
  for (const auto& [name, text] : c.files) dir.write(name, text);
  try {
    (void)load_scenario(scenario, kRules);
    FAIL() << "no InputError for " << c.name;
  } catch (const InputError& e) {
    SCOPED_TRACE(e.what());
    EXPECT_EQ(e.file(), dir.path() / c.file);
    EXPECT_EQ(e.line(), c.line);
    EXPECT_EQ(e.field(), c.field);
    EXPECT_NE(e.found().find(c.found), std::string::npos) << "found: " << e.found();
    EXPECT_FALSE(e.expected().empty());
    const std::string where = c.line > 0 ? (dir.path() / c.file).string() + ":" + std::to_string(c.line)
                                         : (dir.path() / c.file).string();
    EXPECT_EQ(std::string(e.what()),
              where + ": " + c.field + ": found " + e.found() + ", expected " + e.expected());
  }
}

// A CSV saved by a spreadsheet in a European locale separates with ';' (a text export with tabs):
// a row or header of too few cells holding one says so, with the line as found, and asks for
// commas. It said "z: found nothing (the row has 1 of 3 columns)", which hides the cause.
std::string csv_error(TempDir& dir, const std::string& csv, const std::string& file = "p.csv") {
  Case c{"csv", {{9, "file = \"p.csv\""}}, {}, file, 0, "", ""};
  if (file != "p.csv") c.replace = {{16, "[blocks]\nfile = \"b.csv\""}, {17, ""}, {18, ""}};
  const auto scenario = dir.write("s.toml", scenario_text(c));
  dir.write("p.csv", "x,z,material\n0,10,rock\n10,0,rock\n20,0,\n");
  dir.write(file, csv);
  try {
    (void)load_scenario(scenario, kRules);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no InputError";
}

// A decimal comma in a comma-separated file splits a number in two: one column too many, or a
// material that is a number. Both messages ask whether it is one; a real extra column does not.
// The last inline vertex may go without its material, as its CSV row may leave it empty.
TEST(ScenarioInline, TheLastVertexMayOmitItsMaterial) {
  TempDir dir;
  const auto l = load_scenario(
      dir.write("s.toml", pierre::test::base_with(9, "points = [[0.0, 10.0, \"rock\"], [20.0, 0.0]]")),
      kRules);
  ASSERT_EQ(l.scenario.profile.segment_count(), 1u);
  EXPECT_DOUBLE_EQ(l.scenario.profile.vertices()[1].x, 20.0);
}

TEST(ScenarioCsv, ADecimalCommaIsAskedAbout) {
  TempDir dir;
  const std::string p = (dir.path() / "p.csv").string();
  EXPECT_EQ(csv_error(dir, "x,z,material\n0,10,rock\n16,5,0,rock\n20,0,\n"),
            p + ":3: row: found 4 columns (column 4 holds \"rock\"), expected 3 columns "
                "(x,z,material); a decimal comma? numbers take a point (16.5, not 16,5)");
  EXPECT_EQ(csv_error(dir, "x,z,material\n0,10,rock\n10,0,rock,rock\n20,0,\n"),
            p + ":3: row: found 4 columns (column 4 holds \"rock\"), expected 3 columns "
                "(x,z,material)");
  EXPECT_EQ(csv_error(dir, "x,z,material\n0,10,rock\n20,-0,5\n"),
            p + ":3: material: found \"5\", expected a material defined in [materials] (rock); "
                "a decimal comma in z? numbers take a point (-0.5, not -0,5)");
}

// A file that starts with its numbers has no header: said so, not "found column \"0\"".
// Headings are matched without case, as spreadsheets capitalise them.
TEST(ScenarioCsv, AMissingHeaderIsSaidAndCaseIsIgnored) {
  TempDir dir;
  const std::string p = (dir.path() / "p.csv").string();
  EXPECT_EQ(csv_error(dir, "0,10,rock\n10,0,rock\n20,0,\n"),
            p + ":1: header: found a row of values (\"0,10,rock\") where the header belongs, "
                "expected a header line x,z,material above the data rows");
  // Led by a text cell (a material, an id): the numbers after it still say it is a row.
  EXPECT_EQ(csv_error(dir, "rock,0,10\nrock,10,0\n,20,0\n"),
            p + ":1: header: found a row of values (\"rock,0,10\") where the header belongs, "
                "expected a header line x,z,material above the data rows");
  EXPECT_EQ(csv_error(dir, "X,Z_M,Material\n0,10,rock\n10,0,rock\n20,1,\n"), "no InputError");
  const auto l = load_scenario(dir.path() / "s.toml", kRules);  // the scenario csv_error wrote
  EXPECT_DOUBLE_EQ(l.scenario.profile.vertices()[2].z, 1.0);
  // A title line above the header (a spreadsheet's export): said as one, with how to keep it.
  EXPECT_EQ(csv_error(dir, "Railway cutting km 12.4\nx,z,material\n0,10,rock\n10,0,rock\n20,0,\n"),
            p + ":1: header: found column \"Railway cutting km 12.4\", expected only the columns "
                "x,z,material (x may be written x_m, z z_m); a title line? delete it, or start it "
                "with # (a comment line)");
  // A misnamed column among several is no title.
  EXPECT_EQ(csv_error(dir, "x,height,material\n0,10,rock\n").find("title"), std::string::npos);
}

TEST(ScenarioCsv, ASemicolonRowSaysItsSeparator) {
  TempDir dir;
  const std::string p = (dir.path() / "p.csv").string();
  EXPECT_EQ(csv_error(dir, "x,z,material\n0,10,rock\n10;0;rock\n20,0,\n"),
            p + ":3: row: found \"10;0;rock\" (1 of 3 columns: the cells are separated by \";\"), "
                "expected cells separated by commas (x,z,material)");
  // Two of three cells, the last two run together: still the separator.
  EXPECT_EQ(csv_error(dir, "x,z,material\n0,10,rock\n10,0;rock\n20,0,\n"),
            p + ":3: row: found \"10,0;rock\" (2 of 3 columns: the cells are separated by \";\"), "
                "expected cells separated by commas (x,z,material)");
}

// A value past the header's last name: the row may hold a stray value, or the header may have
// lost a name ("x,z," for "x,z,material"); the message names both (found by fuzzing: it
// blamed the row alone, "expected 2 columns").
TEST(ScenarioCsv, AValueUnderAnUnnamedColumnNamesTheHeaderToo) {
  TempDir dir;
  const std::string p = (dir.path() / "p.csv").string();
  EXPECT_EQ(csv_error(dir, "x,z,\n0,10,rock\n10,0,rock\n20,0,\n"),
            p + ":2: row: found 3 columns (column 3 holds \"rock\"), expected 2 columns (x,z), or "
                "a name for column 3 in the header (line 1: \"x,z,\")");
  // A header without trailing empty cells: the row alone.
  EXPECT_EQ(csv_error(dir, "x,z,material\n0,10,rock,1\n20,0,\n"),
            p + ":2: row: found 4 columns (column 4 holds \"1\"), expected 3 columns (x,z,material)");
}

// A European export separates by ';' and writes decimal commas: the header's message asks for
// both changes, so that swapping ';' for ',' alone does not lead to a second, puzzling error
// (a new user's "found 5 columns" once the semicolons were gone).
TEST(ScenarioCsv, ASemicolonHeaderOverDecimalCommasAsksForDecimalPointsToo) {
  TempDir dir;
  const std::string p = (dir.path() / "p.csv").string();
  EXPECT_EQ(csv_error(dir, "x;z;material\n0;10,5;rock\n10;0;rock\n20;0;\n"),
            p + ":1: header: found \"x;z;material\" (1 column: the cells are separated by \";\"), "
                "expected cells separated by commas (x,z,material); the rows' decimal commas must "
                "then become points (10,5 → 10.5)");
  EXPECT_EQ(csv_error(dir, "x;z;material\n0;10;rock\n10;0;rock\n20;0;\n"),
            p + ":1: header: found \"x;z;material\" (1 column: the cells are separated by \";\"), "
                "expected cells separated by commas (x,z,material)");
}

TEST(ScenarioCsv, ATabSeparatedRowSaysItsSeparatorAndShowsTheTabs) {
  TempDir dir;
  EXPECT_EQ(csv_error(dir, "x,z,material\n0,10,rock\n10\t0\trock\n20,0,\n"),
            (dir.path() / "p.csv").string() +
                ":3: row: found \"10\\t0\\trock\" (1 of 3 columns: the cells are separated by "
                "tabs), expected cells separated by commas (x,z,material)");
}

TEST(ScenarioCsv, ASemicolonHeaderSaysItsSeparator) {
  TempDir dir;
  const std::string p = (dir.path() / "p.csv").string();
  EXPECT_EQ(csv_error(dir, "x;z;material\n0;10;rock\n10;0;rock\n"),
            p + ":1: header: found \"x;z;material\" (1 column: the cells are separated by \";\"), "
                "expected cells separated by commas (x,z,material)");
  EXPECT_EQ(csv_error(dir, "x\tz\tmaterial\n0\t10\trock\n10\t0\trock\n"),
            p + ":1: header: found \"x\\tz\\tmaterial\" (1 column: the cells are separated by "
                "tabs), expected cells separated by commas (x,z,material)");
  // A header that is merely wrong does not get the hint.
  EXPECT_EQ(csv_error(dir, "x,z,colour\n0,10,rock\n10,0,rock\n"),
            p + ":1: header: found column \"colour\", expected only the columns x,z,material "
                "(x may be written x_m, z z_m)");
}

// A row short of a cell without another separator keeps its message; so does one whose ';' is
// inside a quoted text (a block's id), which is no separator. Where the missing cells may be
// empty (a blocks CSV), the message shows the row with them: a cut-off row stays an error.
TEST(ScenarioCsv, AShortCommaRowNamesTheMissingColumn) {
  TempDir dir;
  EXPECT_EQ(csv_error(dir, "x,z,material\n0,10,rock\n10,0\n20,0,\n"),
            (dir.path() / "p.csv").string() +
                ":3: material: found nothing (the row has 2 of 3 columns), expected a value in "
                "every column of x,z,material");
  EXPECT_EQ(csv_error(dir, "id,mass,count\n\"a;b\",100\n", "b.csv"),
            (dir.path() / "b.csv").string() +
                ":2: count: found nothing (the row has 2 of 3 columns), expected a value or an "
                "empty cell in every column of id,mass,count (\"\"a;b\",100,\" leaves count empty)");
  EXPECT_EQ(csv_error(dir, "id,mass,volume,count\nP01,,0.5,2\nP02,140\n", "b.csv"),
            (dir.path() / "b.csv").string() +
                ":3: volume: found nothing (the row has 2 of 4 columns), expected a value or an "
                "empty cell in every column of id,mass,volume,count (\"P02,140,,\" leaves "
                "volume,count empty)");
}

// Rows added to a table written inline: a TOML syntax error whose expectation says what to write.
TEST(ScenarioSyntax, RowsAfterAnInlineTableSayToWriteATable) {
  TempDir dir;
  const auto file = dir.write("q.toml",
                              "[scenario]\nname = \"x\"\n[[quarries]]\nblocks = { density = 2650.0 }\n"
                              "[[quarries.blocks.table]]\nmass = 1.0\n");
  try {
    (void)load_scenario(file, kRules);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "TOML syntax");
    EXPECT_NE(e.found().find("inline table"), std::string::npos) << e.found();
    EXPECT_NE(e.expected().find("write it as a table"), std::string::npos) << e.expected();
  }
  // Any other syntax error keeps the plain expectation.
  const auto other = dir.write("o.toml", "[scenario]\nname = = 1\n");
  try {
    (void)load_scenario(other, kRules);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.expected(), "valid TOML (https://toml.io)");
  }
}

// A file named where a table of a file was asked (`profile = "profile.csv"`): the table's form is
// said, at the root as [profile] and inline inside a quarry section.
TEST(ScenarioSyntax, AFileGivenForATableSaysTheTablesForm) {
  TempDir dir;
  auto expected_of = [&](const std::string& text) {
    const InputError e = scenario_error(dir, text);
    return e.field() + ": " + e.expected();
  };
  EXPECT_EQ(expected_of("profile = \"profile.csv\"\n" + pierre::test::base_with({{8, ""}, {9, ""}})),
            "profile: a table: [profile] with file = \"profile.csv\" on the line below it, or "
            "profile = { file = \"profile.csv\" }");
  std::string quarry = pierre::test::read_file(PIERRE_SOURCE_DIR "/examples/quarry-austria/scenario.toml");
  const std::string inline_file = "profile = { file = \"profile-kloech.csv\" }";
  ASSERT_NE(quarry.find(inline_file), std::string::npos);
  quarry.replace(quarry.find(inline_file), inline_file.size(), "profile = \"profile-kloech.csv\"");
  EXPECT_EQ(expected_of(quarry),
            "quarries[0].profile: a table, e.g. profile = { file = \"profile-kloech.csv\" }");
  // The path as TOML writes it: a Windows path pasted back is read as typed.
  EXPECT_EQ(expected_of("profile = 'C:\\data\\p\"1.csv'\n" + pierre::test::base_with({{8, ""}, {9, ""}})),
            "profile: a table: [profile] with file = \"C:\\\\data\\\\p\\\"1.csv\" on the line below "
            "it, or profile = { file = \"C:\\\\data\\\\p\\\"1.csv\" }");
}

// A section's key typed below another section's header is in that section for TOML: the
// message says so, whether the other section rejects it as unknown or the section is then
// missing from the root (found at any depth). Not for a key that is a slip of one of the
// table's own keys, nor inside an inline table, where a key stands as written.
TEST(ScenarioSyntax, ASectionBelowAnotherHeaderIsToldSo) {
  TempDir dir;
  auto error_of = [&](const std::string& text) {
    const InputError e = scenario_error(dir, text);
    return std::to_string(e.line()) + " " + e.field() + ": " + e.expected();
  };
  const std::string points = "points = [[0.0, 10.0, \"rock\"], [10.0, 0.0, \"rock\"], [20.0, 0.0, \"\"]]";
  const std::string advice = "write profile above the first header, or under a header of its own";
  // Below [simulation], which reads its keys strictly.
  EXPECT_THAT(error_of(pierre::test::base_with({{7, "profile = { " + points + " }"}, {8, ""}, {9, ""}})),
              HasSubstr("; profile is a section of its own, and TOML puts every key below the "
                        "[simulation] header into it: " + advice));
  // At the end of the file, below the last [[observation_lines]]: the profile is found missing
  // first, and the message points at the line where it stands.
  const std::string at_end =
      pierre::test::base_with({{8, ""}, {9, ""}}) + "profile = { " + points + " }\n";
  EXPECT_EQ(error_of(at_end),
            "27 profile: a [profile] table with file = \"...\" or points = [...]; the key profile "
            "on this line stands below the [[observation_lines]] header, and TOML puts it into that "
            "table: " + advice);
  // Two tables deep: the header as written, without the index of the array entry.
  const std::string deep = pierre::test::base_with({{8, ""}, {9, ""}}) +
                           "[[barriers]]\nname = \"B\"\nline = \"L\"\n[barriers.candidate]\n"
                           "height = 3.0\nprofile = { " + points + " }\n";
  EXPECT_THAT(error_of(deep), HasSubstr("32 profile: ")) << error_of(deep);
  EXPECT_THAT(error_of(deep), HasSubstr("below the [barriers.candidate] header"));
  // Inside an inline table the key stands where it is written: no advice to move it.
  const std::string in_inline =
      "sources = [{ x = 1.0, z = 11.0, profile = { " + points + " } }]\n" +
      pierre::test::base_with({{8, ""}, {9, ""}, {20, ""}, {21, ""}, {22, ""}});
  EXPECT_EQ(error_of(in_inline),
            "0 profile: a [profile] table with file = \"...\" or points = [...]");
  // A slip of the table's own key keeps its hint: materials for materials_file in [scenario].
  EXPECT_THAT(error_of(pierre::test::base_with(3, "materials = \"m.toml\"")),
              HasSubstr("; the nearest is materials_file"));
  // A key that is no section gets no such hint.
  EXPECT_THAT(error_of(pierre::test::base_with(7, "seeds = 1")), Not(HasSubstr("section")));
  // A barrier's own table written as [candidate], below its [[barriers]] header: TOML reads it
  // as a top-level section, and the message gives the header that belongs to the barrier.
  const std::string root_candidate = pierre::test::base_with({{8, ""}, {9, ""}}) +
                                     "[[barriers]]\nname = \"B\"\nline = \"L\"\n[candidate]\n"
                                     "height = 3.0\n";
  EXPECT_THAT(error_of(root_candidate),
              HasSubstr("30 candidate: one of scenario, simulation, profile, materials, blocks, "
                        "sources, observation_lines, barriers, quarries, confirmed; if it belongs to "
                        "the [[barriers]] item above, write [barriers.candidate]"))
      << error_of(root_candidate);
  // Above every [[list]] item there is no item to point to.
  EXPECT_THAT(error_of("[candidate]\nheight = 3.0\n" + pierre::test::base_with({{8, ""}, {9, ""}})),
              AllOf(HasSubstr("candidate: one of"), Not(HasSubstr("item above"))));
  // Below the first of two barriers, after which another list's item stands: the barrier is the
  // item above it, not the last item of any list (the first version took each list's last item).
  const std::string first_of_two =
      pierre::test::base_with({{8, ""}, {9, ""}}) +
      "[[barriers]]\nname = \"A\"\nline = \"L\"\n[candidate]\nheight = 3.0\n"
      "[[barriers]]\nname = \"B\"\nline = \"L\"\n";
  EXPECT_THAT(error_of(first_of_two), HasSubstr("the [[barriers]] item above, write [barriers.candidate]"))
      << error_of(first_of_two);
  // Items written inline have no header to follow.
  const std::string inline_only = "observation_lines = [{ name = \"L\", x = 15.0 }]\n"
                                  "sources = [{ x = 1.0, z = 11.0 }]\n" +
                                  pierre::test::base_with({{8, ""}, {9, ""}, {20, ""}, {21, ""}, {22, ""},
                                                           {24, ""}, {25, ""}, {26, ""}}) +
                                  "[candidate]\nheight = 3.0\n";
  EXPECT_THAT(error_of(inline_only), AllOf(HasSubstr("candidate: one of"), Not(HasSubstr("item above"))))
      << error_of(inline_only);
}

// The two slips toml++ describes in its own terms get a hint in ours: a decimal comma cuts a
// number short ("saw ','"), and a string without its closing quote runs into the line's end.
TEST(ScenarioSyntax, ADecimalCommaAndAnUnclosedStringAreHinted) {
  TempDir dir;
  struct Slip {
    std::string line, hint;
  };
  const Slip cases[] = {
      {"throws = 2,5", "a decimal comma? TOML numbers take a point (0.5, not 0,5)"},
      {"throws = \"2", "a string not closed on its line? every \"…\" needs its closing quote"},
      // A unit typed after the number, with or without a space, and text without its quotes.
      {"throws = 2 m", "a unit after the number? write the number alone (5.0)"},
      {"throws = 2700kg", "a unit after the number?"},
      {"throws = 35°", "a unit after the number?"},
      {"throws = Preg 1", "text? put it in quotes (name = \"Preg 1\")"},
  };
  for (const Slip& c : cases) {
    try {
      (void)load_scenario(dir.write("s.toml", pierre::test::base_with(6, c.line)), kRules);
      FAIL() << "no InputError for " << c.line;
    } catch (const InputError& e) {
      EXPECT_EQ(e.line(), 6);
      EXPECT_EQ(e.field(), "TOML syntax");
      EXPECT_EQ(e.expected().rfind("valid TOML (https://toml.io); ", 0), 0u) << e.expected();
      EXPECT_NE(e.expected().find(c.hint), std::string::npos) << e.expected();
    }
  }
  // A profile table given where the scenario belongs is named for what it is.
  try {
    (void)load_scenario(dir.write("p.csv", "x,z,material\n0,1,rock\n"), kRules);
    FAIL() << "no InputError for a CSV";
  } catch (const InputError& e) {
    EXPECT_EQ(e.expected(), "valid TOML (https://toml.io); this is a CSV file: give the scenario "
                            "(.toml) that names it");
  }
}

// A number written as text: with its unit, or with a decimal comma, the expectation says which
// to leave out; other text is only "a number".
TEST(ScenarioSyntax, ANumberWrittenAsTextIsToldHowToWriteIt) {
  TempDir dir;
  auto error_of = [&](const std::string& text) { return scenario_error(dir, text); };
  EXPECT_EQ(error_of(pierre::test::base_with(14, "roughness = \"0.5 m\"")).expected(),
            "a number, written without quotes or unit (each value has a fixed unit: m, kg, kg/m³, "
            "m/s, °; docs/scenario-format.md)");
  EXPECT_EQ(error_of(pierre::test::base_with(14, "roughness = \"0,5\"")).expected(),
            "a number, written without quotes and with a decimal point (12.5, not \"12,5\")");
  EXPECT_EQ(error_of(pierre::test::base_with(14, "roughness = \"rough\"")).expected(), "a number");
  // A comma before three digits is a thousands separator: a decimal point there would make the
  // value 1000 times too small.
  EXPECT_EQ(error_of(pierre::test::base_with(14, "roughness = \"2,650\"")).expected(),
            "a number, written without quotes and without a thousands separator (2650, not \"2,650\")");
  // An integer written as text, likewise.
  EXPECT_EQ(error_of(pierre::test::base_with(6, "throws = \"5\"")).expected(),
            "an integer, written without quotes or unit (each value has a fixed unit: m, kg, kg/m³, "
            "m/s, °; docs/scenario-format.md)");
  // Text that opens with a number is no number with a unit: no unit hint.
  EXPECT_EQ(error_of(pierre::test::base_with(2, "name = 2nd road")).expected().find("unit"),
            std::string::npos);
}

// A syntax error says what is malformed, not toml++'s "Error while parsing …" ("found Error
// while parsing floating-point: …" read as if the file held an error message); a character it
// saw is shown escaped, so that the message stays on one line.
TEST(ScenarioSyntax, SaysWhatIsMalformedInWords) {
  TempDir dir;
  struct Bad {
    std::string line;  // replaces base line 6 (throws = 2)
    std::string found;
  };
  const Bad cases[] = {
      {"throws = 1..2", "a malformed floating-point number (expected decimal digit or exponent, "
                        "saw '.'; column 12)"},
      {"throws = tru", "a malformed boolean (expected 'true', saw 'tru\\n'; column 13)"},
      {"= 2", "a line that is not TOML (expected keys, tables, whitespace or comments, saw '='; "
              "column 1)"},
  };
  for (const Bad& b : cases) {
    const auto file = dir.write("s.toml", pierre::test::base_with(6, b.line));
    try {
      (void)load_scenario(file, kRules);
      FAIL() << "no InputError for " << b.line;
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), file);
      EXPECT_EQ(e.line(), 6);
      EXPECT_EQ(e.field(), "TOML syntax");
      EXPECT_EQ(e.found(), b.found);
      EXPECT_EQ(e.expected(), "valid TOML (https://toml.io)");
      EXPECT_EQ(std::string(e.what()), file.string() + ":6: TOML syntax: found " + b.found +
                                           ", expected valid TOML (https://toml.io)");
      EXPECT_EQ(std::string(e.what()).find("Error while parsing"), std::string::npos);
    }
  }
}

// A missing file's expectation says where a relative path is looked for, and nothing of the
// sort for an absolute one (it was "a path relative to the current folder" for /nonexist/p.csv).
TEST(ScenarioFiles, AMissingFileSaysWhereARelativePathIsLookedFor) {
  TempDir dir;
  const std::string absolute = (dir.path() / "nowhere" / "p.csv").string();
  for (const std::string& name : {std::string("p.csv"), absolute}) {
    try {
      (void)load_scenario(dir.write("s.toml", pierre::test::base_with(9, "file = \"" + name + "\"")),
                          kRules);
      FAIL() << "no InputError for " << name;
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), "profile.file");
      const bool says_relative = e.expected().find("a path relative to " + dir.path().string()) !=
                                 std::string::npos;
      EXPECT_EQ(says_relative, name == "p.csv") << e.expected();
    }
  }
}

const std::string kCsvProfile = "file = \"p.csv\"";
const std::string kCrossingRows = "x,z,material\n0,10,rock\n10,0,rock\n10,10,rock\n0,0,\n";

INSTANTIATE_TEST_SUITE_P(
    Reader, ScenarioError,
    ::testing::Values(
        // syntax and missing things
        Case{"toml_syntax", {{6, "throws = = 2"}}, {}, "s.toml", 6, "TOML syntax", "column"},
        Case{"missing_simulation_table", {{4, ""}, {5, ""}, {6, ""}}, {}, "s.toml", 0, "simulation", "nothing"},
        Case{"missing_seed", {{5, ""}}, {}, "s.toml", 4, "simulation.seed", "nothing"},
        Case{"missing_name", {{2, ""}}, {}, "s.toml", 1, "scenario.name", "nothing"},
        Case{"missing_material_roughness", {{14, ""}}, {}, "s.toml", 11, "materials.rock.roughness", "nothing"},
        Case{"missing_source_z", {{22, ""}}, {}, "s.toml", 20, "sources[0].z", "nothing"},
        Case{"missing_block_mass", {{18, ""}}, {}, "s.toml", 17, "blocks.table[0].mass", "neither mass nor volume"},
        Case{"missing_line_name", {{25, ""}}, {}, "s.toml", 24, "observation_lines[0].name", "nothing"},
        // unknown keys, in every table
        Case{"unknown_root", {{1, "colour = 1\n[scenario]"}}, {}, "s.toml", 1, "colour", "an unknown key"},
        Case{"unknown_scenario", {{2, "name = \"t\"\ntitle = \"x\""}}, {}, "s.toml", 3, "scenario.title", "an unknown key"},
        Case{"unknown_simulation", {{6, "thows = 2"}}, {}, "s.toml", 6, "simulation.thows", "an unknown key"},
        Case{"unknown_profile", {{9, base_lines()[8] + "\nstep = 1"}}, {}, "s.toml", 10, "profile.step", "an unknown key"},
        Case{"unknown_material", {{14, "roughness = 0.5\nrougness = 0.6"}}, {}, "s.toml", 15, "materials.rock.rougness", "an unknown key"},
        Case{"unknown_blocks", {{16, "[blocks]\ncolour = 1"}}, {}, "s.toml", 17, "blocks.colour", "an unknown key"},
        Case{"unknown_block_row", {{18, "mass = 100.0\nmas = 1"}}, {}, "s.toml", 19, "blocks.table[0].mas", "an unknown key"},
        Case{"unknown_source", {{22, "z = 11.0\ny = 0"}}, {}, "s.toml", 23, "sources[0].y", "an unknown key"},
        Case{"unknown_line", {{26, "x = 15.0\nz = 1"}}, {}, "s.toml", 27, "observation_lines[0].z", "an unknown key"},
        // wrong types: exact-type accessors
        Case{"seed_string", {{5, "seed = \"1\""}}, {}, "s.toml", 5, "simulation.seed", "\"1\""},
        Case{"throws_float", {{6, "throws = 1.5"}}, {}, "s.toml", 6, "simulation.throws", "1.5"},
        Case{"throws_integral_float", {{6, "throws = 2.0"}}, {}, "s.toml", 6, "simulation.throws", "2.0"},
        Case{"bool_string", {{6, "throws = 2\nsize_reduction = \"yes\""}}, {}, "s.toml", 7, "simulation.size_reduction", "\"yes\""},
        Case{"roughness_string", {{14, "roughness = \"0.5\""}}, {}, "s.toml", 14, "materials.rock.roughness", "\"0.5\""},
        Case{"name_integer", {{2, "name = 5"}}, {}, "s.toml", 2, "scenario.name", "5"},
        // control characters (the report's XML cannot hold them): TOML text, material names, CSV cells
        Case{"name_control_character", {{2, "name = \"a\\u0007b\""}}, {}, "s.toml", 2, "scenario.name", "control character U+0007"},
        Case{"material_name_control_character", {{9, "points = [[0.0, 10.0, \"r\\u001b\"], [20.0, 0.0, \"\"]]"}, {11, "[materials.\"r\\u001b\"]"}}, {}, "s.toml", 11, "materials", "material name: a text with the control character U+001B"},
        Case{"blocks_csv_control_character", {{16, "[blocks]\nfile = \"b.csv\""}, {17, ""}, {18, ""}}, {{"b.csv", "id,mass\na\x7f,100\n"}}, "b.csv", 2, "id", "control character U+007F"},
        Case{"blocks_csv_latin1", {{16, "[blocks]\nfile = \"b.csv\""}, {17, ""}, {18, ""}}, {{"b.csv", "id,mass\nok,50\ncaf\xe9,100\n"}}, "b.csv", 3, "id", "not UTF-8 (byte 0xE9 at position 4"},
        Case{"blocks_csv_overlong", {{16, "[blocks]\nfile = \"b.csv\""}, {17, ""}, {18, ""}}, {{"b.csv", "id,mass\na\xc0\xaf" "b,100\n"}}, "b.csv", 2, "id", "not UTF-8"},
        Case{"name_noncharacter", {{2, "name = \"a\\uFFFFb\""}}, {}, "s.toml", 2, "scenario.name", "non-character U+FFFF"},
        Case{"mass_bool", {{18, "mass = true"}}, {}, "s.toml", 18, "blocks.table[0].mass", "true"},
        Case{"point_string", {{9, "points = [[\"0\", 10.0, \"rock\"], [10.0, 0.0, \"\"]]"}}, {}, "s.toml", 9, "profile.points[0]", "\"0\""},
        Case{"distribution_name", {{6, "throws = 2\nroughness_distribution = \"normal\""}}, {}, "s.toml", 7, "simulation.roughness_distribution", "\"normal\""},
        // out of range
        Case{"mass_negative", {{18, "mass = -5.0"}}, {}, "s.toml", 18, "blocks.table[0].mass", "-5.0"},
        // Absurd but finite values that made inf energies in the CSV files.
        Case{"mass_absurd", {{18, "mass = 1e300"}}, {}, "s.toml", 18, "blocks.table[0].mass", "1e+300"},
        Case{"volume_absurd", {{18, "volume = 1e5"}}, {}, "s.toml", 18, "blocks.table[0].volume", "100000"},
        Case{"blocks_csv_mass_absurd", {{16, "[blocks]\nfile = \"b.csv\""}, {17, ""}, {18, ""}}, {{"b.csv", "id,mass\na,1e300\n"}}, "b.csv", 2, "mass", "1e300"},
        Case{"source_speed_absurd", {{23, "vx = 1e200"}}, {}, "s.toml", 23, "sources[0].vx", "1e+200"},
        Case{"source_spin_absurd", {{23, "omega = -2e4"}}, {}, "s.toml", 23, "sources[0].omega", "-20000"},
        // Two sources of one name (the source column of trajectories.csv would not tell them
        // apart), also an unnamed one whose S2 another source took.
        Case{"source_name_twice", {{23, "name = \"crest\"\n[[sources]]\nname = \"crest\"\nx = 2.0\nz = 11.0"}}, {}, "s.toml", 25, "sources[1].name", "\"crest\""},
        Case{"source_default_name_taken", {{23, "name = \"S2\"\n[[sources]]\nx = 2.0\nz = 11.0"}}, {}, "s.toml", 24, "sources[1].name", "nothing"},
        Case{"mass_zero", {{18, "mass = 0.0"}}, {}, "s.toml", 18, "blocks.table[0].mass", "0.0"},
        Case{"volume_zero", {{18, "volume = 0.0"}}, {}, "s.toml", 18, "blocks.table[0].volume", "0.0"},
        Case{"density_negative", {{16, "[blocks]\ndensity = -2650.0"}}, {}, "s.toml", 17, "blocks.density", "-2650.0"},
        Case{"row_density_zero", {{18, "volume = 1.0\ndensity = 0"}}, {}, "s.toml", 19, "blocks.table[0].density", "0"},
        Case{"friction_90", {{14, "roughness = 0.5\nfriction_angle = 90.0"}}, {}, "s.toml", 15, "materials.rock.friction_angle", "90.0"},
        Case{"friction_negative", {{14, "roughness = 0.5\nfriction_angle = -1.0"}}, {}, "s.toml", 15, "materials.rock.friction_angle", "-1.0"},
        Case{"kn_ref_one", {{12, "normal_energy = 5.0\nnormal_energy_k = 1.0"}}, {}, "s.toml", 13, "materials.rock.normal_energy_k", "1.0"},
        Case{"kt_ref_zero", {{13, "tangential_energy = 50.0\ntangential_energy_k = 0.0"}}, {}, "s.toml", 14, "materials.rock.tangential_energy_k", "0.0"},
        Case{"normal_energy_zero", {{12, "normal_energy = 0.0"}}, {}, "s.toml", 12, "materials.rock.normal_energy", "0.0"},
        Case{"tangential_energy_negative", {{13, "tangential_energy = -50.0"}}, {}, "s.toml", 13, "materials.rock.tangential_energy", "-50.0"},
        Case{"roughness_negative", {{14, "roughness = -0.1"}}, {}, "s.toml", 14, "materials.rock.roughness", "-0.1"},
        Case{"roughness_zero", {{14, "roughness = 0.0"}}, {}, "s.toml", 14, "materials.rock.roughness", "0.0"},
        Case{"throws_zero", {{6, "throws = 0"}}, {}, "s.toml", 6, "simulation.throws", "0"},
        Case{"seed_negative", {{5, "seed = -1"}}, {}, "s.toml", 5, "simulation.seed", "-1"},
        Case{"roughness_mean_far_below_zero", {{6, "throws = 2\nroughness_mean = -16.0"}}, {}, "s.toml", 7, "simulation.roughness_mean", "-16.0"},
        Case{"max_time_zero", {{6, "throws = 2\nmax_time = 0.0"}}, {}, "s.toml", 7, "simulation.max_time", "0.0"},
        Case{"max_impacts_too_large", {{6, "throws = 2\nmax_impacts = 4294967296"}}, {}, "s.toml", 7, "simulation.max_impacts", "4294967296"},
        Case{"throws_too_large", {{6, "throws = 4294967296"}}, {}, "s.toml", 6, "simulation.throws", "4294967296"},
        Case{"blocks_in_all", {{16, "[blocks]\nfile = \"b.csv\""}, {17, ""}, {18, ""}}, {{"b.csv", "id,mass,count\na,100,1000000\nb,100,1\n"}}, "b.csv", 3, "id", "1000001 blocks in all"},
        Case{"count_zero", {{18, "mass = 100.0\ncount = 0"}}, {}, "s.toml", 19, "blocks.table[0].count", "0"},
        // NaN and infinities (TOML allows the literals)
        Case{"roughness_nan", {{14, "roughness = nan"}}, {}, "s.toml", 14, "materials.rock.roughness", "nan"},
        Case{"source_x_inf", {{21, "x = inf"}}, {}, "s.toml", 21, "sources[0].x", "inf"},
        Case{"mass_minus_inf", {{18, "mass = -inf"}}, {}, "s.toml", 18, "blocks.table[0].mass", "-inf"},
        Case{"point_nan", {{9, "points = [[0.0, nan, \"rock\"], [10.0, 0.0, \"\"]]"}}, {}, "s.toml", 9, "profile.points[0]", "nan"},
        // profile CSV: empty, truncated, non-numeric
        Case{"csv_empty", {{9, kCsvProfile}}, {{"p.csv", ""}}, "p.csv", 0, "header", "an empty file"},
        // a file the scenario names and that is not there: said at the scenario's line
        Case{"csv_missing", {{9, kCsvProfile}}, {}, "s.toml", 9, "profile.file", "\"p.csv\" (no such file: "},
        Case{"blocks_csv_missing", {{16, "[blocks]\nfile = \"b.csv\""}, {17, ""}, {18, ""}}, {}, "s.toml", 17, "blocks.file", "\"b.csv\" (no such file: "},
        Case{"profile_csv_a_folder", {{9, "file = \".\""}}, {}, "s.toml", 9, "profile.file", "\".\" (a folder, not a file: "},
        Case{"csv_utf16", {{9, kCsvProfile}}, {{"p.csv", std::string("\xFF\xFEx\0,\0z\0\n\0", 10)}}, "p.csv", 1, "file", "UTF-16"},
        Case{"csv_header_latin1", {{9, kCsvProfile}}, {{"p.csv", "x,z,mat\xe9rial\n0,10,rock\n"}}, "p.csv", 1, "header", "not UTF-8"},
        Case{"csv_header_only", {{9, kCsvProfile}}, {{"p.csv", "x,z,material\n"}}, "p.csv", 1, "profile", "0 vertex rows"},
        Case{"csv_missing_column", {{9, kCsvProfile}}, {{"p.csv", "x,z,material\n0,10,rock\n10,0\n20,0,\n"}}, "p.csv", 3, "material", "2 of 3"},
        Case{"csv_extra_column", {{9, kCsvProfile}}, {{"p.csv", "x,z,material\n0,10,rock,1\n20,0,\n"}}, "p.csv", 2, "row", "4 columns"},
        // Empty trailing cells are ignored (a spreadsheet's), a value in one is not.
        Case{"csv_value_beyond_empty_header_cells", {{9, kCsvProfile}}, {{"p.csv", "x,z,material,,\n0,10,rock,,\n10,0,rock,,5\n20,0,,,\n"}}, "p.csv", 3, "row", "5 columns"},
        // Found by fuzzing (2026-11-24): a stray NUL named at its line, a file of comments alone
        // not called empty, a header whose last name was lost named beside the row.
        Case{"csv_nul_byte", {{9, kCsvProfile}}, {{"p.csv", std::string("x,z,material\n0,10,rock\n10,0,ro\0ck\n20,0,\n", 40)}}, "p.csv", 3, "file", "a NUL byte (code 0) at column 8"},
        Case{"csv_comments_only", {{9, kCsvProfile}}, {{"p.csv", "# x,z,material\n# none yet\n"}}, "p.csv", 0, "header", "only comment lines (2 starting with #), no header"},
        Case{"csv_header_name_lost", {{9, kCsvProfile}}, {{"p.csv", "x,z,\n0,10,rock\n10,0,rock\n20,0,\n"}}, "p.csv", 2, "row", "3 columns (column 3 holds \"rock\")"},
        // One x mistyped (-5 for 25) turns the last segment back under the whole profile: named
        // at its line, not as a profile listed the wrong way round at the first vertex.
        Case{"csv_one_x_mistyped", {{9, kCsvProfile}}, {{"p.csv", "x,z,material\n0,10,rock\n10,0,rock\n20,0,rock\n-5,-5,\n"}}, "p.csv", 5, "x", "x = -5 m after x = 20 m (line 4)"},
        Case{"toml_not_utf8_at_line_start", {{9, "\xE9" + base_lines()[8]}}, {}, "s.toml", 9, "TOML syntax", "byte 0xE9 at column 1"},
        Case{"toml_control_character", {{2, "name = \"a\x01" "b\""}}, {}, "s.toml", 2, "TOML syntax", "control character U+0001 at column 10"},
        Case{"unknown_empty_key", {{1, "\"\" = 1\n[scenario]"}}, {}, "s.toml", 1, "\"\"", "an unknown key"},
        Case{"source_z_beyond_any_section", {{22, "z = 1e300"}}, {}, "s.toml", 22, "sources[0].z", "1e+300"},
        Case{"block_volume_times_density_too_heavy", {{18, "volume = 0.5\ndensity = 1e9"}}, {}, "s.toml", 18, "blocks.table[0].volume", "0.5"},
        Case{"csv_cr_line_ends_bad_number", {{9, kCsvProfile}}, {{"p.csv", "x,z,material\r0,10,rock\r10,zero,rock\r20,0,\r"}}, "p.csv", 3, "z", "\"zero\""},
        Case{"csv_column_and_its_unit_alias", {{9, kCsvProfile}}, {{"p.csv", "x,x_m,z,material\n0,0,10,rock\n10,10,0,rock\n"}}, "p.csv", 1, "header", "column \"x\" twice"},
        Case{"csv_non_numeric", {{9, kCsvProfile}}, {{"p.csv", "x,z,material\n0,10,rock\n10,abc,rock\n20,0,\n"}}, "p.csv", 3, "z", "\"abc\""},
        Case{"csv_nan", {{9, kCsvProfile}}, {{"p.csv", "x,z,material\n0,nan,rock\n20,0,\n"}}, "p.csv", 2, "z", "\"nan\""},
        Case{"csv_unknown_column", {{9, kCsvProfile}}, {{"p.csv", "x,z,material,colour\n0,10,rock,red\n"}}, "p.csv", 1, "header", "colour"},
        Case{"csv_missing_header_column", {{9, kCsvProfile}}, {{"p.csv", "x,material\n0,rock\n"}}, "p.csv", 1, "header", "no column \"z\""},
        // profile geometry: crossing, too few vertices (vertex → CSV line or points entry)
        Case{"csv_crosses_itself", {{9, kCsvProfile}}, {{"p.csv", kCrossingRows}}, "p.csv", 2, "x,z", "crosses itself: the segment from (0, 10) to (10, 0) meets the segment from (10, 10) to (0, 0) (it starts on line 4)"},
        Case{"inline_crosses_itself",
             {{9, "points = [\n  [0.0, 10.0, \"rock\"],\n  [10.0, 0.0, \"rock\"],\n  [10.0, 10.0, \"rock\"],\n  [0.0, 0.0, \"\"],\n]"}},
             {}, "s.toml", 10, "profile.points[0]", "crosses itself: the segment from (0, 10) to (10, 0) meets the segment from (10, 10) to (0, 0) (it starts at profile.points[2])"},
        // [x, z] without a material: the last vertex only (it starts no segment)
        Case{"inline_two_values_not_last", {{9, "points = [[0.0, 10.0], [10.0, 0.0]]"}}, {}, "s.toml", 9, "profile.points[0]", "an array of 2 values"},
        Case{"inline_one_vertex", {{9, "points = [[0.0, 10.0, \"\"]]"}}, {}, "s.toml", 9, "profile.points", "1 vertex"},
        Case{"csv_one_vertex", {{9, kCsvProfile}}, {{"p.csv", "x,z,material\n\n# c\n0,10,\n"}}, "p.csv", 4, "profile", "1 vertex row"},
        // a slope listed from its source end but descending towards -x: the air is below it
        Case{"csv_air_below", {{9, kCsvProfile}}, {{"p.csv", "x,z,material\n# mirrored\n20,10,rock\n10,2,rock\n0,0,\n"}}, "p.csv", 3, "x,z", "the air below 100 %"},
        Case{"inline_air_below", {{9, "points = [[20.0, 10.0, \"rock\"], [0.0, 0.0, \"\"]]"}}, {}, "s.toml", 9, "profile.points[0]", "from x = 20 to 0 m"},
        Case{"inline_vertical_only", {{9, "points = [[5.0, 10.0, \"rock\"], [5.0, 0.0, \"\"]]"}}, {}, "s.toml", 9, "profile.points[0]", "vertical segments only, at x = 5 m"},
        // coordinates beyond 1e9 m (their squares overflowed: "vertical segments only")
        Case{"inline_huge_coordinate", {{9, "points = [[0.0, 10.0, \"rock\"], [2e200, 0.0, \"\"]]"}}, {}, "s.toml", 9, "profile.points[1]", "x = 2e+200 m"},
        Case{"csv_huge_coordinate", {{9, kCsvProfile}}, {{"p.csv", "x,z,material\n0,10,rock\n10,-1.5e9,rock\n20,0,\n"}}, "p.csv", 3, "z", "z = -1.5e+09 m"},
        Case{"inline_repeated_vertex", {{9, "points = [[0.0, 10.0, \"rock\"], [0.0, 10.0, \"rock\"], [20.0, 0.0, \"\"]]"}}, {}, "s.toml", 9, "profile.points[1]", "repeats"},
        Case{"profile_file_and_points", {{9, base_lines()[8] + "\n" + kCsvProfile}}, {}, "s.toml", 8, "profile.points", "both file and points"},
        // materials
        Case{"inline_material_undefined", {{9, "points = [[0.0, 10.0, \"rok\"], [20.0, 0.0, \"\"]]"}}, {}, "s.toml", 9, "profile.points[0]", "\"rok\""},
        Case{"inline_material_empty_not_last", {{9, "points = [[0.0, 10.0, \"\"], [10.0, 0.0, \"rock\"], [20.0, 0.0, \"\"]]"}}, {}, "s.toml", 9, "profile.points[0]", "\"\""},
        Case{"csv_material_undefined", {{9, kCsvProfile}}, {{"p.csv", "# comment\n\nx,z,material\n0,10,rock\n10,0,rok\n20,0,\n"}}, "p.csv", 5, "material", "\"rok\""},
        Case{"preset_unknown", {{12, "preset = \"talsu\""}}, {}, "s.toml", 12, "materials.rock.preset", "\"talsu\""},
        Case{"materials_file_bad_preset",
             {{2, "name = \"t\"\nmaterials_file = \"m.toml\""}, {12, "preset = \"x\""}},
             {{"m.toml", "[x]\nsource = \"s\"\nnormal_energy = 5.0\ntangential_energy = 50.0\nroughness = -1.0\n"}},
             "m.toml", 5, "x.roughness", "-1.0"},
        Case{"materials_file_unknown_key",
             {{2, "name = \"t\"\nmaterials_file = \"m.toml\""}, {12, "preset = \"x\""}},
             {{"m.toml", "[x]\nsource = \"s\"\nnormal_energy = 5.0\ntangential_energy = 50.0\nroughness = 1.0\ncolour = 1\n"}},
             "m.toml", 6, "x.colour", "an unknown key"},
        // shape factors 0.7 <= min <= max <= 2.0
        Case{"shape_below", {{18, "mass = 100.0\nshape_factor = [0.6, 1.0]"}}, {}, "s.toml", 19, "blocks.table[0].shape_factor", "[0.6, 1"},
        Case{"shape_min_above_max", {{18, "mass = 100.0\nshape_factor = [1.5, 1.2]"}}, {}, "s.toml", 19, "blocks.table[0].shape_factor", "[1.5, 1.2]"},
        Case{"shape_above", {{18, "mass = 100.0\nshape_factor = [1.0, 2.1]"}}, {}, "s.toml", 19, "blocks.table[0].shape_factor", "2.1]"},
        Case{"shape_one_number", {{18, "mass = 100.0\nshape_factor = 1.2"}}, {}, "s.toml", 19, "blocks.table[0].shape_factor", "1.2"},
        Case{"shape_three_values", {{18, "mass = 100.0\nshape_factor = [1.0, 1.2, 1.5]"}}, {}, "s.toml", 19, "blocks.table[0].shape_factor", "an array of 3 values"},
        Case{"shape_default_above", {{16, "[blocks]\nshape_factor = [1.0, 2.5]"}}, {}, "s.toml", 17, "blocks.shape_factor", "2.5]"},
        Case{"shape_csv", {{16, "[blocks]\nfile = \"b.csv\""}, {17, ""}, {18, ""}}, {{"b.csv", "mass,shape_min,shape_max\n100,1.0,1.5\n200,0.5,1.0\n"}}, "b.csv", 3, "shape_min", "0.5"},
        // blocks CSV
        Case{"blocks_csv_mass_negative", {{16, "[blocks]\nfile = \"b.csv\""}, {17, ""}, {18, ""}}, {{"b.csv", "mass\n-3\n"}}, "b.csv", 2, "mass", "-3"},
        Case{"blocks_csv_count_float", {{16, "[blocks]\nfile = \"b.csv\""}, {17, ""}, {18, ""}}, {{"b.csv", "mass,count\n100,1.5\n"}}, "b.csv", 2, "count", "\"1.5\""},
        Case{"blocks_csv_header_only", {{16, "[blocks]\nfile = \"b.csv\""}, {17, ""}, {18, ""}}, {{"b.csv", "id,volume\n"}}, "b.csv", 1, "blocks", "no block rows"},
        Case{"blocks_csv_truncated", {{16, "[blocks]\nfile = \"b.csv\""}, {17, ""}, {18, ""}}, {{"b.csv", "id,volume\na,1.0\nb\n"}}, "b.csv", 3, "volume", "1 of 2"},
        Case{"block_mass_and_volume", {{18, "mass = 100.0\nvolume = 1.0"}}, {}, "s.toml", 17, "blocks.table[0].volume", "both mass and volume"},
        Case{"block_duplicate_id", {{18, "mass = 100.0\nid = \"a\"\n[[blocks.table]]\nid = \"a\"\nmass = 5.0"}}, {}, "s.toml", 21, "blocks.table[1].id", "\"a\""},
        // "a" with count 2 is blocks a.1 and a.2: a row named a.1 clashes, in either order
        Case{"block_id_expanded_clash", {{18, "mass = 100.0\nid = \"a\"\ncount = 2\n[[blocks.table]]\nid = \"a.1\"\nmass = 5.0"}}, {}, "s.toml", 22, "blocks.table[1].id", "\"a.1\""},
        Case{"block_id_expanded_clash_after", {{18, "mass = 100.0\nid = \"a.2\"\n[[blocks.table]]\nid = \"a\"\ncount = 2\nmass = 5.0"}}, {}, "s.toml", 21, "blocks.table[1].id", "\"a\" with count 2, which gives block a.2"},
        Case{"blocks_csv_expanded_clash", {{16, "[blocks]\nfile = \"b.csv\""}, {17, ""}, {18, ""}}, {{"b.csv", "id,mass,count\nb,1000,2\nb.1,2000,1\n"}}, "b.csv", 3, "id", "\"b.1\""},
        // sources and observation lines inside the profile's horizontal extent [0, 20]
        Case{"source_outside", {{21, "x = -1.0"}}, {}, "s.toml", 21, "sources[0].x", "-1.0"},
        Case{"line_outside", {{26, "x = 25.0"}}, {}, "s.toml", 26, "observation_lines[0].x", "25.0"},
        Case{"line_duplicate_name", {{26, "x = 15.0\n[[observation_lines]]\nname = \"L\"\nx = 16.0"}}, {}, "s.toml", 28, "observation_lines[1].name", "\"L\""}),
    [](const ::testing::TestParamInfo<Case>& i) { return i.param.name; });

TEST(ScenarioReader, MissingScenarioFile) {
  TempDir dir;
  try {
    (void)load_scenario(dir.path() / "nope.toml", kRules);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), dir.path() / "nope.toml");
    EXPECT_EQ(e.line(), 0);
    EXPECT_EQ(e.field(), "file");
    EXPECT_EQ(e.found(), "no such file");
    EXPECT_EQ(std::string(e.what()),
              (dir.path() / "nope.toml").string() + ": file: found no such file, expected " + e.expected());
  }
}

// A value of 100 000 digits is echoed by its first 200 bytes and its length, not whole (a
// message of 100 kB); found() keeps it whole for a program that wants it.
TEST(ScenarioReader, AHugeValueIsShownByItsStartAndLength) {
  TempDir dir;
  Case c{"huge", {{16, "[blocks]\nfile = \"b.csv\""}, {17, ""}, {18, ""}}, {}, "", 0, "", ""};
  const std::string digits = "1" + std::string(99999, '0');  // 1e99999: not a finite number
  dir.write("b.csv", "mass\n" + digits + "\n");
  const auto scenario = dir.write("s.toml", scenario_text(c));
  try {
    (void)load_scenario(scenario, kRules);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.found(), "\"" + digits + "\"");
    const std::string what = e.what();
    EXPECT_LT(what.size(), 600u) << what.size();
    EXPECT_NE(what.find("found \"" + digits.substr(0, 199) + "… (100002 bytes in all), expected"),
              std::string::npos)
        << what;
  }
}

// The field and the expectation quote the input too: an unknown key of 100 000 letters, or a
// list of names to choose from, are shortened in the message as a found value is (found by
// fuzzing: a 2 MB rule-set path made a 2 MB message), and kept whole by field() and expected().
TEST(ScenarioReader, AHugeKeyOrExpectationIsShownByItsStartAndLength) {
  TempDir dir;
  const std::string key(100000, 'k');
  const auto scenario = dir.write("s.toml", pierre::test::base_with(6, "throws = 2\n" + key + " = 1"));
  try {
    (void)load_scenario(scenario, kRules);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "simulation." + key);
    const std::string what = e.what();
    EXPECT_LT(what.size(), 1000u) << what.size();
    EXPECT_NE(what.find(":7: simulation." + std::string(189, 'k') + "… (100011 bytes in all): found an unknown key"),
              std::string::npos)
        << what.substr(0, 400);
  }
  const pierre::io::InputError long_expectation("f.toml", 3, "x", "1", std::string(5000, 'e'));
  EXPECT_EQ(long_expectation.expected().size(), 5000u);
  EXPECT_LT(std::string(long_expectation.what()).size(), 1100u);
}

}  // namespace
