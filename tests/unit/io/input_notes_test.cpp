// Notes on the input (io::InputNote, LoadedScenario::notes): likely mistakes that do not stop a
// run, said where they are like an error — a profile that runs back in x (read as an overhang:
// valid, but one x typed out of order makes one), a source far above the ground under it (a z
// in absolute elevations over a profile in local ones). Each names the file, the line, the
// field, and says why it matters; valid input of the usual kind gets none.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <fmt/format.h>

#include "pierre/io/scenario_reader.hpp"
#include "test_files.hpp"

namespace {

namespace fs = std::filesystem;
using pierre::io::InputNote;
using pierre::io::load_scenario;
using pierre::test::base_with;
using pierre::test::TempDir;

const fs::path kRules = PIERRE_SOURCE_DIR "/rules";

std::vector<InputNote> notes_of(const TempDir& dir, const std::string& scenario) {
  return load_scenario(dir.write("s.toml", scenario), kRules).notes;
}

// A quarry scenario of one section, "East": a crest at (10, 20), a 63.4° face to the toe at
// (20, 0), a level floor to x = 90; `keys` (lines) added to the section after its name, its
// source at (10.3, `source_z`).
std::string pit(const std::string& keys, double source_z) {
  return R"([scenario]
name = "pit"

[simulation]
seed = 40
throws = 3

[materials.face]
preset = "quarry-face"

[[quarries]]
name = "East"
)" + (keys.empty() ? "" : keys + "\n") +
         R"(profile = { points = [[0.0, 20.0, "face"], [10.0, 20.0, "face"], [20.0, 0.0, "face"], [90.0, 0.0, ""]] }
blocks = { table = [{ id = "A", mass = 500.0 }] }
sources = [{ x = 10.3, z = )" + std::to_string(source_z) + " }]\n";
}

TEST(InputNotes, TheUsualScenarioHasNone) {
  TempDir dir;
  EXPECT_TRUE(notes_of(dir, pierre::test::base()).empty());
  // A vertical face is not a segment running back in x.
  EXPECT_TRUE(notes_of(dir, base_with(9, "points = [[0.0, 10.0, \"rock\"], [5.0, 10.0, \"rock\"], "
                                         "[5.0, 0.0, \"rock\"], [20.0, 0.0, \"\"]]"))
                  .empty());
}

// The walkthrough's typo: 30,62 and 20,46 where 40,62 and 70,46 were meant. Accepted (an
// overhang is valid), but said, at the vertex that lies behind its predecessor.
TEST(InputNotes, AnXOutOfOrderIsNotedAsAnOverhang) {
  TempDir dir;
  const fs::path csv = dir.write("p.csv",
                                 "x,z,material\n0,70,rock\n30,62,rock\n20,46,rock\n100,0,rock\n110,0,\n");
  const auto notes = notes_of(dir, base_with(9, "file = \"p.csv\""));
  ASSERT_EQ(notes.size(), 1u);
  const InputNote& n = notes[0];
  EXPECT_EQ(n.file, csv);
  EXPECT_EQ(n.line, 4);
  EXPECT_EQ(n.field, "x");
  const std::string text =
      "profile segment 1 (line 3 → line 4, x 30 → 20 m) runs back in x: it is read as an overhang "
      "(the air below it); check the x values if the slope has none";
  EXPECT_EQ(n.text, text);
  EXPECT_EQ(n.message(), csv.string() + ":4: x: " + text);
}

// One note per run of segments going back in x, not one per segment.
TEST(InputNotes, OneNotePerRunOfSegmentsGoingBack) {
  TempDir dir;
  const fs::path csv = dir.write("p.csv",
                                 "x,z,material\n"
                                 "0,70,rock\n"    // 2
                                 "40,60,rock\n"   // 3
                                 "35,55,rock\n"   // 4: back
                                 "30,50,rock\n"   // 5: back
                                 "50,40,rock\n"   // 6
                                 "45,35,rock\n"   // 7: back
                                 "100,0,rock\n"   // 8
                                 "110,0,\n");     // 9
  const auto notes = notes_of(dir, base_with(9, "file = \"p.csv\""));
  ASSERT_EQ(notes.size(), 2u);
  EXPECT_EQ(notes[0].line, 4);
  EXPECT_EQ(notes[0].text,
            "profile segments 1-2 (line 3 → line 5, x 40 → 30 m) run back in x: they are read as "
            "an overhang (the air below them); check the x values if the slope has none");
  EXPECT_EQ(notes[1].line, 7);
  EXPECT_EQ(notes[1].field, "x");
  EXPECT_NE(notes[1].text.find("profile segment 4 (line 6 → line 7, x 50 → 45 m) runs back in x"),
            std::string::npos)
      << notes[1].text;
}

