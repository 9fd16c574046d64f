// The [[quarries]] part of a scenario and the quarry rule sets (docs/quarry.md): what is read,
// and every error with its file, line, field, found and expected.
#include "pierre/io/quarry_reader.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "test_files.hpp"

namespace pierre::io {
namespace {

namespace fs = std::filesystem;
const fs::path kRules = fs::path(PIERRE_SOURCE_DIR) / "rules";

std::vector<model::Material> materials() {
  model::Material face, floor;
  face.name = "face";
  face.normal_energy = 5, face.tangential_energy = 50, face.roughness = 0.65;
  floor = face;
  floor.name = "floor";
  floor.roughness = 0.35;
  return {face, floor};
}

sim::SimulationSettings settings() {
  sim::SimulationSettings s;
  s.seed = 100;
  s.throws = 10;
  return s;
}

const std::string kSection = R"([[quarries]]
name = "Preg 1"
group = "Preg"
bench_width = 12.0
exceedance = [0.05, 0.01, 0.001]

[quarries.profile]
points = [[0.0, 20.0, "floor"], [10.0, 20.0, "face"], [20.0, 0.0, "floor"], [90.0, 0.0, ""]]

[quarries.blocks]
density = 2800.0
[[quarries.blocks.table]]
id = "P1"
mass = 140.0
[[quarries.blocks.table]]
id = "P2"
mass = 8130.0
count = 2

[[quarries.sources]]
x = 10.3
z = 20.5
vx = 0.5

[[quarries.work_areas]]
name = "crusher"
distance = 40.0

[quarries.observed]
source = "Table 6.2, 6.3"
count = 25
runout = { p50 = 10.5, p95 = 15.8, max = 17.0 }
first_impact = { p50 = 1.0, p95 = 3.8, max = 4.3 }
)";

// The section with line `n` (1-based) replaced.
std::string section_with(int n, const std::string& text) {
  std::istringstream in(kSection);
  std::string line, out;
  for (int k = 1; std::getline(in, line); ++k) out += (k == n ? text : line) + "\n";
  return out;
}

std::vector<QuarrySection> read(const test::TempDir& dir, const std::string& text) {
  const fs::path file = dir.write("scenario.toml", text);
  const toml::table root = toml::parse(text, file.string());
  return read_quarries(root, file, kRules, materials(), settings());
}

InputError error_of(const std::string& text) {
  test::TempDir dir;
  try {
    read(dir, text);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no error for:\n" << text;
  return InputError("", 0, "", "", "");
}

// A section without a seed gets the run's + its index, wrapped so that it stays a seed a user
// can give back (up to 2^63 − 1): --seed 9223372036854775807 made sections ...808, ...809.
TEST(QuarryReader, SectionSeedsStaySeedsAUserCanGiveBack) {
  constexpr std::uint64_t kMax = 9223372036854775807ull;
  EXPECT_EQ(pierre::io::section_seed(500, 1), 501u);
  EXPECT_EQ(pierre::io::section_seed(kMax, 0), kMax);
  EXPECT_EQ(pierre::io::section_seed(kMax, 1), 0u);
  EXPECT_EQ(pierre::io::section_seed(kMax - 1, 3), 1u);
}

TEST(QuarryReader, ReadsASection) {
  test::TempDir dir;
  const auto q = read(dir, kSection + "\n" + section_with(2, "name = \"Preg 2\""));
  ASSERT_EQ(q.size(), 2u);
  const QuarrySection& s = q[0];
  EXPECT_EQ(s.spec.name, "Preg 1");
  EXPECT_EQ(s.spec.group, "Preg");
  EXPECT_EQ(s.spec.rules, "quarry-thesis-2015");
  EXPECT_EQ(s.rules.name, "quarry-thesis-2015");
  EXPECT_DOUBLE_EQ(*s.spec.bench_width, 12);
  EXPECT_EQ(s.spec.exceedance, (std::vector<double>{0.05, 0.01, 0.001}));
  EXPECT_EQ(s.scenario.blocks.size(), 3u);
  EXPECT_EQ(s.scenario.blocks[1].id, "P2.1");
  EXPECT_DOUBLE_EQ(s.scenario.blocks[0].density, 2800);
  EXPECT_EQ(s.scenario.sources.size(), 1u);
  EXPECT_EQ(s.scenario.materials.size(), 2u);
  EXPECT_EQ(s.scenario.settings.throws, 10u);
  EXPECT_EQ(s.scenario.settings.seed, 100u);
  EXPECT_EQ(q[1].scenario.settings.seed, 101u);  // each section its own stream
  EXPECT_EQ(s.geometry.toe_vertex, 2u);
  EXPECT_DOUBLE_EQ(s.geometry.height, 20);
  EXPECT_EQ(s.scenario.settings.floor_segment, 2);
  ASSERT_EQ(s.spec.work_areas.size(), 1u);
  EXPECT_EQ(s.spec.work_areas[0].name, "crusher");
  EXPECT_DOUBLE_EQ(*s.observed.rd.p95, 15.8);
  EXPECT_DOUBLE_EQ(*s.observed.id.max, 4.3);
  EXPECT_EQ(*s.observed.rd.count, 25u);
  EXPECT_EQ(s.observed.source, "Table 6.2, 6.3");
}

// A source behind the crest is noted at its line (not a doubt: loose blocks on the top bench
// may be meant): its blocks reach the floor only over the crest. One over the face is not.
TEST(QuarryReader, ASourceBehindTheCrestIsNoted) {
  test::TempDir dir;
  auto behind_crest = [](const QuarrySection& s) {
    for (const auto& n : s.notes)
      if (n.text.find("behind the crest") != std::string::npos) return &n;
    return static_cast<const InputNote*>(nullptr);
  };
  EXPECT_FALSE(behind_crest(read(dir, kSection).at(0)));
  const auto q = read(dir, section_with(21, "x = 6.0"));
  const InputNote* n = behind_crest(q.at(0));
  ASSERT_TRUE(n);
  EXPECT_EQ(n->line, 20);  // the [[quarries.sources]] header
  EXPECT_EQ(n->field, "quarries[0].sources[0].x");
  EXPECT_EQ(n->text, "the source at x = 6 m lies 4.00 m behind the crest (x = 10.00 m), above the "
                     "face, not on it: its blocks reach the floor only if they roll over the "
                     "crest; a release from the face lies between crest and toe (x = 20.00 m)");
  EXPECT_FALSE(n->doubt);
}

// A toe given inside a segment: the floor is the profile past the toe, so the segment is cut
// there (two collinear pieces, the same physics) and the floor starts at the new vertex. Before,
// the whole segment was floor and every first contact on it before the toe counted as ID = 0.
TEST(QuarryReader, AToeInsideASegmentStartsTheFloorThere) {
  test::TempDir dir;
  const auto q = read(dir, section_with(3, "group = \"Preg\"\ntoe = 25.0"));
  ASSERT_EQ(q.size(), 1u);
  const QuarrySection& s = q[0];
  const auto& v = s.scenario.profile.vertices();
  ASSERT_EQ(v.size(), 5u);  // (0, 20), (10, 20), (20, 0), (25, 0), (90, 0)
  EXPECT_DOUBLE_EQ(v[3].x, 25);
  EXPECT_DOUBLE_EQ(v[3].z, 0);
  EXPECT_EQ(s.geometry.toe_vertex, 3u);
  EXPECT_EQ(s.scenario.settings.floor_segment, 3);
  EXPECT_DOUBLE_EQ(s.geometry.floor_length, 65);
  EXPECT_EQ(s.scenario.profile.segment(2).material, s.scenario.profile.segment(3).material);
  EXPECT_EQ(s.geometry.toe_origin, design::GeometryOrigin::given);
}

TEST(QuarryReader, GivenGeometryCsvFilesAndSeed) {
  test::TempDir dir;
  dir.write("face.csv", "x,z,material\n0,20,floor\n10,20,face\n20,0,floor\n90,0,\n");
  dir.write("blocks.csv", "id,mass\nA,140\nB,500\n");
  // A field record with the block of each row and a remark, read and left alone.
  dir.write("observed.csv", "block,first_impact,runout,remark\nA,1.0,10.5,\nB,,12.0,\"fell short, then rolled\"\nC,2.5,,\n");
  const std::string text = R"([[quarries]]
name = "Pauliberg"
rules = "quarry-conservative"
toe = 25.0
crest = 10.0
height = 19.5
seed = 7
profile = { file = "face.csv" }
blocks = { file = "blocks.csv" }
sources = [{ x = 10.3, z = 20.5 }]
observed = { file = "observed.csv" }
)";
  const auto q = read(dir, text);
  ASSERT_EQ(q.size(), 1u);
  const auto& s = q[0];
  EXPECT_EQ(s.rules.name, "quarry-conservative");
  EXPECT_EQ(s.geometry.toe_origin, design::GeometryOrigin::given);
  EXPECT_DOUBLE_EQ(s.geometry.toe.x, 25);
  EXPECT_DOUBLE_EQ(s.geometry.height, 19.5);
  EXPECT_DOUBLE_EQ(s.geometry.height_derived, 20);
  EXPECT_EQ(s.scenario.settings.floor_segment, 3);  // the segment cut at the toe (x = 25)
  EXPECT_EQ(s.scenario.settings.seed, 7u);
  EXPECT_EQ(s.scenario.blocks.size(), 2u);
  EXPECT_EQ(s.observed.id.metres, (std::vector<double>{1.0, 2.5}));
  EXPECT_EQ(s.observed.rd.metres, (std::vector<double>{10.5, 12.0}));
}

// A probability typed as a percentage is told the fraction it means (new-user review:
// exceedance = [5, 1] got only "in (0, 1)").
TEST(QuarryReader, APercentageForAProbabilityIsToldItsFraction) {
  EXPECT_EQ(error_of(section_with(5, "exceedance = [0.05, 5]")).expected(),
            "a probability of exceedance in (0, 1) (a fraction, not a percentage: 5 % is 0.05)");
  EXPECT_EQ(error_of(section_with(5, "exceedance = [0.05, 250.0]")).expected(),
            "a probability of exceedance in (0, 1)");
}

TEST(QuarryReader, NoQuarries) {
  test::TempDir dir;
  EXPECT_TRUE(read(dir, "[scenario]\nname = \"x\"\n").empty());
}

struct ErrorCase {
  const char* name;
  int line;             // of kSection to replace (0: append `text`)
  const char* text;
  long expect_line;     // in the scenario file (-1: do not check)
  const char* field;
  const char* found;    // a part of the message's found (empty: do not check)
};

class QuarryReaderErrors : public ::testing::TestWithParam<ErrorCase> {};

TEST_P(QuarryReaderErrors, NamesLineFieldFound) {
  const ErrorCase& c = GetParam();
  const std::string text = c.line > 0 ? section_with(c.line, c.text) : kSection + c.text;
  const InputError e = error_of(text);
  if (c.expect_line >= 0) {
    EXPECT_EQ(e.line(), c.expect_line) << e.what();
  }
  EXPECT_EQ(e.field(), c.field) << e.what();
  EXPECT_NE(e.found().find(c.found), std::string::npos) << e.what();
  EXPECT_FALSE(e.expected().empty());
  EXPECT_EQ(e.file().filename(), "scenario.toml");
}

const ErrorCase kErrors[] = {
    {"unknown_key", 4, "bench = 12.0", 4, "quarries[0].bench", "an unknown key"},
    {"bench_width_zero", 4, "bench_width = 0.0", 4, "quarries[0].bench_width", "0.0"},
    {"exceedance_one", 5, "exceedance = [0.05, 1.0]", 5, "quarries[0].exceedance[1]", "1.0"},
    {"exceedance_twice", 5, "exceedance = [0.05, 0.01, 0.05]", 5, "quarries[0].exceedance[2]", "0.05"},
    {"unknown_material", 8,
     "points = [[0.0, 20.0, \"floor\"], [10.0, 20.0, \"rock\"], [20.0, 0.0, \"floor\"], [90.0, 0.0, \"\"]]",
     8, "quarries[0].profile.points[1]", "\"rock\""},
    {"no_floor", 8,
     "points = [[0.0, 20.0, \"floor\"], [10.0, 20.0, \"face\"], [20.0, 0.0, \"face\"], [40.0, -10.0, \"\"]]",
     7, "quarries[0].profile", "a section with no toe"},
    {"toe_outside", 0, "", -1, "", ""},  // placeholder replaced below
    {"mass_negative", 14, "mass = -1.0", 14, "quarries[0].blocks.table[0].mass", "-1.0"},
    {"source_outside", 21, "x = 95.0", 21, "quarries[0].sources[0].x", "95.0"},
    {"work_area_negative", 27, "distance = -3.0", 27, "quarries[0].work_areas[0].distance", "-3.0"},
    {"work_area_space", 26, "name = \"haul road\"", 26, "quarries[0].work_areas[0].name", "haul road"},
    {"observed_order", 32, "runout = { p50 = 10.5, p95 = 9.0, max = 17.0 }", 32,
     "quarries[0].observed.runout.p95", "9.0"},
    {"rules_unknown", 4, "rules = \"no-such-rules\"", 4, "quarries[0].rules", "no-such-rules"},
    {"rules_barrier", 4, "rules = \"thesis-2015\"", 4, "quarries[0].rules", "thesis-2015"},
    {"observed_file_and_summary", 30, "source = \"x\"\nfile = \"obs.csv\"", 33,
     "quarries[0].observed.runout", "a table"},
    {"duplicate_name", 0, "\n[[quarries]]\nname = \"Preg 1\"\n", 36, "quarries[1].name", "Preg 1"},
};

std::vector<ErrorCase> error_cases() {
  std::vector<ErrorCase> v;
  for (const auto& c : kErrors)
    if (std::string(c.name) != "toe_outside") v.push_back(c);
  // The value found is the number, the section's extent is in what was expected.
  v.push_back({"toe_outside", 4, "toe = 120.0", 4, "quarries[0].toe", "120.0"});
  v.push_back({"crest_outside", 4, "crest = -5.0", 4, "quarries[0].crest", "-5.0"});
  return v;
}

INSTANTIATE_TEST_SUITE_P(All, QuarryReaderErrors, ::testing::ValuesIn(error_cases()),
                         [](const auto& info) { return std::string(info.param.name); });

// An error inside a rule file given by path is said in that file, even a missing table (line 0):
// it was replaced by "expected a rule set in rules/ or a path to a .toml file".
TEST(QuarryReader, AnErrorInsideTheRuleFileIsSaidThere) {
  test::TempDir dir;
  dir.write("site.toml", "[rule_set]\ntitle = \"Site\"\nsource = \"site manager\"\n");
  try {
    read(dir, section_with(4, "rules = \"site.toml\""));
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), dir.path() / "site.toml") << e.what();
    EXPECT_EQ(e.field(), "governing") << e.what();
    EXPECT_EQ(e.found(), "nothing") << e.what();
  }
}

