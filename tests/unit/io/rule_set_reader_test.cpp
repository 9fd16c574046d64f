// Barrier rule sets and class tables as data: the shipped files say what design-checks.md §1
// says (and carry their (verify) marks), the thesis-2015 file reproduces Table 4.1, a rule set
// written to a temporary TOML file is used by a scenario without recompiling (by path and by
// name), and every error in a rule file names the file, the line and the field.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "pierre/design/barrier_check.hpp"
#include "pierre/io/rule_set_reader.hpp"
#include "pierre/io/scenario_reader.hpp"
#include "test_files.hpp"

namespace {

using namespace pierre;
using io::InputError;
using test::TempDir;

const std::filesystem::path kRules = PIERRE_SOURCE_DIR "/rules";

TEST(ShippedRuleSets, Thesis2015IsSection47) {
  const auto r = io::load_rule_set("thesis-2015", kRules);
  EXPECT_EQ(r.name, "thesis-2015");
  EXPECT_DOUBLE_EQ(r.percentile, 95);
  EXPECT_EQ(r.governing, design::Governing::weibull);
  EXPECT_EQ(r.design_on, design::DesignOn::both);
  ASSERT_TRUE(r.gamma_F.value && r.gamma_M.value && r.gamma_h.value);  // given, not products
  EXPECT_DOUBLE_EQ(*r.gamma_F.value, 1.16);
  EXPECT_DOUBLE_EQ(*r.gamma_M.value, 1.05);
  EXPECT_DOUBLE_EQ(*r.gamma_h.value, 1.0);
  EXPECT_DOUBLE_EQ(r.gamma_E_MEL, 1.3);
  EXPECT_DOUBLE_EQ(r.gamma_E_SEL, 1.0);
  EXPECT_DOUBLE_EQ(r.free_board_abs, 0.0);
  EXPECT_DOUBLE_EQ(r.free_board_rel, 0.5);
  EXPECT_FALSE(r.gamma_d_MEL);
  EXPECT_FALSE(r.gamma_d_SEL);
  EXPECT_EQ(r.classes, "etag027-classes");
  EXPECT_FALSE(r.clauses.at("energy.mel").empty());
}

TEST(ShippedRuleSets, Thesis2015FileReproducesTable41) {
  const auto r = io::load_rule_set("thesis-2015", kRules);
  const auto c = io::load_energy_classes(r.classes, kRules);
  design::DesignInputs in;
  in.v_k = 24.9 / 1.16;
  in.h_k = 3.56;
  in.volume = 1.26;
  in.density = 2800;
  in.free_board_diameter = 1.2;
  const auto d = design::design_values(r, c, in);
  ASSERT_TRUE(d.ok()) << d.error;
  EXPECT_NEAR(d->m_d, 3704.4, 1e-9);
  EXPECT_NEAR(d->SEL_req_kJ, 1148.4, 0.05);
  EXPECT_NEAR(d->MEL_req_kJ, 1492.9, 0.05);
  EXPECT_NEAR(d->h_i, 4.16, 1e-12);
  // SEL 1500 ≥ 1148 kJ: ETAG class 7 (design-checks.md's eight-class table numbers it 6).
  EXPECT_EQ(d->energy_class->number, 7);
}

TEST(ShippedRuleSets, PeilaRonco2009PartsAndFactors) {
  const auto r = io::load_rule_set("peila-ronco-2009", kRules);
  EXPECT_EQ(r.governing, design::Governing::larger);
  EXPECT_EQ(r.design_on, design::DesignOn::mel);
  EXPECT_DOUBLE_EQ(r.gamma_E_MEL, 1.2);
  EXPECT_DOUBLE_EQ(r.gamma_E_SEL, 1.0);
  EXPECT_DOUBLE_EQ(r.free_board_abs, 0.5);
  EXPECT_DOUBLE_EQ(r.free_board_rel, 0.5);
  EXPECT_DOUBLE_EQ(*r.gamma_d_MEL, 1.3);
  EXPECT_DOUBLE_EQ(*r.gamma_d_SEL, 1.5);
  const auto q = design::data_quality_questions(r);
  ASSERT_EQ(q.size(), 3u);
  const std::map<std::string, std::string> worst = {
      {"trajectory", "literature"}, {"topography", "low"}, {"block_volume", "estimated"}};
  const std::map<std::string, std::string> best = {
      {"trajectory", "back-analysed"}, {"topography", "high"}, {"block_volume", "surveyed"}};
  EXPECT_DOUBLE_EQ(design::resolve_factor(r.gamma_F, worst)->value, 1.10 * 1.10);
  EXPECT_DOUBLE_EQ(design::resolve_factor(r.gamma_F, best)->value, 1.02 * 1.02);
  EXPECT_DOUBLE_EQ(design::resolve_factor(r.gamma_M, worst)->value, 1.10 * 1.0);
  EXPECT_DOUBLE_EQ(design::resolve_factor(r.gamma_M, best)->value, 1.02 * 1.0);
  EXPECT_DOUBLE_EQ(design::resolve_factor(r.gamma_h, worst)->value, 1.10 * 1.10);
}

// Every value design-checks.md marks (verify) carries the mark on its line.
TEST(ShippedRuleSets, VerifyMarksWhereTheSpecAsksForThem) {
  const std::string pr = test::read_file(kRules / "peila-ronco-2009.toml");
  std::istringstream in(pr);
  std::string l;
  int marked = 0;
  for (const char* key : {"gamma_h =", "gamma_E_MEL =", "gamma_E_SEL =", "gamma_d_MEL =",
                          "gamma_d_SEL =", "options =", "absolute =", "relative =", "value ="}) {
    in.clear();
    in.seekg(0);
    bool found = false;
    while (std::getline(in, l))
      if (l.rfind(key, 0) == 0) {
        found = true;
        EXPECT_NE(l.find("(verify"), std::string::npos) << l;
        ++marked;
      }
    EXPECT_TRUE(found) << key;
  }
  EXPECT_GE(marked, 11);  // three options lines
  const std::string classes = test::read_file(kRules / "etag027-classes.toml");
  std::istringstream cin(classes);
  while (std::getline(cin, l)) {
    if (l.rfind("mel =", 0) == 0 || l.rfind("sel =", 0) == 0 || l.rfind("A =", 0) == 0 ||
        l.rfind("B =", 0) == 0) {
      EXPECT_NE(l.find("(verify)"), std::string::npos) << l;
    }
  }
}

TEST(ShippedRuleSets, Etag027ClassTableWhole) {
  const auto t = io::load_energy_classes("etag027-classes", kRules);
  // ETAG 027's nine classes (Peila & Ronco 2009 Table 1): SEL = MEL / 3 from class 1 up, to
  // the kJ the table rounds to. design-checks.md §1 prints eight, without class 4.
  const double sel[] = {NAN, 85, 170, 330, 500, 660, 1000, 1500, 1500};
  const double mel[] = {100, 250, 500, 1000, 1500, 2000, 3000, 4500, 4500};
  ASSERT_EQ(t.classes.size(), 9u);
  for (int i = 0; i < 9; ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(t.classes[static_cast<std::size_t>(i)].number, i);
    EXPECT_DOUBLE_EQ(t.classes[static_cast<std::size_t>(i)].mel_kJ, mel[i]);
    if (i == 0)
      EXPECT_TRUE(std::isnan(t.classes[0].sel_kJ));
    else
      EXPECT_DOUBLE_EQ(t.classes[static_cast<std::size_t>(i)].sel_kJ, sel[i]);
    EXPECT_EQ(t.classes[static_cast<std::size_t>(i)].open_ended, i == 8);
  }
  ASSERT_TRUE(t.residual_height);
  EXPECT_DOUBLE_EQ(t.residual_height->a_min, 0.5);
  EXPECT_DOUBLE_EQ(t.residual_height->b_min, 0.3);
}

TEST(ShippedRuleSets, NamesListsTheBarrierRuleSetsOnly) {
  const auto names = io::barrier_rule_set_names(kRules);
  EXPECT_NE(std::find(names.begin(), names.end(), "thesis-2015"), names.end());
  EXPECT_NE(std::find(names.begin(), names.end(), "peila-ronco-2009"), names.end());
  EXPECT_EQ(std::find(names.begin(), names.end(), "etag027-classes"), names.end());
  EXPECT_EQ(std::find(names.begin(), names.end(), "materials"), names.end());
}

// A new code as data: consequence classes on the velocity factor (ONR 24810-like; the numbers
// are made up for the test).
const char* kOnrLike = R"([rule_set]
kind = "barrier"
title = "test code with consequence classes"
source = "a test"
percentile = 98.0
governing = "empirical"
design_on = "SEL"

[factors]
gamma_F = ["gamma_cc"]
gamma_M = 1.0
gamma_h = 1.25
gamma_E_MEL = 1.0
gamma_E_SEL = 2.0

[parts.gamma_cc]
symbol = "γCC"
choice = "consequence"
options = { CC1 = 1.0, CC2 = 1.1, CC3 = 1.2 }
source = "made up"

[free_board]
absolute = 1.0
relative = 0.0
)";