// Inline points: the note names the point by its field, at the TOML line.
TEST(InputNotes, InlinePointsAreNamedByTheirField) {
  TempDir dir;
  const fs::path s = dir.path() / "s.toml";
  const auto notes = notes_of(dir, base_with(9, "points = [[0.0, 10.0, \"rock\"], [10.0, 0.0, \"rock\"], "
                                                "[8.0, -1.0, \"rock\"], [20.0, -2.0, \"\"]]"));
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0].message(),
            s.string() + ":9: profile.points[2]: profile segment 1 (profile.points[1] → "
                         "profile.points[2], x 10 → 8 m) runs back in x: it is read as an overhang "
                         "(the air below it); check the x values if the slope has none");
}

// The walkthrough's source 4 880 m above the ground (z = 5000 over a profile at about 120 m).
TEST(InputNotes, ASourceFarAboveTheGroundIsNoted) {
  TempDir dir;
  const fs::path s = dir.path() / "s.toml";
  const auto notes = notes_of(dir, base_with(22, "z = 5000.0"));
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0].file, s);
  EXPECT_EQ(notes[0].line, 22);
  EXPECT_EQ(notes[0].field, "sources[0].z");
  EXPECT_EQ(notes[0].message(),
            s.string() +
                ":22: sources[0].z: source \"S1\" is 4991 m above the ground under it (z = 5000 m; "
                "the ground at x = 1 m is at 9.0 m), more than 100 m and more than the profile's "
                "whole height (10.0 m, z from 0.0 to 10.0 m): its blocks fall freely that far "
                "before their first impact, which then governs the results. Check that z is an "
                "elevation of the same kind as the profile's (local, or absolute such as m "
                "a.s.l.); a source on or below the ground starts on it. If it is meant, confirm it in "
                "the scenario: [confirmed] \"sources[0].z\" = 5000");
}

// The threshold: more than 100 m and more than the profile's whole height. A drop from the
// lip of a high face onto the ground far below (less than the section's height) is a release
// from the slope drawn; a source below the ground (placed on it) says nothing either.
TEST(InputNotes, TheThresholdIsAHundredMetresAndTheProfilesHeight) {
  TempDir dir;
  EXPECT_TRUE(notes_of(dir, base_with(22, "z = 108.0")).empty());     // 99 m above the ground
  EXPECT_EQ(notes_of(dir, base_with(22, "z = 110.0")).size(), 1u);    // 101 m
  EXPECT_TRUE(notes_of(dir, base_with(22, "z = 5.0")).empty());       // 4 m inside: placed on it
  EXPECT_TRUE(notes_of(dir, base_with(22, "z = -90.0")).empty());     // 99 m inside
  const auto deep = notes_of(dir, base_with(22, "z = -5000.0"));      // far inside: noted too
  ASSERT_EQ(deep.size(), 1u);
  EXPECT_NE(deep[0].text.find("is 5009 m below the ground over it"), std::string::npos)
      << deep[0].text;
  const std::string tall = "points = [[0.0, 400.0, \"rock\"], [10.0, 0.0, \"rock\"], [200.0, 0.0, \"\"]]";
  auto scenario = [&](const std::string& source) {
    return base_with({{9, tall},
                      {21, source},
                      {22, "z = " + std::string(source == "x = 100.0" ? "350.0" : "420.0")},
                      // the line ahead of the source (behind it is noted too)
                      {26, "x = 180.0"}});
  };
  EXPECT_TRUE(notes_of(dir, scenario("x = 100.0")).empty());  // 350 m: less than 400 m
  const auto n = notes_of(dir, scenario("x = 150.0"));         // 420 m: more
  ASSERT_EQ(n.size(), 1u);
  EXPECT_NE(n[0].text.find("is 420 m above the ground under it"), std::string::npos) << n[0].text;
  EXPECT_NE(n[0].text.find("whole height (400.0 m, z from 0.0 to 400.0 m)"), std::string::npos)
      << n[0].text;
}