TEST(QuarryReader, GroupWithDifferentRuleSets) {
  const std::string text = kSection + "\n" + section_with(2, "name = \"Preg 2\"\nrules = \"quarry-conservative\"");
  const InputError e = error_of(text);
  EXPECT_EQ(e.field(), "quarries[1].rules") << e.what();
  EXPECT_NE(e.expected().find("quarry-thesis-2015"), std::string::npos) << e.what();
}

// A report row is a lone section or a group: a group named as a section outside it would
// make two rows of one name.
TEST(QuarryReader, GroupNamedAsASectionOutsideIt) {
  std::string other = section_with(3, "group = \"Other\"");
  other.replace(other.find("name = \"Preg 1\""), 15, "name = \"Preg\"");
  const std::string text = kSection + "\n" + other;
  const InputError e = error_of(text);
  EXPECT_EQ(e.field(), "quarries[0].group") << e.what();
  EXPECT_EQ(e.found(), "\"Preg\"") << e.what();
  // A section named as its own group is one row, and fine.
  test::TempDir dir;
  EXPECT_EQ(read(dir, kSection + "\n" + section_with(2, "name = \"Preg\"")).size(), 2u);
}

// Sections pooled in a group: raw observations in every one, or summary values; a mix would
// drop the summary values without a word.
TEST(QuarryReader, GroupMixingRawAndSummaryObservations) {
  test::TempDir dir;
  dir.write("obs.csv", "runout\n5.0\n9.5\n");
  std::string second = section_with(2, "name = \"Preg 2\"");
  second = second.substr(0, second.find("count = 25")) + "file = \"obs.csv\"\n";
  try {
    read(dir, kSection + "\n" + second);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "quarries[1].observed") << e.what();
    EXPECT_NE(e.expected().find("quarries[0] gives summary values"), std::string::npos) << e.what();
  }
}

