// What the reader builds from valid input: presets and overrides, block expansion, defaults,
// accepted forms (an integer where a float is expected, a source below the ground), and the
// presets of rules/materials.toml against the thesis's tables.
#include <gtest/gtest.h>

#include <cstdlib>

#include "pierre/io/scenario_reader.hpp"
#include "test_files.hpp"

namespace {

using pierre::io::InputError;
using pierre::io::load_scenario;
using pierre::test::base_with;
using pierre::test::TempDir;

const std::filesystem::path kRules = PIERRE_SOURCE_DIR "/rules";

TEST(ScenarioReader, BaseScenarioWithDefaults) {
  TempDir dir;
  const auto l = load_scenario(dir.write("s.toml", pierre::test::base()), kRules);
  const auto& s = l.scenario;
  EXPECT_EQ(s.name, "t");
  EXPECT_EQ(s.settings.seed, 1u);
  EXPECT_EQ(s.settings.throws, 2u);
  EXPECT_EQ(s.settings.max_time, 600.0);
  EXPECT_EQ(s.settings.stop_head_factor, 0.25);
  EXPECT_TRUE(s.settings.roughness.size_reduction);
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.materials[0].name, "rock");
  EXPECT_EQ(s.materials[0].source, "scenario");
  EXPECT_EQ(s.materials[0].normal_energy_k, 0.5);
  EXPECT_EQ(s.materials[0].tangential_energy_k, 0.95);
  EXPECT_EQ(s.materials[0].friction_angle_deg, 30.0);
  EXPECT_EQ(s.profile.vertices().size(), 3u);
  ASSERT_EQ(s.blocks.size(), 1u);
  EXPECT_EQ(s.blocks[0].id, "B1");
  EXPECT_EQ(s.blocks[0].density, 2650.0);
  EXPECT_EQ(s.blocks[0].shape_min, 1.0);
  ASSERT_EQ(s.sources.size(), 1u);
  EXPECT_EQ(s.sources[0].name, "S1");
  ASSERT_EQ(s.lines.size(), 1u);
  EXPECT_EQ(s.lines[0].x, 15.0);
  EXPECT_EQ(s.trajectory_count(), 2u);
  EXPECT_EQ(l.materials_file, kRules / "materials.toml");
  EXPECT_NE(l.text.find("[simulation]"), std::string::npos);
}

// Document control in [scenario], each optional: read as written; longer than a page header
// holds, an error at its line.
TEST(ScenarioReader, DocumentControlIsReadWhereGiven) {
  TempDir dir;
  const auto none = load_scenario(dir.write("s.toml", pierre::test::base()), kRules);
  EXPECT_TRUE(none.document.reference.empty() && none.document.revision.empty() &&
              none.document.prepared_by.empty() && none.document.checked_by.empty());
  const auto l = load_scenario(
      dir.write("s.toml", pierre::test::base_with(3, "reference = \"P-17 & Co\"\nrevision = \"B\"\n"
                                                     "prepared_by = \"A. Engineer\"\nchecked_by = \"B. Checker\"")),
      kRules);
  EXPECT_EQ(l.document.reference, "P-17 & Co");
  EXPECT_EQ(l.document.revision, "B");
  EXPECT_EQ(l.document.prepared_by, "A. Engineer");
  EXPECT_EQ(l.document.checked_by, "B. Checker");
  try {
    (void)load_scenario(dir.write("s.toml", pierre::test::base_with(3, "reference = \"" +
                                                                          std::string(81, 'x') + "\"")),
                        kRules);
    FAIL() << "an 81-character reference was taken";
  } catch (const pierre::io::InputError& e) {
    EXPECT_EQ(e.line(), 3);
    EXPECT_EQ(e.field(), "scenario.reference");
    EXPECT_NE(e.expected().find("at most 80 characters"), std::string::npos) << e.expected();
  }
}

TEST(ScenarioReader, IntegerAcceptedWhereFloatExpected) {
  TempDir dir;
  const auto l = load_scenario(dir.write("s.toml", base_with(14, "roughness = 1")), kRules);
  EXPECT_EQ(l.scenario.materials[0].roughness, 1.0);
}