// The unit slips of a block table change every energy a thousandfold and pass every range
// check: a density in t/m³ (2.65), masses in tonnes, volumes in litres. Each is noted once, at
// the value that holds it.
TEST(InputNotes, ADensityInTonnesPerCubicMetreIsNoted) {
  TempDir dir;
  const fs::path s = dir.path() / "s.toml";
  // The base's block is given by its mass (line 18): the density makes its volume, not its mass.
  const auto notes = notes_of(dir, base_with(16, "[blocks]\ndensity = 2.65"));
  ASSERT_EQ(notes.size(), 1u);  // and not the light blocks too: the density says why
  EXPECT_EQ(notes[0].message(),
            s.string() + ":17: blocks.density: the block density 2.65 kg/m³ is outside the "
                         "densities of rock (1500 to 4000 kg/m³). A density is in kg/m³: if "
                         "2.65 is in t/m³ (or g/cm³), it is 2650 kg/m³; as typed, it gives blocks "
                         "1000 times too large in volume for their masses (10 times in radius), "
                         "and with the radius the restitution, the roughness, the stop criterion "
                         "c_stop·R and the free board. If it is meant, confirm "
                "it in the scenario: [confirmed] \"blocks.density\" = 2.65");
  // Given by volume, the density makes the mass.
  const auto by_volume =
      notes_of(dir, base_with({{16, "[blocks]\ndensity = 2.65"}, {18, "volume = 1.0"}}));
  ASSERT_EQ(by_volume.size(), 1u);
  EXPECT_NE(by_volume[0].text.find("as typed, it gives blocks 1000 times too light, and every "
                                   "energy 1000 times too small. If"),
            std::string::npos)
      << by_volume[0].text;
  // Both kinds of row take it: each is said.
  const auto both = notes_of(dir, base_with(18, "volume = 1.0\n[[blocks.table]]\nmass = 900.0"));
  EXPECT_TRUE(both.empty());  // 2650 kg/m³, the default
  const auto mixed = notes_of(
      dir, base_with({{16, "[blocks]\ndensity = 2.65"}, {18, "volume = 1.0\n[[blocks.table]]\nmass = 900.0"}}));
  ASSERT_EQ(mixed.size(), 1u);
  EXPECT_NE(mixed[0].text.find("as typed, it gives the blocks given by volume 1000 times too "
                               "light, and their energies 1000 times too small; and the blocks "
                               "given by mass 1000 times too large in volume"),
            std::string::npos)
      << mixed[0].text;
  // Every row with a density of its own: this one changes nothing, and is not noted (a note would
  // make every line of the run doubted, and --strict refuse it).
  EXPECT_TRUE(notes_of(dir, base_with({{16, "[blocks]\ndensity = 2.65"},
                                       {18, "mass = 900.0\ndensity = 2700.0"}}))
                  .empty());
  // A density that is not rock in t/m³ either (a digit too many) is not read as one.
  const auto typo = notes_of(dir, base_with(16, "[blocks]\ndensity = 26500.0"));
  ASSERT_EQ(typo.size(), 1u);
  EXPECT_EQ(typo[0].text, "the block density 26500 kg/m³ is outside the densities of rock (1500 "
                          "to 4000 kg/m³). A density is in kg/m³. If it is meant, confirm it in the scenario: "
            "[confirmed] \"blocks.density\" = 26500");
  // Rows of their own: the first one said, with how many more.
  const auto rows = notes_of(
      dir, base_with(17, "[[blocks.table]]\nid = \"a\"\nvolume = 1.0\ndensity = 2.7\n"
                         "[[blocks.table]]\nid = \"b\"\nvolume = 1.0\ndensity = 2.7\n"
                         "[[blocks.table]]\nid = \"c\""));  // and line 18's mass
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].line, 20);  // at the density that holds the slip, not the row's id
  EXPECT_EQ(rows[0].field, "blocks.table[0].density");
  EXPECT_NE(rows[0].text.find("block \"a\" has a density of 2.7 kg/m³ (and 1 more rows like "
                              "it), outside the densities of rock"),
            std::string::npos)
      << rows[0].text;
  EXPECT_NE(rows[0].text.find("gives blocks 1000 times too light"), std::string::npos)
      << rows[0].text;  // "a" is given by volume
  // The bounds themselves are rock.
  EXPECT_TRUE(notes_of(dir, base_with(16, "[blocks]\ndensity = 1500.0")).empty());
  EXPECT_TRUE(notes_of(dir, base_with(16, "[blocks]\ndensity = 4000.0")).empty());
}

