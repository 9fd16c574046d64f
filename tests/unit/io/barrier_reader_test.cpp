// [[barriers]] in a scenario (docs/scenario-format.md): every field read, defaults, and every
// input error naming the file, the line, the field and the value found.
#include <gtest/gtest.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "pierre/io/scenario_reader.hpp"
#include "test_files.hpp"

namespace {

using namespace pierre;
using io::InputError;
using test::TempDir;

const std::filesystem::path kRules = PIERRE_SOURCE_DIR "/rules";

// The base scenario (26 lines, observation line "L"), a blank line 27, the barrier from line 28.
std::string with_barrier(const std::string& barrier) { return test::base() + "\n" + barrier; }

const char* kFull = R"([[barriers]]
name = "B1"
line = "L"
rules = "peila-ronco-2009"
design_block = { percentile = 90, density = 2700.0 }
free_board_diameter = 1.1
data_quality = { trajectory = "literature", topography = "high", block_volume = "estimated" }
acceptable_energy_exceedance = 0.001
acceptable_height_exceedance = 0.05
observed = "obs.csv"

[barriers.candidate]
energy_class = 5
mel = 3200.0
height = 5.0
elongation_mel = 6.0
elongation_sel = 4.0
distance_to_object = 9.0
residual_height = 2.0

[[barriers]]
name = "B2"
line = "L"
rules = "thesis-2015"
)";

TEST(BarrierReader, ReadsEveryField) {
  TempDir dir;
  dir.write("obs.csv", "speed_m_s,height_m,energy_kJ\n10.5,1.2,300\n,2.0,\n12.0,,410.5\n");
  const auto l = io::load_scenario(dir.write("s.toml", with_barrier(kFull)), kRules);
  ASSERT_EQ(l.barriers.size(), 2u);
  ASSERT_EQ(l.barrier_rules.size(), 2u);
  ASSERT_EQ(l.barrier_classes.size(), 2u);
  ASSERT_EQ(l.barrier_observed.size(), 2u);
  const design::BarrierSpec& b = l.barriers[0];
  EXPECT_EQ(b.name, "B1");
  EXPECT_EQ(b.line, "L");
  EXPECT_EQ(b.rules, "peila-ronco-2009");
  EXPECT_EQ(b.design_block.kind, design::DesignBlock::Kind::percentile);
  EXPECT_DOUBLE_EQ(b.design_block.percentile, 90);
  EXPECT_DOUBLE_EQ(b.design_block.density, 2700);
  EXPECT_DOUBLE_EQ(*b.free_board_diameter, 1.1);
  EXPECT_EQ(b.data_quality.at("trajectory"), "literature");
  EXPECT_EQ(b.data_quality.at("block_volume"), "estimated");
  EXPECT_DOUBLE_EQ(*b.acceptable_energy_exceedance, 0.001);
  EXPECT_DOUBLE_EQ(*b.acceptable_height_exceedance, 0.05);
  ASSERT_TRUE(b.candidate);
  EXPECT_EQ(*b.candidate->energy_class, 5);
  EXPECT_DOUBLE_EQ(*b.candidate->mel_kJ, 3200);
  EXPECT_FALSE(b.candidate->sel_kJ);
  EXPECT_DOUBLE_EQ(*b.candidate->height, 5.0);
  EXPECT_DOUBLE_EQ(*b.candidate->elongation_mel, 6.0);
  EXPECT_DOUBLE_EQ(*b.candidate->elongation_sel, 4.0);
  EXPECT_DOUBLE_EQ(*b.candidate->distance_to_object, 9.0);
  EXPECT_DOUBLE_EQ(*b.candidate->residual_height, 2.0);
  EXPECT_EQ(b.observed_file, "obs.csv");
  ASSERT_TRUE(l.barrier_observed[0]);
  EXPECT_EQ(l.barrier_observed[0]->speed, (std::vector<double>{10.5, 12.0}));
  EXPECT_EQ(l.barrier_observed[0]->height, (std::vector<double>{1.2, 2.0}));
  EXPECT_EQ(l.barrier_observed[0]->energy, (std::vector<double>{300e3, 410.5e3}));  // J
  EXPECT_EQ(l.barrier_rules[0].name, "peila-ronco-2009");
  EXPECT_EQ(l.barrier_classes[0].classes.size(), 9u);  // ETAG 027 classes 0 to 8
  // The second: defaults.
  const design::BarrierSpec& c = l.barriers[1];
  EXPECT_EQ(l.barrier_rules[1].name, "thesis-2015");
  EXPECT_EQ(c.design_block.kind, design::DesignBlock::Kind::largest);
  EXPECT_FALSE(c.free_board_diameter);
  EXPECT_FALSE(c.candidate);
  EXPECT_TRUE(c.data_quality.empty());
  EXPECT_FALSE(l.barrier_observed[1]);
}