TEST(ScenarioReader, SourceBelowGroundIsNotAnError) {
  TempDir dir;
  const auto l = load_scenario(dir.write("s.toml", base_with(22, "z = -50.0")), kRules);
  EXPECT_EQ(l.scenario.sources[0].position.z, -50.0);
}

TEST(ScenarioReader, PresetWithOverrideAndSource) {
  TempDir dir;
  const auto l = load_scenario(
      dir.write("s.toml", base_with(12, "preset = \"talus\"\n").replace(
                              base_with(12, "preset = \"talus\"\n").find("tangential_energy = 50.0\n"),
                              25, "")),
      kRules);
  const auto& m = l.scenario.materials[0];
  EXPECT_EQ(m.normal_energy, 15.0);
  EXPECT_EQ(m.tangential_energy, 50.0);
  EXPECT_EQ(m.roughness, 0.5);  // overridden by the scenario
  EXPECT_NE(m.source.find("Table 4.3"), std::string::npos) << m.source;
  EXPECT_NE(m.source.find("(overridden: roughness)"), std::string::npos) << m.source;
}

TEST(ScenarioReader, BlockGroupsExpandAndMassFromVolume) {
  TempDir dir;
  dir.write("b.csv", "id,volume,density,count,shape_min,shape_max\ncsv,2.0,2000,2,0.8,1.2\n,1.0,,,,\n");
  const auto l = load_scenario(
      dir.write("s.toml", base_with(18, "volume = 0.5\ncount = 3\nid = \"a\"\n"
                                         "[[blocks.table]]\nmass = 10")
                              .replace(base_with(18, "").find("[blocks]"), 8,
                                       "[blocks]\nfile = \"b.csv\"\ndensity = 3000\nshape_factor = [1.0, 1.5]")),
      kRules);
  const auto& b = l.scenario.blocks;
  ASSERT_EQ(l.block_groups.size(), 4u);
  ASSERT_EQ(b.size(), 2u + 1u + 3u + 1u);
  EXPECT_EQ(b[0].id, "csv.1");
  EXPECT_EQ(b[1].id, "csv.2");
  EXPECT_DOUBLE_EQ(b[0].mass, 4000.0);
  EXPECT_EQ(b[0].shape_min, 0.8);
  EXPECT_EQ(b[0].shape_max, 1.2);
  EXPECT_EQ(b[2].id, "B2");  // CSV row 2 without id: the blocks default
  EXPECT_DOUBLE_EQ(b[2].mass, 3000.0);
  EXPECT_EQ(b[2].shape_max, 1.5);
  EXPECT_EQ(b[3].id, "a.1");
  EXPECT_EQ(b[5].id, "a.3");
  EXPECT_DOUBLE_EQ(b[3].mass, 1500.0);  // 0.5 m³ × 3000 kg/m³
  EXPECT_DOUBLE_EQ(b[3].volume(), 0.5);
  EXPECT_EQ(b[6].id, "B4");
  EXPECT_EQ(b[6].mass, 10.0);
}

// Quoted cells may hold commas and doubled quotes (RFC 4180), and numbers a leading '+'.
TEST(ScenarioReader, CsvQuotedCellsAndPlusSigns) {
  TempDir dir;
  dir.write("p.csv", "x,z,material\n+0.0,+10,\"rock\"\n10,0,rock\n20,0,\n");
  dir.write("b.csv", "id,mass\n\"P,01\",100\n\"the \"\"big\"\" one\",+200\n");
  const auto l = load_scenario(
      dir.write("s.toml", base_with(9, "file = \"p.csv\"").replace(
                              base_with(9, "file = \"p.csv\"").find("[blocks]"), 8,
                              "[blocks]\nfile = \"b.csv\"")),
      kRules);
  EXPECT_EQ(l.scenario.profile.vertices()[0].z, 10.0);
  ASSERT_GE(l.scenario.blocks.size(), 2u);
  EXPECT_EQ(l.scenario.blocks[0].id, "P,01");
  EXPECT_EQ(l.scenario.blocks[1].id, "the \"big\" one");
  EXPECT_EQ(l.scenario.blocks[1].mass, 200.0);
}