std::string with_barrier(const std::string& barrier) {
  return test::base() + "\n" + barrier;  // the base has 26 lines, then a blank one: line 28 on
}

TEST(TemporaryRuleSet, UsedByPathWithoutRecompiling) {
  TempDir dir;
  dir.write("onr-like.toml", kOnrLike);
  const auto s = dir.write("s.toml", with_barrier(R"([[barriers]]
name = "B1"
line = "L"
rules = "onr-like.toml"
design_block = { volume = 2.0, density = 2500.0 }
free_board_diameter = 1.0
data_quality = { consequence = "CC2" }
)"));
  const auto l = io::load_scenario(s, kRules);
  ASSERT_EQ(l.barriers.size(), 1u);
  const auto& r = l.barrier_rules[0];
  EXPECT_EQ(r.name, "onr-like");
  EXPECT_EQ(l.barrier_rules_files[0], dir.path() / "onr-like.toml");
  EXPECT_EQ(l.barrier_classes[0].name, "etag027-classes");  // from the rules folder
  design::DesignInputs in;
  in.v_k = 20;
  in.h_k = 2;
  in.volume = 2.0;
  in.density = 2500;
  in.free_board_diameter = 1.0;
  in.data_quality = l.barriers[0].data_quality;
  const auto d = design::design_values(r, l.barrier_classes[0], in);
  ASSERT_TRUE(d.ok()) << d.error;
  EXPECT_DOUBLE_EQ(d->v_d, 22.0);                       // γCC(CC2) = 1.1
  EXPECT_DOUBLE_EQ(d->E_d_kJ, 0.5 * 5000 * 22 * 22 / 1000);
  EXPECT_DOUBLE_EQ(d->SEL_req_kJ, 2 * d->E_d_kJ);        // 2420 kJ: above class 7's SEL
  EXPECT_EQ(d->energy_class->number, 8);
  EXPECT_DOUBLE_EQ(d->h_i, 2 * 1.25 + 1.0);
}

// design-checks.md §1 step 8 asks for a 90 % interval from at least 1000 resamples: the
// default, and a rule set may ask for a wider interval from more.
TEST(TemporaryRuleSet, BootstrapSizeDefaultsToTheSpecAndMayBeRaised) {
  TempDir dir;
  const auto plain = io::load_rule_set(dir.write("a.toml", kOnrLike).string(), kRules);
  EXPECT_EQ(plain.sample_confidence, 0.90);
  EXPECT_EQ(plain.sample_resamples, 1000u);
  std::string text = kOnrLike;
  text.replace(text.find("design_on"), 0, "sample_confidence = 0.95\nsample_resamples = 5000\n");
  const auto raised = io::load_rule_set(dir.write("b.toml", text).string(), kRules);
  EXPECT_EQ(raised.sample_confidence, 0.95);
  EXPECT_EQ(raised.sample_resamples, 5000u);
}

TEST(TemporaryRuleSet, UsedByNameFromAnotherRulesFolder) {
  TempDir rules, dir;
  rules.write("my-code.toml", kOnrLike);
  rules.write("etag027-classes.toml", test::read_file(kRules / "etag027-classes.toml"));
  const auto s = dir.write("s.toml", with_barrier(R"([[barriers]]
name = "B1"
line = "L"
rules = "my-code"
data_quality = { consequence = "CC3" }
)"));
  const auto l = io::load_scenario(s, rules.path());
  EXPECT_EQ(l.barrier_rules[0].name, "my-code");
  EXPECT_DOUBLE_EQ(design::resolve_factor(l.barrier_rules[0].gamma_F, l.barriers[0].data_quality)->value, 1.2);
}

// A rules folder of one's own without the default rule set: the error names the default that was
// looked for and how to get it there.
TEST(TemporaryRuleSet, AFolderWithoutTheDefaultSaysWhichWasLookedFor) {
  TempDir rules, dir;
  rules.write("materials.toml", test::read_file(kRules / "materials.toml"));
  const auto s = dir.write("s.toml", with_barrier("[[barriers]]\nname = \"B1\"\nline = \"L\"\n"));
  try {
    (void)io::load_scenario(s, rules.path());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "barriers[0].rules");
    EXPECT_EQ(e.found(), "nothing");
    EXPECT_NE(e.expected().find("the default rule set \"peila-ronco-2009\""), std::string::npos)
        << e.expected();
    EXPECT_NE(e.expected().find("it holds no barrier rule set"), std::string::npos)
        << e.expected();
  }
}

// A rule set of one's own with a TOML typo is not a barrier rule set, but it is the one the user
// may be looking for: the list says it was passed over, and at which line it does not parse.
TEST(TemporaryRuleSet, AFolderListsTheRuleFilesThatDoNotParse) {
  TempDir rules, dir;
  rules.write("materials.toml", test::read_file(kRules / "materials.toml"));
  rules.write("thesis-2015.toml", test::read_file(kRules / "thesis-2015.toml"));
  rules.write("my-code.toml", "[rule_set]\nkind = \"barrier\"\nname = \"my code\n");
  const auto s = dir.write("s.toml", with_barrier(
      "[[barriers]]\nname = \"B1\"\nline = \"L\"\nrules = \"my-cod\"\n"));
  try {
    (void)io::load_scenario(s, rules.path());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "barriers[0].rules");
    EXPECT_EQ(e.found(), "\"my-cod\"");
    EXPECT_NE(e.expected().find("its barrier rule sets: \"thesis-2015\"; not valid TOML, so not "
                                "looked at: my-code.toml (line 3: "),
              std::string::npos)
        << e.expected();
  }
}