// The observed sample the reader takes from `csv`, written as obs.csv beside a barrier scenario.
design::ObservedSample observed_from(TempDir& dir, const std::string& csv) {
  dir.write("obs.csv", csv);
  const auto l = io::load_scenario(dir.write("s.toml", with_barrier(kFull)), kRules);
  if (!l.barrier_observed[0]) throw std::runtime_error("no observed sample read");
  return *l.barrier_observed[0];
}

// The observed columns as a spreadsheet heads them: speed and height without their unit, any
// case. The values are the same as under the canonical header.
TEST(BarrierReader, ObservedColumnsMayGoWithoutUnitOrCase) {
  TempDir dir;
  const auto o = observed_from(dir, "Speed,HEIGHT,Energy_KJ\n10.5,1.2,300\n,2.0,\n12.0,,410.5\n");
  EXPECT_EQ(o.speed, (std::vector<double>{10.5, 12.0}));
  EXPECT_EQ(o.height, (std::vector<double>{1.2, 2.0}));
  EXPECT_EQ(o.energy, (std::vector<double>{300e3, 410.5e3}));  // J
}

// A field record names its blocks and adds remarks: an id and a note column are read and left
// alone (they were refused as unknown columns: new-user review). They alone are no record.
TEST(BarrierReader, ObservedRecordsMayNameTheirBlocks) {
  TempDir dir;
  const auto o = observed_from(
      dir, "id,Block_ID,speed,height_m,Comment\n1,B1,10.5,1.2,\"rolled, then flew\"\n2,B2,12.0,2.0,\n");
  EXPECT_EQ(o.speed, (std::vector<double>{10.5, 12.0}));
  EXPECT_EQ(o.height, (std::vector<double>{1.2, 2.0}));
  EXPECT_TRUE(o.energy.empty());
  dir.write("obs.csv", "id,note\nB1,seen\n");
  try {
    (void)io::load_scenario(dir.path() / "s.toml", kRules);
    ADD_FAILURE() << "a record without values was read";
  } catch (const io::InputError& e) {
    EXPECT_EQ(e.field(), "header");
    EXPECT_NE(e.expected().find("speed_m_s, height_m and/or energy_kJ"), std::string::npos) << e.what();
  }
}