// ---- rule sets ----

TEST(QuarryRules, ShippedRuleSets) {
  const auto t = load_quarry_rules("quarry-thesis-2015", kRules);
  EXPECT_EQ(t.name, "quarry-thesis-2015");
  EXPECT_EQ(t.governing, (std::vector<design::QuarryGoverning>{design::QuarryGoverning::percentile}));
  EXPECT_DOUBLE_EQ(t.percentile, 95);
  EXPECT_DOUBLE_EQ(t.floor_angle_deg, 15);
  EXPECT_DOUBLE_EQ(t.retention_target, 0.9);
  EXPECT_DOUBLE_EQ(t.ritchie_factor, 0.2);
  EXPECT_DOUBLE_EQ(t.ritchie_offset, 4.5);
  EXPECT_FALSE(t.source.empty());
  EXPECT_TRUE(t.clauses.count("zone"));
  const auto c = load_quarry_rules("quarry-conservative", kRules);
  EXPECT_EQ(c.governing, (std::vector<design::QuarryGoverning>{design::QuarryGoverning::maximum,
                                                               design::QuarryGoverning::lognormal}));
  EXPECT_DOUBLE_EQ(c.lognormal_percentile, 99);
}

const std::string kCustom = R"([rule_set]
title = "Site rules"
source = "site manager, 2024"
[toe]
floor_angle = 10.0
[governing]
use = ["percentile", "maximum"]
percentile = 98.0
[retention]
target = 0.95
[ritchie]
factor = 0.25
offset = 5.0
[sample]
min_reached = 50
resamples = 2000
[fit]
p_value = 0.01
[clauses]
zone = "site rule 3.1"
)";