TEST(ScenarioReader, ProfileCsvWithCommentsAndMaterials) {
  TempDir dir;
  dir.write("p.csv", "# a comment\n\nx, z, material\n0,10,rock\n10,0,rock\n20,0,\n");
  const auto l = load_scenario(dir.write("s.toml", base_with(9, "file = \"p.csv\"")), kRules);
  ASSERT_EQ(l.scenario.profile.segment_count(), 2u);
  EXPECT_EQ(l.scenario.profile.segment(1).material, 0);
  EXPECT_EQ(l.scenario.profile.x_max(), 20.0);
}

// A profile as spreadsheets write it reads as the plain file does: empty cells after the last
// column (every row as wide as the widest the sheet ever had), rows of empty cells, and the
// CR-only line ends of old Mac spreadsheets. (A value in a trailing cell is still a row too
// long, and errors count lines by CRs: ScenarioError.)
TEST(ScenarioReader, ProfileCsvAsSpreadsheetsWriteIt) {
  TempDir dir;
  const auto toml = dir.write("s.toml", base_with(9, "file = \"p.csv\""));
  for (const char* text : {"x,z,material,,\n0,10,rock,,\n,,,,\n10,0,rock,,\n20,0,,,\n",
                           "x,z,material\r0,10,rock\r10,0,rock\r20,0,\r"}) {
    SCOPED_TRACE(text);
    dir.write("p.csv", text);
    const auto l = load_scenario(toml, kRules);
    const auto& v = l.scenario.profile.vertices();
    ASSERT_EQ(v.size(), 3u);
    EXPECT_EQ(v[0].z, 10.0);
    EXPECT_EQ(v[1].x, 10.0);
    EXPECT_EQ(v[2].x, 20.0);
  }
}

// The units in the column names, as pierre's own CSVs write them (start_x_m, mass_kg).
TEST(ScenarioReader, CsvColumnsMayCarryTheirUnits) {
  TempDir dir;
  dir.write("p.csv", "x_m,z_m,material\n0,10,rock\n10,0,rock\n20,0,\n");
  dir.write("b.csv", "id,volume_m3,density_kg_m3\nB1,0.5,2000\n");
  auto toml = base_with(9, "file = \"p.csv\"");
  toml.replace(toml.find("[blocks]"), 8, "[blocks]\nfile = \"b.csv\"");
  const auto l = load_scenario(dir.write("s.toml", toml), kRules);
  EXPECT_EQ(l.scenario.profile.vertices()[0].z, 10.0);
  ASSERT_GE(l.scenario.blocks.size(), 1u);
  EXPECT_DOUBLE_EQ(l.scenario.blocks[0].mass, 1000.0);  // 0.5 m³ × 2000 kg/m³
  // (A column under both its names is there twice: ScenarioError.)
}

TEST(ScenarioReader, TestDataScenarioIsValid) {
  const auto l = load_scenario(PIERRE_TEST_DATA "/small/scenario.toml", kRules);
  EXPECT_EQ(l.scenario.blocks.size(), 2u);
  EXPECT_EQ(l.scenario.lines.size(), 2u);
  EXPECT_EQ(l.scenario.trajectory_count(), 600u);
  EXPECT_DOUBLE_EQ(l.scenario.blocks[1].mass, 1.2 * 2650.0);
}

// Every preset of rules/materials.toml, loaded through the reader, against the thesis.
struct PresetCase {
  const char* name;
  double en, et, roughness;
  const char* cites;
};

class Preset : public ::testing::TestWithParam<PresetCase> {};