TEST(BarrierReader, DefaultRuleSetIsPeilaRonco) {
  TempDir dir;
  const auto l = io::load_scenario(dir.write("s.toml", with_barrier(R"([[barriers]]
name = "B"
line = "L"
design_block = { volume = 1.26, density = 2800 }
data_quality = { trajectory = "back-analysed", topography = "low", block_volume = "surveyed" }
)")), kRules);
  EXPECT_EQ(l.barriers[0].rules, "peila-ronco-2009");
  EXPECT_EQ(l.barrier_rules[0].name, "peila-ronco-2009");
  EXPECT_EQ(l.barriers[0].design_block.kind, design::DesignBlock::Kind::given);
  EXPECT_DOUBLE_EQ(l.barriers[0].design_block.volume, 1.26);
}

// A design block's density in t/m³ is noted as the blocks' densities are: its energy would be a
// thousandth of the real one.
TEST(BarrierReader, ADesignBlockDensityOutsideRockIsNoted) {
  TempDir dir;
  auto notes = [&](const std::string& design_block) {
    const std::string barrier = "[[barriers]]\nname = \"B\"\nline = \"L\"\nrules = \"thesis-2015\"\n"
                                "design_block = " + design_block + "\n";
    return io::load_scenario(dir.write("s.toml", with_barrier(barrier)), kRules).notes;
  };
  const auto slip = notes("{ volume = 1.26, density = 2.8 }");
  ASSERT_EQ(slip.size(), 1u);
  EXPECT_EQ(slip[0].line, 32);
  EXPECT_EQ(slip[0].field, "barriers[0].design_block.density");
  EXPECT_EQ(slip[0].text.rfind("the design block's density 2.8 kg/m³ is outside the densities of rock", 0), 0u)
      << slip[0].text;
  EXPECT_EQ(notes("{ percentile = 90, density = 0.9 }").size(), 1u);  // a percentile's density too
  EXPECT_TRUE(notes("{ percentile = 90, density = 2700.0 }").empty());
}

// A barrier's numbers in the smaller unit (mm for m, J for kJ, km/h for m/s) pass every range
// check and change the design a thousandfold: each noted at its value, with what it would be.
TEST(BarrierReader, ValuesInTheSmallerUnitAreNoted) {
  TempDir dir;
  auto notes = [&](const std::string& fields) {
    const std::string barrier =
        "[[barriers]]\nname = \"B\"\nline = \"L\"\nrules = \"thesis-2015\"\n" + fields + "\n";
    return io::load_scenario(dir.write("s.toml", with_barrier(barrier)), kRules).notes;
  };
  // The kFull barrier's values, in m and kJ: none.
  EXPECT_TRUE(notes("free_board_diameter = 1.1\n[barriers.candidate]\nmel = 3200.0\nheight = 5.0\n"
                    "elongation_mel = 6.0\nelongation_sel = 4.0")
                  .empty());
  const auto slips = notes("free_board_diameter = 1100.0\n[barriers.candidate]\nmel = 3.2e6\n"
                           "height = 5000.0\nelongation_mel = 6000.0\nelongation_sel = 4000.0");
  ASSERT_EQ(slips.size(), 5u);
  EXPECT_EQ(slips[0].line, 32);
  EXPECT_EQ(slips[0].field, "barriers[0].free_board_diameter");
  EXPECT_EQ(slips[0].text,
            "the free-board diameter 1100 m is more than 10 m, the diameter of a block of over "
            "1 000 t: it is read in m; if it was meant in mm, it is 1.1 m");
  EXPECT_EQ(slips[1].field, "barriers[0].candidate.mel");
  EXPECT_EQ(slips[1].line, 34);
  EXPECT_EQ(slips[1].text,
            "the candidate's MEL 3200000 kJ is more than 30000 kJ (the largest class of "
            "etag027-classes: MEL > 4500 kJ): it is read in kJ; if it was meant in J, it is 3200 kJ. "
            "If it is meant, confirm it in the scenario: [confirmed] \"barriers[0].candidate.mel\" = "
            "3200000");
  EXPECT_EQ(slips[2].field, "barriers[0].candidate.height");
  EXPECT_NE(slips[2].text.find("if it was meant in mm, it is 5 m"), std::string::npos) << slips[2].text;
  EXPECT_EQ(slips[3].field, "barriers[0].candidate.elongation_mel");
  EXPECT_EQ(slips[4].field, "barriers[0].candidate.elongation_sel");
  // The limits themselves are taken as they are; an SEL alone is judged as the MEL would be.
  EXPECT_TRUE(notes("free_board_diameter = 10.0\n[barriers.candidate]\nmel = 30000.0\nheight = 20.0\n"
                    "elongation_mel = 30.0")
                  .empty());
  const auto sel = notes("[barriers.candidate]\nsel = 1e6");
  ASSERT_EQ(sel.size(), 1u);
  EXPECT_EQ(sel[0].field, "barriers[0].candidate.sel");
  // Beside a SEL, the largest class's SEL; both in J, both noted (the SEL was left to the next run).
  EXPECT_NE(sel[0].text.find("(the largest class of etag027-classes: SEL > 1500 kJ)"), std::string::npos)
      << sel[0].text;
  EXPECT_EQ(notes("[barriers.candidate]\nmel = 45000.0\nsel = 35000.0").size(), 2u);
  // The capacities so noted doubt the lines that pass on them (design::doubt_passes); the
  // elongations (a larger one only makes the check stricter) doubt none.
  const auto l = io::load_scenario(
      dir.write("s.toml", with_barrier("[[barriers]]\nname = \"B\"\nline = \"L\"\nrules = "
                                       "\"thesis-2015\"\n[barriers.candidate]\nmel = 3.2e6\n"
                                       "sel = 900.0\nheight = 5000.0\nelongation_mel = 6000.0\n")),
      kRules);
  std::vector<std::string> doubted;
  for (const auto& n : l.notes) {
    if (!n.doubt) continue;
    EXPECT_EQ(n.doubt->field, n.field);
    EXPECT_EQ(n.doubt->subject, "B");
    doubted.push_back(n.doubt->field + ":" + fmt::format("{}", fmt::join(n.doubt->ids, ",")));
  }
  EXPECT_EQ(doubted, (std::vector<std::string>{
                         "barriers[0].candidate.mel:energy.mel,exceedance.energy",
                         "barriers[0].candidate.height:height.interception,exceedance.height"}));
}

// An acceptable probability is a fraction, and every output shows it in %: 0.5 copied from a
// report's "0.5 %" is 50 %, under which the exceedance line passes. Above 10 % it is noted, and
// its own exceedance line cannot PASS; 10 % itself, and the usual 0.1 % to 5 %, are taken.
TEST(BarrierReader, AnAcceptableProbabilityInPercentIsNoted) {
  TempDir dir;
  auto notes = [&](const std::string& fields) {
    const std::string barrier = "[[barriers]]\nname = \"B\"\nline = \"L\"\nrules = \"thesis-2015\"\n" +
                                fields + "\n[barriers.candidate]\nmel = 3200.0\nheight = 5.0\n";
    return io::load_scenario(dir.write("s.toml", with_barrier(barrier)), kRules).notes;
  };
  EXPECT_TRUE(notes("acceptable_energy_exceedance = 0.001\nacceptable_height_exceedance = 0.1").empty());
  const auto slips = notes("acceptable_energy_exceedance = 0.5\nacceptable_height_exceedance = 0.25");
  ASSERT_EQ(slips.size(), 2u);
  EXPECT_EQ(slips[0].field, "barriers[0].acceptable_energy_exceedance");
  EXPECT_EQ(slips[0].line, 32);
  EXPECT_TRUE(slips[0].text.starts_with("an acceptable probability of 0.5 is 50 %: it is a fraction "
                                        "(0.01 is 1 %); if it was meant in %, it is 0.005"))
      << slips[0].text;
  ASSERT_TRUE(slips[0].doubt && slips[1].doubt);
  EXPECT_EQ(slips[0].doubt->subject, "B");
  EXPECT_EQ(slips[0].doubt->ids, std::vector<std::string>{"exceedance.energy"});
  EXPECT_EQ(slips[0].doubt->value, 0.5);
  EXPECT_EQ(slips[1].field, "barriers[0].acceptable_height_exceedance");
  EXPECT_EQ(slips[1].doubt->ids, std::vector<std::string>{"exceedance.height"});
}

TEST(BarrierReader, ObservedColumnsInTheSmallerUnitAreNoted) {
  TempDir dir;
  const auto obs = dir.write("obs.csv",
                             "speed_m_s,height_m,energy_kJ\n54.0,1.2,300\n72.0,150,410\n90.0,2.0,4.1e5\n");
  const std::string barrier =
      "[[barriers]]\nname = \"B\"\nline = \"L\"\nrules = \"thesis-2015\"\nobserved = \"obs.csv\"\n";
  const auto notes = io::load_scenario(dir.write("s.toml", with_barrier(barrier)), kRules).notes;
  ASSERT_EQ(notes.size(), 3u);
  EXPECT_EQ(notes[0].file, obs);
  EXPECT_EQ(notes[0].line, 3);  // 54 km/h is 15 m/s, a speed a block has: not noted
  EXPECT_EQ(notes[0].field, "speed_m_s");
  EXPECT_EQ(notes[0].text,
            "speed_m_s 72 m/s (and 1 more rows like it) is more than 60 m/s, far faster than "
            "blocks cross a line on a slope: the column is read in m/s; if it is in km/h, 72 is "
            "20 m/s");
  EXPECT_EQ(notes[1].line, 3);
  EXPECT_NE(notes[1].text.find("if it is in cm, 150 is 1.5 m"), std::string::npos) << notes[1].text;
  EXPECT_EQ(notes[2].line, 4);
  EXPECT_NE(notes[2].text.find("if it is in J, 410000 is 410 kJ"), std::string::npos) << notes[2].text;
}

TEST(BarrierReader, NoBarriersNoVectors) {
  TempDir dir;
  const auto l = io::load_scenario(dir.write("s.toml", test::base()), kRules);
  EXPECT_TRUE(l.barriers.empty());
  EXPECT_TRUE(l.barrier_rules.empty());
}

struct Case {
  std::string name;
  std::string barrier;  // from line 28
  std::vector<std::pair<std::string, std::string>> files;
  std::string file;  // named by the error ("" = the scenario)
  long line;
  std::string field, found, expected;  // found and expected: substrings
};
void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

class BarrierError : public ::testing::TestWithParam<Case> {};

TEST_P(BarrierError, NamesFileLineFieldFoundExpected) {
  const Case& c = GetParam();
  TempDir dir;
  const auto s = dir.write("s.toml", with_barrier(c.barrier));
  for (const auto& [n, t] : c.files) dir.write(n, t);
  try {
    (void)io::load_scenario(s, kRules);
    FAIL() << "no InputError for " << c.name;
  } catch (const InputError& e) {
    SCOPED_TRACE(e.what());
    EXPECT_EQ(e.file(), c.file.empty() ? s : dir.path() / c.file);
    EXPECT_EQ(e.line(), c.line);
    EXPECT_EQ(e.field(), c.field);
    EXPECT_NE(e.found().find(c.found), std::string::npos) << "found: " << e.found();
    EXPECT_NE(e.expected().find(c.expected), std::string::npos) << "expected: " << e.expected();
  }
}

const std::string kHead = "[[barriers]]\nname = \"B\"\nline = \"L\"\n";           // lines 28-30
const std::string kThesis = kHead + "rules = \"thesis-2015\"\n";                     // line 31
// A barrier rule set of the file's own, its [rule_set] on lines 1-7 (line 8 may name classes).
const char* const kRuleSet = R"([rule_set]
kind = "barrier"
title = "t"
source = "s"
percentile = 95
governing = "weibull"
design_on = "both"
)";
const char* const kRuleSetRest = R"(
[factors]
gamma_F = 1.0
gamma_M = 1.0
gamma_h = 1.0
gamma_E_MEL = 1.0
gamma_E_SEL = 1.0

[free_board]
absolute = 0.0
relative = 0.5
)";
const std::string kPR = kHead + "data_quality = { trajectory = \"literature\", topography = \"low\", block_volume = \"surveyed\" }\n";  // 31