// A rule set of another kind named as a barrier's: the error says what the file is and which
// barrier rule sets the folder holds, with how the folder was chosen.
TEST(TemporaryRuleSet, AQuarryRuleSetNamedForABarrierSaysWhatItIs) {
  TempDir dir;
  const auto s = dir.write("s.toml", with_barrier(
      "[[barriers]]\nname = \"B1\"\nline = \"L\"\nrules = \"quarry-thesis-2015\"\n"));
  try {
    (void)io::load_scenario(s, io::RulesFolder(kRules, "the rules folder given by --rules"));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "barriers[0].rules");
    EXPECT_EQ(e.found(), "\"quarry-thesis-2015\"");
    EXPECT_EQ(e.expected(),
              "a barrier rule set (" + (kRules / "quarry-thesis-2015.toml").string() +
                  " is a quarry rule set; the rules folder is " + kRules.string() +
                  " (the rules folder given by --rules; its barrier rule sets: "
                  "\"peila-ronco-2009\", \"thesis-2015\"))");
  }
}

TEST(TemporaryRuleSet, AnswerOutsideItsOptionsNamesThem) {
  TempDir dir;
  dir.write("onr-like.toml", kOnrLike);
  const auto s = dir.write("s.toml", with_barrier(R"([[barriers]]
name = "B1"
line = "L"
rules = "onr-like.toml"
data_quality = { consequence = "CC4" }
)"));
  try {
    (void)io::load_scenario(s, kRules);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), s);
    EXPECT_EQ(e.line(), 32);
    EXPECT_EQ(e.field(), "barriers[0].data_quality.consequence");
    EXPECT_EQ(e.found(), "\"CC4\"");
    EXPECT_NE(e.expected().find("\"CC1\" or \"CC2\" or \"CC3\""), std::string::npos) << e.expected();
  }
}