TEST(InputNotes, BlocksInTonnesOrLitresAreNoted) {
  TempDir dir;
  const auto tonnes = notes_of(dir, base_with(18, "mass = 2.5"));
  ASSERT_EQ(tonnes.size(), 1u);
  EXPECT_EQ(tonnes[0].line, 18);  // at the mass that holds the slip
  EXPECT_EQ(tonnes[0].field, "blocks.table[0].mass");
  EXPECT_NE(tonnes[0].text.find("the heaviest block, \"B1\", weighs 2.5 kg: a mass is in kg"),
            std::string::npos)
      << tonnes[0].text;
  // 1500 litres typed as m³, at the default 2650 kg/m³: 3 975 000 kg.
  const auto litres = notes_of(dir, base_with(18, "volume = 1500.0"));
  ASSERT_EQ(litres.size(), 1u);
  EXPECT_NE(litres[0].text.find("weighs 3975 t (1500 m³), more than rockfall blocks weigh"),
            std::string::npos)
      << litres[0].text;
  // The heaviest block decides: light stones beside a real block are a valid mix.
  EXPECT_TRUE(notes_of(dir, base_with(18, "mass = 10.0")).empty());
  EXPECT_EQ(notes_of(dir, base_with(18, "mass = 9.9")).size(), 1u);
  EXPECT_TRUE(notes_of(dir, base_with(18, "mass = 2.5\n[[blocks.table]]\nmass = 800.0")).empty());
  EXPECT_TRUE(notes_of(dir, base_with(18, "mass = 1e6")).empty());
  // One row in tonnes among rows by volume: the heaviest block is real, the row is not.
  const auto mixed = notes_of(
      dir, base_with(18, "volume = 0.5\n[[blocks.table]]\nid = \"T\"\nmass = 2.5\n"
                         "[[blocks.table]]\nvolume = 2.0"));
  ASSERT_EQ(mixed.size(), 1u);
  EXPECT_EQ(mixed[0].line, 21);
  EXPECT_EQ(mixed[0].field, "blocks.table[1].mass");
  EXPECT_EQ(mixed[0].text, "block \"T\" is given by its mass, 2.5 kg, among rows given by volume "
                           "that weigh 1325 to 5300 kg: a mass is in kg; if it is in tonnes, it "
                           "is 2500 kg. If it is meant, confirm it in the scenario: [confirmed] "
            "\"blocks.table[1].mass\" = 2.5");
  // A light stone among them that is no block in tonnes either (0.01 kg: 10 kg, not a block of
  // the table's size) is a valid mix.
  EXPECT_TRUE(notes_of(dir, base_with(18, "volume = 0.5\n[[blocks.table]]\nmass = 0.01\n"
                                          "[[blocks.table]]\nvolume = 2.0"))
                  .empty());
  // One row in tonnes among rows in kg (1.69 among 1500 to 3500 kg): a hundredth of the
  // median block, and of its size read in kg.
  auto masses = [](std::initializer_list<const char*> ms) {
    std::string t;
    for (const char* m : ms) t += std::string(t.empty() ? "" : "[[blocks.table]]\n") + "mass = " + m + "\n";
    return t;
  };
  const auto kg = notes_of(dir, base_with(18, masses({"1500.0", "2500.0", "1.69", "3500.0"})));
  ASSERT_EQ(kg.size(), 1u);
  EXPECT_EQ(kg[0].field, "blocks.table[2].mass");
  EXPECT_EQ(kg[0].line, 22);
  EXPECT_THAT(kg[0].text, testing::StartsWith("block \"B3\" weighs 1.69 kg, where the median block "
                                              "weighs 2500 kg: a mass is in kg; if it is in "
                                              "tonnes, it is 1690 kg"));
  // Two such rows do not hide each other.
  const auto two = notes_of(dir, base_with(18, masses({"1500.0", "2.5", "2500.0", "1.69", "3500.0"})));
  ASSERT_EQ(two.size(), 1u);
  EXPECT_THAT(two[0].text, testing::HasSubstr("weighs 2.5 kg (and 1 more row like it)"));
  // A varied set (Preg's 0.14 to 8.13 Mg) is valid, and so is a stone too small to be a
  // block in tonnes (0.01 kg: 10 kg against a median of 2500).
  EXPECT_TRUE(notes_of(dir, base_with(18, masses({"140.0", "1500.0", "8130.0"}))).empty());
  EXPECT_TRUE(notes_of(dir, base_with(18, masses({"1500.0", "2500.0", "0.01", "3500.0"}))).empty());
  // An 8 t block and a 0.6 t one typed in tonnes among 1500 to 3500 kg are asked about; a row
  // that read in kg would be over three times the heaviest is not (12 000 kg against 3500 kg).
  for (const char* slip : {"8.0", "0.6"})
    EXPECT_EQ(notes_of(dir, base_with(18, masses({"1500.0", "2500.0", slip, "3500.0"}))).size(), 1u) << slip;
  EXPECT_TRUE(notes_of(dir, base_with(18, masses({"1500.0", "2500.0", "12.0", "3500.0"}))).empty());
}