INSTANTIATE_TEST_SUITE_P(
    Cases, BarrierError,
    ::testing::Values(
        Case{"unknown_line", "[[barriers]]\nname = \"B\"\nline = \"Screen 9\"\n", {}, "", 30,
             "barriers[0].line", "\"Screen 9\"", "\"L\""},
        Case{"no_name", "[[barriers]]\nline = \"L\"\n", {}, "", 28, "barriers[0].name", "nothing", "name"},
        Case{"duplicate_name", kThesis + "[[barriers]]\nname = \"B\"\nline = \"L\"\nrules = \"thesis-2015\"\n", {}, "", 33,
             "barriers[1].name", "\"B\"", "not used by another barrier"},
        Case{"unknown_key", kThesis + "heigth = 3.0\n", {}, "", 32, "barriers[0].heigth", "unknown key", "design_block"},
        Case{"unknown_rules", kHead + "rules = \"etag-2099\"\n", {}, "", 31, "barriers[0].rules",
             "\"etag-2099\"", "thesis-2015"},
        // a file of rules/ of another kind: said at the scenario's line, not as an unknown key there
        Case{"rules_materials", kHead + "rules = \"materials\"\n", {}, "", 31, "barriers[0].rules",
             "\"materials\"", "materials.toml is a materials file"},
        Case{"rules_quarry", kHead + "rules = \"quarry-thesis-2015\"\n", {}, "", 31, "barriers[0].rules",
             "\"quarry-thesis-2015\"", "is a quarry rule set"},
        Case{"rules_classes", kHead + "rules = \"etag027-classes\"\n", {}, "", 31, "barriers[0].rules",
             "\"etag027-classes\"", "is an energy class table"},
        Case{"rules_path_missing", kHead + "rules = \"nothere.toml\"\n", {}, "", 31, "barriers[0].rules",
             "\"nothere.toml\"", "path"},
        Case{"rules_file_broken", kHead + "rules = \"r.toml\"\n",
             {{"r.toml", "[rule_set]\nkind = \"barrier\"\ntitle = 3\n"}}, "r.toml", 3, "rule_set.title", "3", "string"},
        Case{"missing_answer", kHead + "data_quality = { trajectory = \"literature\", topography = \"low\" }\n", {}, "", 31,
             "barriers[0].data_quality.block_volume", "nothing", "\"surveyed\""},
        // Every unanswered question at once (a new user met them one run at a time).
        Case{"no_data_quality", kHead, {}, "", 28, "barriers[0].data_quality",
             "no answer to block_volume, topography and trajectory",
             "block_volume = \"estimated\" or \"surveyed\"; topography = \"high\" or \"low\"; "
             "trajectory = \"back-analysed\" or \"literature\""},
        Case{"one_question_unanswered", kHead + "data_quality = { trajectory = \"literature\", topography = \"low\" }\n",
             {}, "", 31, "barriers[0].data_quality.block_volume", "nothing", "\"surveyed\""},
        Case{"wrong_answer", kHead + "data_quality = { trajectory = \"guess\", topography = \"low\", block_volume = \"surveyed\" }\n", {}, "", 31,
             "barriers[0].data_quality.trajectory", "\"guess\"", "\"back-analysed\" or \"literature\""},
        Case{"unasked_question", kThesis + "data_quality = { trajectory = \"literature\" }\n", {}, "", 32,
             "barriers[0].data_quality.trajectory", "does not ask", "asks none"},
        Case{"design_block_word", kThesis + "design_block = \"biggest\"\n", {}, "", 32, "barriers[0].design_block",
             "\"biggest\"", "largest"},
        Case{"design_block_both", kThesis + "design_block = { percentile = 95, volume = 1.0 }\n", {}, "", 32,
             "barriers[0].design_block", "both", "largest"},
        Case{"design_block_no_density", kThesis + "design_block = { volume = 1.0 }\n", {}, "", 32,
             "barriers[0].design_block.density", "nothing", "density"},
        Case{"design_block_percentile", kThesis + "design_block = { percentile = 0 }\n", {}, "", 32,
             "barriers[0].design_block.percentile", "0", "(0, 100]"},
        // Found by fuzzing: { volume = 1e300, density = 1e300 } was read as a block of infinite
        // mass, where a block of the table that heavy is refused.
        Case{"design_block_too_heavy", kThesis + "design_block = { volume = 2.0, density = 1e8 }\n", {}, "", 32,
             "barriers[0].design_block.volume", "2.0", "here 2 m³ × density 1e+08 kg/m³ = 2e+08 kg"},
        Case{"free_board_negative", kThesis + "free_board_diameter = -1.0\n", {}, "", 32,
             "barriers[0].free_board_diameter", "-1.0", "> 0"},
        Case{"class_unknown", kThesis + "[barriers.candidate]\nenergy_class = 9\n", {}, "", 33,
             "barriers[0].candidate.energy_class", "9", "0, 1, 2, 3, 4, 5, 6, 7, 8"},
        Case{"class_open_ended", kThesis + "[barriers.candidate]\nenergy_class = 8\nmel = 6000.0\n", {}, "", 33,
             "barriers[0].candidate.energy_class", "8", "mel and sel"},
        Case{"class_float", kThesis + "[barriers.candidate]\nenergy_class = 5.0\n", {}, "", 33,
             "barriers[0].candidate.energy_class", "5.0", "integer"},
        Case{"sel_above_mel", kThesis + "[barriers.candidate]\nmel = 100.0\nsel = 5000.0\n", {}, "", 34,
             "barriers[0].candidate.sel", "5000.0", "SEL <= the declared MEL (100 kJ"},
        Case{"candidate_empty", kThesis + "[barriers.candidate]\ndistance_to_object = 5.0\n", {}, "", 32,
             "barriers[0].candidate.energy_class", "nothing to check", "height"},
        Case{"candidate_height", kThesis + "[barriers.candidate]\nheight = 0\n", {}, "", 33,
             "barriers[0].candidate.height", "0", "> 0"},
        Case{"residual_above_height", kThesis + "[barriers.candidate]\nheight = 4.0\nresidual_height = 5.0\n", {}, "", 34,
             "barriers[0].candidate.residual_height", "5.0", "<= the height"},
        Case{"candidate_unknown_key", kThesis + "[barriers.candidate]\nMEL = 3000.0\n", {}, "", 33,
             "barriers[0].candidate.MEL", "unknown key", "mel"},
        Case{"acceptable_range", kThesis + "acceptable_height_exceedance = 5.0\n[barriers.candidate]\nheight = 4.0\n", {}, "", 32,
             "barriers[0].acceptable_height_exceedance", "5.0", "(0, 1)"},
        Case{"acceptable_without_candidate", kThesis + "acceptable_energy_exceedance = 0.01\n", {}, "", 32,
             "barriers[0].acceptable_energy_exceedance", "0.01", "candidate"},
        Case{"observed_missing", kThesis + "observed = \"none.csv\"\n", {}, "", 32, "barriers[0].observed",
             "\"none.csv\" (no such file", "readable CSV file of observed crossings"},
        Case{"observed_column", kThesis + "observed = \"o.csv\"\n", {{"o.csv", "velocity,height\n1,2\n"}}, "o.csv", 1,
             "header", "velocity", "speed_m_s"},
        // an energy keeps its unit in its name: J or kJ is the slip that matters
        Case{"observed_energy_unit", kThesis + "observed = \"o.csv\"\n", {{"o.csv", "speed,energy\n1,2\n"}}, "o.csv", 1,
             "header", "\"energy\"", "energy_kJ"},
        Case{"observed_value", kThesis + "observed = \"o.csv\"\n", {{"o.csv", "speed_m_s,height_m\n10,1\n-3,2\n"}}, "o.csv", 3,
             "speed_m_s", "-3", ">= 0"},
        Case{"observed_text", kThesis + "observed = \"o.csv\"\n", {{"o.csv", "energy_kJ\n10\nabc\n"}}, "o.csv", 3,
             "energy_kJ", "abc", "number"},
        Case{"pr_ok_but_bad_rules_type", kPR + "rules = 5\n", {}, "", 32, "barriers[0].rules", "5", "string"},
        // a class table neither beside the rule set nor in the rules folder: said at the rule
        // file's `classes` line (it had no line), or at its [rule_set] when the default is meant
        Case{"classes_missing", kHead + "rules = \"r.toml\"\n",
             {{"r.toml", std::string(kRuleSet) + "classes = \"etag-1999\"\n" + kRuleSetRest}}, "r.toml", 8,
             "rule_set.classes", "\"etag-1999\"", "an energy class table etag-1999.toml beside the rule set or in "}),
    [](const auto& info) { return info.param.name; });