// ---- errors inside rule files ----

struct RuleCase {
  std::string name;
  std::string from, to;  // replace in kOnrLike
  long line;
  std::string field, found;
};
void PrintTo(const RuleCase& c, std::ostream* os) { *os << c.name; }

class RuleSetError : public ::testing::TestWithParam<RuleCase> {};

TEST_P(RuleSetError, NamesFileLineField) {
  const RuleCase& c = GetParam();
  std::string text = kOnrLike;
  const auto at = text.find(c.from);
  ASSERT_NE(at, std::string::npos) << c.from;
  text.replace(at, c.from.size(), c.to);
  TempDir dir;
  const auto f = dir.write("r.toml", text);
  try {
    (void)io::load_rule_set(f.string(), kRules);
    FAIL() << "no error for " << c.name;
  } catch (const InputError& e) {
    SCOPED_TRACE(e.what());
    EXPECT_EQ(e.file(), f);
    EXPECT_EQ(e.line(), c.line);
    EXPECT_EQ(e.field(), c.field);
    EXPECT_NE(e.found().find(c.found), std::string::npos) << e.found();
    EXPECT_FALSE(e.expected().empty());
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, RuleSetError,
    ::testing::Values(
        RuleCase{"wrong_kind", "kind = \"barrier\"", "kind = \"quarry\"", 2, "rule_set.kind", "\"quarry\""},
        RuleCase{"governing", "governing = \"empirical\"", "governing = \"median\"", 6, "rule_set.governing", "\"median\""},
        RuleCase{"design_on", "design_on = \"SEL\"", "design_on = \"sel\"", 7, "rule_set.design_on", "\"sel\""},
        RuleCase{"percentile", "percentile = 98.0", "percentile = 100.0", 5, "rule_set.percentile", "100"},
        RuleCase{"confidence", "design_on = \"SEL\"", "design_on = \"SEL\"\nsample_confidence = 0.5", 8, "rule_set.sample_confidence", "0.5"},
        RuleCase{"resamples", "design_on = \"SEL\"", "design_on = \"SEL\"\nsample_resamples = 999", 8, "rule_set.sample_resamples", "999"},
        // 99.9 % from the default 1000 resamples: half a replicate beyond each end.
        RuleCase{"confidence_for_resamples", "design_on = \"SEL\"", "design_on = \"SEL\"\nsample_confidence = 0.999", 8, "rule_set.sample_confidence", "0.999"},
        RuleCase{"unknown_part", "gamma_F = [\"gamma_cc\"]", "gamma_F = [\"gamma_xx\"]", 10, "factors.gamma_F", "\"gamma_xx\""},
        RuleCase{"factor_type", "gamma_h = 1.25", "gamma_h = \"1.25\"", 12, "factors.gamma_h", "\"1.25\""},
        RuleCase{"factor_zero", "gamma_E_SEL = 2.0", "gamma_E_SEL = 0.0", 14, "factors.gamma_E_SEL", "0.0"},
        // Below 1 a partial factor designs for less than the characteristic value.
        RuleCase{"factor_below_one", "gamma_h = 1.25", "gamma_h = 0.5", 12, "factors.gamma_h", "0.5"},
        RuleCase{"part_below_one", "CC2 = 1.1", "CC2 = 0.9", 19, "parts.gamma_cc.options.CC2", "0.9"},
        RuleCase{"part_both", "choice = \"consequence\"", "choice = \"consequence\"\nvalue = 1.0", 16, "parts.gamma_cc.value", "both"},
        RuleCase{"option_value", "CC2 = 1.1", "CC2 = -1.1", 19, "parts.gamma_cc.options.CC2", "-1.1"},
        RuleCase{"no_free_board", "[free_board]\nabsolute = 1.0\nrelative = 0.0\n", "", 0, "free_board", "nothing"},
        RuleCase{"unknown_key", "source = \"a test\"", "source = \"a test\"\nsourse = \"typo\"", 5, "rule_set.sourse", "unknown"},
        RuleCase{"unknown_clause", "[free_board]", "[clauses]\n\"energy.xyz\" = \"§1\"\n[free_board]", 23, "clauses.energy.xyz", "unknown check id"},
        RuleCase{"syntax", "gamma_M = 1.0", "gamma_M = = 1.0", 11, "TOML syntax", ""}),
    [](const auto& info) { return info.param.name; });

TEST(EnergyClassErrors, OrderAndOpenEnd) {
  TempDir dir;
  const std::string head = "[rule_set]\nkind = \"energy-classes\"\ntitle = \"t\"\nsource = \"s\"\n";
  const auto f1 = dir.write("c1.toml", head + "[[classes]]\nclass = 1\nmel = 200\n[[classes]]\nclass = 1\nmel = 300\n");
  try {
    (void)io::load_energy_classes(f1.string(), kRules);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 9);
    EXPECT_EQ(e.field(), "classes[1].class");
  }
  const auto f2 = dir.write("c2.toml", head + "[[classes]]\nclass = 1\nmel = 200\nopen_ended = true\n[[classes]]\nclass = 2\nmel = 300\n");
  try {
    (void)io::load_energy_classes(f2.string(), kRules);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 8);
    EXPECT_EQ(e.field(), "classes[0].open_ended");
  }
  const auto f3 = dir.write("c3.toml", head + "[[classes]]\nclass = 1\nmel = 200\n[[classes]]\nclass = 2\nmel = 150\n");
  try {
    (void)io::load_energy_classes(f3.string(), kRules);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 10);
    EXPECT_EQ(e.field(), "classes[1].mel");
  }
}