// The roughness is a tangent scale, the one input that is not in degrees: an angle (35) or a
// percentage (65) typed into it passes its range check.
TEST(InputNotes, ARoughnessLikeAnAngleIsNoted) {
  TempDir dir;
  const fs::path s = dir.path() / "s.toml";
  const auto notes = notes_of(dir, base_with(14, "roughness = 35.0"));
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0].message(),
            s.string() + ":14: materials.rock.roughness: roughness 35 is a tangent scale, not an "
                         "angle or a percentage: tan θ = roughness · X, and with X about 0.5 the "
                         "typical roughness angle is 87° (the calibrated sets use 0.3 to 0.72, "
                         "typically 0.3 to 1.5). If it is meant, confirm it in the scenario: [confirmed] "
                "\"materials.rock.roughness\" = 35");
  EXPECT_NE(notes_of(dir, base_with(14, "roughness = 2.5"))[0].text.find("angle is 51°"),
            std::string::npos);  // atan(1.25)
  EXPECT_TRUE(notes_of(dir, base_with(14, "roughness = 2.0")).empty());
  // Over a preset too: where the value is written.
  const auto over = notes_of(dir, base_with({{12, "preset = \"talus\""}, {14, "roughness = 65.0"}}));
  ASSERT_EQ(over.size(), 1u);
  EXPECT_EQ(over[0].line, 14);
}

// A friction angle in radians (0.52 for 30°) passes its range check and lets blocks slide
// almost freely; 0 is a frictionless test, meant as such.
TEST(InputNotes, AFrictionAngleLikeRadiansIsNoted) {
  TempDir dir;
  const fs::path s = dir.path() / "s.toml";
  const auto notes = notes_of(dir, base_with(14, "roughness = 0.5\nfriction_angle = 0.52"));
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0].message(),
            s.string() + ":15: materials.rock.friction_angle: friction angle 0.52° is in degrees "
                         "(the calibrated sets use 30°): if it is in radians, it is 29.8°; as "
                         "typed, blocks slide almost without friction. If it is meant, confirm it in the "
                "scenario: [confirmed] \"materials.rock.friction_angle\" = 0.52");
  EXPECT_TRUE(notes_of(dir, base_with(14, "roughness = 0.5\nfriction_angle = 0.0")).empty());
  EXPECT_TRUE(notes_of(dir, base_with(14, "roughness = 0.5\nfriction_angle = 1.6")).empty());
}