// The rules folder's file missing names the folder as it was chosen: --rules or $PIERRE_RULES
// (app::rules_folder gives `how`), like the report layout's message names $PIERRE_TEMPLATES.
TEST(BarrierReader, AFileTheRulesFolderLacksSaysHowTheFolderWasChosen) {
  TempDir dir, rules;
  // A rules folder holding the thesis's rule set but not the class table it names.
  const std::string thesis = test::read_file(kRules / "thesis-2015.toml");
  rules.write("thesis-2015.toml", thesis);
  // The line of `classes = "etag027-classes"` in it, counted from the file.
  const auto at = thesis.find("\nclasses = \"etag027-classes\"");
  ASSERT_NE(at, std::string::npos);
  const long classes_line = 2 + std::count(thesis.begin(), thesis.begin() + static_cast<std::ptrdiff_t>(at), '\n');
  rules.write("materials.toml", test::read_file(kRules / "materials.toml"));
  const io::RulesFolder given(rules.path(), "the rules folder given by --rules");
  try {
    (void)io::load_scenario(dir.write("s.toml", with_barrier(kThesis)), given);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), rules.path() / "thesis-2015.toml");
    EXPECT_EQ(e.line(), classes_line);
    EXPECT_EQ(e.field(), "rule_set.classes");
    EXPECT_EQ(e.found(), "\"etag027-classes\"");
    EXPECT_EQ(e.expected(), "an energy class table etag027-classes.toml beside the rule set or in " +
                                rules.path().string() + " (the rules folder given by --rules)");
    EXPECT_EQ(std::string(e.what()), (rules.path() / "thesis-2015.toml").string() + ":" +
                                         std::to_string(classes_line) +
                                         ": rule_set.classes: found \"etag027-classes\", expected " +
                                         e.expected());
  }
  // A rule set that names no class table means the default: said at its [rule_set] line.
  dir.write("r.toml", std::string(kRuleSet) + kRuleSetRest);
  try {
    (void)io::load_scenario(dir.write("s.toml", with_barrier(kHead + "rules = \"r.toml\"\n")), given);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              (dir.path() / "r.toml").string() +
                  ":1: rule_set.classes: found \"etag027-classes\" (the default: [rule_set] names no "
                  "classes), expected an energy class table etag027-classes.toml beside the rule set or in " +
                  rules.path().string() + " (the rules folder given by --rules)");
  }
  // A folder that is not there: the materials file's message says it, and where it came from.
  const std::string base = test::base_with(12, "preset = \"talus\"");
  const std::filesystem::path none = dir.path() / "nonexistent";
  try {
    (void)io::load_scenario(dir.write("s.toml", base), io::RulesFolder(none, "the rules folder given by --rules"));
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              (none / "materials.toml").string() +
                  ": file: found no such file, expected a readable materials file (TOML) in " +
                  none.string() + " (the rules folder given by --rules; no such folder)");
  }
}

}  // namespace