// Found by fuzzing: an SEL above its class's MEL was taken, and the first class's number was
// not bounded (2^32 wrapped to class 0, which a candidate then matched).
TEST(EnergyClassErrors, SelWithinMelAndRisingAndClassNumbersBounded) {
  TempDir dir;
  const std::string head = "[rule_set]\nkind = \"energy-classes\"\ntitle = \"t\"\nsource = \"s\"\n";
  auto error = [&](const std::string& name, const std::string& classes) -> InputError {
    try {
      (void)io::load_energy_classes(dir.write(name, head + classes).string(), kRules);
    } catch (const InputError& e) {
      return e;
    }
    ADD_FAILURE() << "no InputError for " << name;
    return InputError("", 0, "", "", "");
  };
  const InputError above = error("a.toml", "[[classes]]\nclass = 1\nmel = 250\nsel = 300\n");
  EXPECT_EQ(above.line(), 8);
  EXPECT_EQ(above.field(), "classes[0].sel");
  EXPECT_EQ(above.expected(), "an SEL <= the class's MEL (250 kJ)");
  const InputError falling = error(
      "f.toml", "[[classes]]\nclass = 1\nmel = 250\nsel = 85\n[[classes]]\nclass = 2\nmel = 500\n"
                "[[classes]]\nclass = 3\nmel = 1000\nsel = 80\n");
  EXPECT_EQ(falling.line(), 15);
  EXPECT_EQ(falling.expected(), "an SEL >= class 1's (85 kJ)");
  const InputError wrapped = error("w.toml", "[[classes]]\nclass = 4294967296\nmel = 100\n");
  EXPECT_EQ(wrapped.line(), 6);
  EXPECT_EQ(wrapped.field(), "classes[0].class");
  EXPECT_EQ(wrapped.found(), "4294967296");
  const InputError negative = error("n.toml", "[[classes]]\nclass = -1\nmel = 100\n");
  EXPECT_EQ(negative.field(), "classes[0].class");
  // The shipped table passes all of these.
  EXPECT_NO_THROW((void)io::load_energy_classes("etag027-classes", kRules));
}

}  // namespace