// Lines count crossings in the vertex order, away from the sources: one upslope of every source
// is crossed by no block (a design there has nothing to stand on), said at its x.
TEST(InputNotes, ALineBehindEverySourceIsNoted) {
  TempDir dir;
  const fs::path s = dir.path() / "s.toml";
  const auto notes = notes_of(dir, base_with(26, "x = 0.5"));
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0].message(),
            s.string() + ":26: observation_lines[0].x: observation line \"L\" (x = 0.5 m) lies "
                         "behind every source (the nearest, \"S1\", is at x = 1 m): lines count "
                         "the blocks that cross them in the profile's vertex order, away from the "
                         "sources, so none reaches this one unless it bounces back past it. Check "
                         "x, or the order of the profile's vertices");
  EXPECT_TRUE(notes_of(dir, base_with(26, "x = 1.0")).empty());  // at the source: not behind it
  // Behind one source but ahead of another: that one's blocks reach it.
  EXPECT_TRUE(notes_of(dir, base_with({{23, "[[sources]]\nx = 0.2\nz = 11.0\n"}, {26, "x = 0.5"}}))
                  .empty());
}

// A barrier on such a line has nothing to be designed from: the note is a likely slip for it,
// doubting that barrier's lines (each barrier on the line its own), so that --strict refuses it
// (new-user review: a design that got no crossing passed `check --strict`). Without a barrier
// on it, the note doubts nothing.
TEST(InputNotes, ALineBehindEverySourceIsInDoubtForTheBarriersOnIt) {
  TempDir dir;
  const std::string behind = pierre::test::base_with(26, "x = 0.5") +
                             "\n[[observation_lines]]\nname = \"M\"\nx = 15.0\n";
  auto barrier = [](const char* name, const char* line) {
    return fmt::format("\n[[barriers]]\nname = \"{}\"\nline = \"{}\"\nrules = \"thesis-2015\"\n",
                       name, line);
  };
  const auto plain = notes_of(dir, behind + barrier("C", "M"));
  ASSERT_EQ(plain.size(), 1u);
  EXPECT_FALSE(plain[0].doubt);
  const auto notes = notes_of(dir, behind + barrier("A", "L") + barrier("C", "M") + barrier("B", "L"));
  ASSERT_EQ(notes.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(notes[i].message(), notes[0].message());  // the line's note, once per barrier
    ASSERT_TRUE(notes[i].doubt);
    EXPECT_EQ(notes[i].doubt->field, "observation_lines[0].x");
    EXPECT_EQ(notes[i].doubt->subject, i == 0 ? "A" : "B");
    EXPECT_TRUE(notes[i].doubt->ids.empty());  // every line of the barrier
    EXPECT_EQ(notes[i].doubt->value, 0.5);
  }
  EXPECT_TRUE(notes[0].message().ends_with("If it is meant, confirm it in the scenario: "
                                           "[confirmed] \"observation_lines[0].x\" = 0.5"))
      << notes[0].message();
}

// A quarry section's profile and sources are read by the same readers: its notes are the
// scenario's, named by the section's field.
TEST(InputNotes, AQuarrySectionsNotesAreTheScenarios) {
  TempDir dir;
  const std::string text = pit("", 500.0);
  const auto l = load_scenario(dir.write("s.toml", text), kRules);
  ASSERT_EQ(l.notes.size(), 1u);
  EXPECT_EQ(l.notes[0].line, 15);
  EXPECT_EQ(l.notes[0].field, "quarries[0].sources[0].z");
  EXPECT_TRUE(l.notes[0].text.starts_with("source \"S1\" is 481 m above the ground under it"))
      << l.notes[0].text;
}