TEST(QuarryRules, FromATempFileByPath) {
  test::TempDir dir;
  const fs::path f = dir.write("site-rules.toml", kCustom);
  const auto r = load_quarry_rules(f.string(), "/nonexistent");
  EXPECT_EQ(r.name, "site-rules");  // the file stem when [rule_set] has no name
  EXPECT_DOUBLE_EQ(r.floor_angle_deg, 10);
  EXPECT_EQ(r.governing.size(), 2u);
  EXPECT_DOUBLE_EQ(r.percentile, 98);
  EXPECT_DOUBLE_EQ(r.retention_target, 0.95);
  EXPECT_DOUBLE_EQ(r.ritchie_offset, 5);
  EXPECT_EQ(r.min_reached, 50u);
  EXPECT_EQ(r.sample_resamples, 2000u);
  EXPECT_DOUBLE_EQ(r.fit_p_value, 0.01);
  EXPECT_EQ(r.clauses.at("zone"), "site rule 3.1");
  // And by name from a rules folder.
  const auto byname = load_quarry_rules("site-rules", dir.path());
  EXPECT_DOUBLE_EQ(byname.percentile, 98);
}

// `[sample] percentile` chose what sample.size judged until it judged RD_gov itself: an older
// site file that sets it still loads (its value checked, then ignored).
TEST(QuarryRules, AnOlderFilesSamplePercentileIsReadAndIgnored) {
  test::TempDir dir;
  std::string text = kCustom;
  text.replace(text.find("[sample]\n"), 9, "[sample]\npercentile = 99.0\n");
  const auto r = load_quarry_rules(dir.write("old.toml", text).string(), dir.path());
  EXPECT_DOUBLE_EQ(r.percentile, 98);  // the governing percentile, untouched
  EXPECT_EQ(r.min_reached, 50u);
  text.replace(text.find("percentile = 99.0"), 17, "percentile = 150.0");
  try {
    load_quarry_rules(dir.write("bad.toml", text).string(), dir.path());
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "sample.percentile") << e.what();
    EXPECT_EQ(e.line(), 15) << e.what();
  }
}

