// [confirmed] (docs/scenario-format.md): an input noted as a likely slip that the engineer means
// is restated under the key its note gives, and loses its doubt; the key of a note on a CSV is the
// CSV's path from the scenario's folder, so that every note can be confirmed on its own.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "pierre/io/input_error.hpp"
#include "pierre/io/scenario_reader.hpp"
#include "test_files.hpp"

namespace {

namespace fs = std::filesystem;
using pierre::io::InputNote;
using pierre::io::load_scenario;
using pierre::test::TempDir;

const fs::path kRules = PIERRE_SOURCE_DIR "/rules";

// Two quarry sections, each with its blocks in a CSV of its own folder (a/blocks.csv,
// b/blocks.csv), both in tonnes: two notes on a column "mass" of a file "blocks.csv".
std::string two_sections(const std::string& confirmed) {
  std::string s = R"([scenario]
name = "two faces"

[simulation]
seed = 4
throws = 2

[materials.face]
preset = "quarry-face"
)";
  for (const char* name : {"a", "b"}) {
    s += std::string("\n[[quarries]]\nname = \"") + name +
         "\"\nprofile = { points = [[0.0, 20.0, \"face\"], [10.0, 20.0, \"face\"], [20.0, 0.0, "
         "\"face\"], [90.0, 0.0, \"\"]] }\nblocks = { file = \"" + name +
         "/blocks.csv\" }\nsources = [{ x = 10.3, z = 20.5 }]\n";
  }
  return s + confirmed;
}

// The two sections' CSVs: 1.5 and 2.5 kg, masses in tonnes.
void write_blocks(const TempDir& dir) {
  fs::create_directories(dir.path() / "a");
  fs::create_directories(dir.path() / "b");
  dir.write("a/blocks.csv", "id,mass\nA1,1.5\n");
  dir.write("b/blocks.csv", "id,mass\nB1,2.5\n");
}

std::vector<InputNote> doubting(const std::vector<InputNote>& notes) {
  std::vector<InputNote> out;
  for (const auto& n : notes)
    if (n.doubt) out.push_back(n);
  return out;
}

TEST(ConfirmedInputs, TwoCsvsOfOneNameAreConfirmedEachByItsPath) {
  TempDir dir;
  write_blocks(dir);
  const auto open = load_scenario(dir.write("s.toml", two_sections("")), kRules);
  const auto both = doubting(open.notes);
  ASSERT_EQ(both.size(), 2u);
  // Each note names its own key, and the check lines name the input by it.
  EXPECT_EQ(both[0].doubt->field, "a/blocks.csv:2:mass");
  EXPECT_EQ(both[1].doubt->field, "b/blocks.csv:2:mass");
  EXPECT_EQ(both[0].doubt->subject, "a");
  EXPECT_NE(both[0].text.find("[confirmed] \"a/blocks.csv:2:mass\" = 1.5"), std::string::npos)
      << both[0].text;
  // One confirmed: the other stays in doubt.
  const auto one = load_scenario(
      dir.write("s.toml", two_sections("\n[confirmed]\n\"b/blocks.csv:2:mass\" = 2.5\n")), kRules);
  const auto left = doubting(one.notes);
  ASSERT_EQ(left.size(), 1u);
  EXPECT_EQ(left[0].doubt->field, "a/blocks.csv:2:mass");
  // Both, each by its own key: none.
  const auto all = load_scenario(dir.write("s.toml", two_sections("\n[confirmed]\n\"a/blocks.csv:2:mass\" = 1.5\n"
                                                                  "\"b/blocks.csv:2:mass\" = 2.5\n")),
                                 kRules);
  EXPECT_TRUE(doubting(all.notes).empty());
  ASSERT_EQ(all.notes.size(), 2u);
  EXPECT_NE(all.notes[1].text.find("Confirmed as meant ([confirmed] \"b/blocks.csv:2:mass\" = 2.5, line "),
            std::string::npos)
      << all.notes[1].text;
}

// Quoted ("blocks.density") or nested (blocks = { density = ... }), a confirmation is one key:
// given both ways it is an error, not a second confirmation said to confirm nothing.
TEST(ConfirmedInputs, OneKeyGivenTwiceIsAnError) {
  TempDir dir;
  write_blocks(dir);
  const auto file = dir.write(
      "s.toml", two_sections("\n[confirmed]\n\"simulation.gravity\" = 3.7\nsimulation = { gravity = 3.7 }\n"));
  try {
    load_scenario(file, kRules);
    FAIL() << "no error";
  } catch (const pierre::io::InputError& e) {
    EXPECT_EQ(e.field(), "confirmed.simulation.gravity");  // the quoted key, line 24
    EXPECT_EQ(e.line(), 24);
    EXPECT_EQ(e.expected(), "\"simulation.gravity\" once (it is confirmed at line 25 too)");
  }
}

}  // namespace