TEST_P(Preset, MatchesTheThesis) {
  const PresetCase& p = GetParam();
  TempDir dir;
  std::string text = base_with(12, std::string("preset = \"") + p.name + "\"");
  text.replace(text.find("tangential_energy = 50.0\n"), 25, "");
  text.replace(text.find("roughness = 0.5\n"), 16, "");
  const auto l = load_scenario(dir.write("s.toml", text), kRules);
  const auto& m = l.scenario.materials[0];
  EXPECT_EQ(m.normal_energy, p.en);
  EXPECT_EQ(m.tangential_energy, p.et);
  EXPECT_EQ(m.roughness, p.roughness);
  EXPECT_EQ(m.normal_energy_k, 0.5);
  EXPECT_EQ(m.tangential_energy_k, 0.95);
  EXPECT_EQ(m.friction_angle_deg, 30.0);
  EXPECT_NE(m.source.find(p.cites), std::string::npos) << m.source;
  EXPECT_EQ(m.source.find("overridden"), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(
    RulesMaterials, Preset,
    ::testing::Values(PresetCase{"talus", 15, 50, 0.65, "Table 4.3"},
                      PresetCase{"talus-vaujany", 15, 50, 0.72, "§4.4.1"},
                      PresetCase{"vaujany-road", 15, 50, 0.4, "§4.4.1"},
                      PresetCase{"rock-face", 5, 50, 0.65, "Table 8.1"},
                      PresetCase{"quarry-face", 5, 50, 0.65, "Table 6.1"},
                      PresetCase{"quarry-floor", 5, 50, 0.35, "Table 6.1"},
                      PresetCase{"preg-initial-face", 20, 50, 0.7, "§4.4.2"},
                      PresetCase{"preg-initial-bench", 20, 50, 0.3, "§4.4.2"}),
    [](const ::testing::TestParamInfo<PresetCase>& i) {
      std::string n = i.param.name;
      for (char& c : n)
        if (c == '-') c = '_';
      return n;
    });

}  // namespace

// A folder where the scenario file is expected is named as such: reading a folder as a stream
// gives nothing, which said "found nothing, expected a [scenario] table". (A CSV given by path
// is checked at the scenario's key: ScenarioError profile_csv_a_folder.)
// A gravity far from the Earth's is taken but noted: 98.1 for 9.81 multiplies every energy.
TEST(ScenarioReader, AGravityOffTheEarthsIsNoted) {
  TempDir dir;
  const auto slip = load_scenario(dir.write("s.toml", base_with(6, "throws = 2\ngravity = 98.1")), kRules);
  ASSERT_EQ(slip.notes.size(), 1u);
  EXPECT_EQ(slip.notes[0].line, 7);
  EXPECT_EQ(slip.notes[0].field, "simulation.gravity");
  EXPECT_EQ(slip.notes[0].text.rfind("gravity 98.1 m/s² is not the Earth's", 0), 0u) << slip.notes[0].text;
  for (const char* g : {"9.81", "10.0"})
    EXPECT_TRUE(load_scenario(dir.write("t.toml", base_with(6, std::string("throws = 2\ngravity = ") + g)), kRules)
                    .notes.empty())
        << g;
  // A centrifuge's 1000 g is taken (noted); 1e308 overflowed every flight (no landing found, the
  // blocks lost through the ground and reported as having left the profile): refused.
  EXPECT_EQ(load_scenario(dir.write("c.toml", base_with(6, "throws = 2\ngravity = 1e4")), kRules).notes.size(), 1u);
  try {
    load_scenario(dir.write("u.toml", base_with(6, "throws = 2\ngravity = 1.7e308")), kRules);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 7);
    EXPECT_EQ(e.field(), "simulation.gravity");
    EXPECT_EQ(e.found(), "1.7e+308");
    EXPECT_EQ(e.expected(), "an acceleration > 0 and <= 10000 m/s²");
  }
}

// An endless stream named as an input (found by fuzzing: /dev/zero filled the memory without a
// word) is read up to the largest input and refused there.
TEST(ScenarioReader, AnEndlessStreamIsReadNoFurtherThanTheLargestInput) {
  TempDir dir;
  const auto s = dir.write("s.toml", base_with(9, "file = \"/dev/zero\""));
  try {
    (void)load_scenario(s, kRules);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), std::filesystem::path("/dev/zero"));
    EXPECT_EQ(e.field(), "file");
    EXPECT_EQ(e.found().rfind("more than 256 MiB", 0), 0u) << e.found();
    EXPECT_EQ(e.expected(), "a CSV file with header x,z,material of at most 256 MiB");
  }
}

TEST(ScenarioReader, AFolderIsNotAFile) {
  TempDir dir;
  std::filesystem::create_directories(dir.path() / "s.toml");
  try {
    (void)load_scenario(dir.path() / "s.toml", kRules);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.found(), "a folder, not a file");
    EXPECT_EQ(e.file(), dir.path() / "s.toml");
  }
}