TEST(QuarryRules, Errors) {
  test::TempDir dir;
  auto err = [&](const std::string& text) {
    const fs::path f = dir.write("r.toml", text);
    try {
      load_quarry_rules(f.string(), dir.path());
    } catch (const InputError& e) {
      return e;
    }
    ADD_FAILURE() << "no error";
    return InputError("", 0, "", "", "");
  };
  // kCustom with its first `from` made `to`.
  auto edited = [](const std::string& from, const std::string& to) {
    std::string t = kCustom;
    const auto at = t.find(from);
    if (at == std::string::npos) throw std::logic_error("kCustom has no " + from);
    return t.replace(at, from.size(), to);
  };
  const auto a = err(edited("\"maximum\"", "\"median\""));
  EXPECT_EQ(a.line(), 7);
  EXPECT_EQ(a.field(), "governing.use[1]");
  EXPECT_EQ(a.found(), "\"median\"");
  EXPECT_EQ(err(edited("percentile = 98.0", "")).field(), "governing.percentile");
  EXPECT_EQ(err(edited("10.0", "95.0")).field(), "toe.floor_angle");
  // design-checks.md §1 step 8: at least 1000 resamples and a 90 % interval; more, not fewer.
  EXPECT_EQ(err(edited("resamples = 2000", "resamples = 999")).field(), "sample.resamples");
  EXPECT_EQ(err(edited("min_reached = 50", "min_reached = 50\nconfidence = 0.5")).field(),
            "sample.confidence");
  // resamples ≥ 2 / (1 − confidence): 2000 resamples carry 99.9 % (one beyond each end), not
  // 99.95 %.
  EXPECT_DOUBLE_EQ(load_quarry_rules(dir.write("ok.toml", edited("min_reached = 50",
                                                                  "min_reached = 50\nconfidence = 0.999"))
                                          .string(),
                                      dir.path())
                       .sample_confidence,
                   0.999);
  EXPECT_EQ(err(edited("min_reached = 50", "min_reached = 50\nconfidence = 0.9995")).field(),
            "sample.confidence");
  // [toe], [retention] and [ritchie] left out: the spec's defaults (15°, 90 %, 0.2·H + 4.5 m).
  std::string bare = kCustom;
  for (const char* t : {"[toe]\nfloor_angle = 10.0\n", "[retention]\ntarget = 0.95\n",
                        "[ritchie]\nfactor = 0.25\noffset = 5.0\n"}) {
    ASSERT_NE(bare.find(t), std::string::npos) << t;
    bare.replace(bare.find(t), std::string(t).size(), "");
  }
  const auto d = load_quarry_rules(dir.write("bare.toml", bare).string(), dir.path());
  EXPECT_DOUBLE_EQ(d.floor_angle_deg, 15);
  EXPECT_DOUBLE_EQ(d.retention_target, 0.90);
  EXPECT_DOUBLE_EQ(d.ritchie_factor, 0.2);
  EXPECT_DOUBLE_EQ(d.ritchie_offset, 4.5);
  const auto missing = [&] {
    try {
      load_quarry_rules("absent", dir.path());
    } catch (const InputError& e) {
      return e;
    }
    return InputError("", 0, "", "", "");
  }();
  EXPECT_EQ(missing.line(), 0);
  EXPECT_EQ(missing.found(), "no such file");
}

}  // namespace
}  // namespace pierre::io