// A toe given on the face makes the steep face part of the floor, and a height given far from
// crest z − toe z divides every distance by another H: both are taken, and noted at their keys.
// The section's found toe is x = 20 (pit).
TEST(InputNotes, AToeGivenOnTheFaceAndAFarHeightAreNoted) {
  TempDir dir;
  const auto on_face = load_scenario(dir.write("s.toml", pit("toe = 15.0\nheight = 10.0", 20.0)), kRules);
  ASSERT_EQ(on_face.notes.size(), 1u) << on_face.notes[0].message();  // H = 20 − 10 = 10: as given
  EXPECT_EQ(on_face.notes[0].line, 13);
  EXPECT_EQ(on_face.notes[0].field, "quarries[0].toe");
  // The face from x = 15 (where the toe cuts it) to 20 m: atan(20 / 10) = 63.43°.
  EXPECT_EQ(on_face.notes[0].text,
            "the floor past the given toe (x = 15 m) has 1 segment steeper than the rule set's "
            "floor angle of 15°: segment 2 (x 15 → 20 m, 63°). Every distance from the toe, and H, "
            "are measured from it; the toe found from the section is at x = 20.00 m. If it is "
            "meant, confirm it in the scenario: [confirmed] \"quarries[0].toe\" = 15");
  // A likely slip every line of the section rests on (new-user review: the zone lines still
  // passed, and --strict took it).
  ASSERT_TRUE(on_face.notes[0].doubt);
  EXPECT_EQ(on_face.notes[0].doubt->subject, "East");
  EXPECT_TRUE(on_face.notes[0].doubt->ids.empty());
  EXPECT_TRUE(load_scenario(dir.write("s.toml", pit("toe = 20.0", 20.0)), kRules).notes.empty());
  EXPECT_TRUE(load_scenario(dir.write("s.toml", pit("toe = 40.0\nheight = 21.9", 20.0)), kRules)
                  .notes.empty());  // 9.5 % above the 20 m the section gives
  const auto high = load_scenario(dir.write("s.toml", pit("height = 25.0", 20.0)), kRules);
  ASSERT_EQ(high.notes.size(), 1u);
  EXPECT_EQ(high.notes[0].field, "quarries[0].height");
  EXPECT_EQ(high.notes[0].text,
            "the height given (H = 25 m) differs from crest z − toe z (20.00 m) by 25 %: every "
            "distance divided by H uses the given one. If it is meant, confirm it in the "
            "scenario: [confirmed] \"quarries[0].height\" = 25");
  ASSERT_TRUE(high.notes[0].doubt);
  EXPECT_EQ(high.notes[0].doubt->subject, "East");
}

// A catch bench or a work area past the end of the floor (70 m from the pit's toe): a length in
// cm passes every range check. Noted at its value; one within the floor is not.
TEST(InputNotes, ABenchOrAWorkAreaPastTheFloorIsNoted) {
  TempDir dir;
  const auto l = load_scenario(
      dir.write("s.toml", pit("bench_width = 300.0\nwork_areas = [{ name = \"road\", distance = "
                              "69.0 }, { name = \"crusher\", distance = 700.0 }]",
                              20.0)),
      kRules);
  ASSERT_EQ(l.notes.size(), 2u);
  EXPECT_EQ(l.notes[0].line, 13);
  EXPECT_EQ(l.notes[0].field, "quarries[0].bench_width");
  EXPECT_EQ(l.notes[0].text,
            "bench width 300 m: the section's floor ends 70.00 m from the toe, so the section "
            "cannot say what reaches 300 m; extend the floor, or check the unit (if it is in cm, "
            "it is 3 m). If it is meant, confirm it in the scenario: [confirmed] "
            "\"quarries[0].bench_width\" = 300");
  EXPECT_EQ(l.notes[1].field, "quarries[0].work_areas[1].distance");
  EXPECT_NE(l.notes[1].text.find("work area \"crusher\" at 700 m from the toe: the section's "
                                 "floor ends 70.00 m"),
            std::string::npos)
      << l.notes[1].text;
  EXPECT_TRUE(load_scenario(dir.write("s.toml", pit("bench_width = 70.0", 20.0)), kRules)
                  .notes.empty());
}

}  // namespace
