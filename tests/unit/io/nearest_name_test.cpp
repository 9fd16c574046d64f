// The nearest name said after a list of valid ones (nearest_name.hpp): close enough to be the
// typo, never a guess between two, and what it makes of real mistakes (the user review's
// [[observation_line]] and "asphalt" for a table named asfalt).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "pierre/io/nearest_name.hpp"
#include "pierre/io/scenario_reader.hpp"
#include "test_files.hpp"

namespace {

using pierre::io::detail::nearest_name;
using pierre::io::detail::nearest_name_hint;

const std::vector<std::string> kRoot = {"scenario", "simulation",        "profile",  "materials", "blocks",
                                        "sources",  "observation_lines", "barriers", "quarries"};

TEST(NearestName, OneNameWithinAFewEdits) {
  EXPECT_EQ(nearest_name("observation_line", kRoot), "observation_lines");  // a deletion
  EXPECT_EQ(nearest_name("source", kRoot), "sources");
  EXPECT_EQ(nearest_name("simluation", kRoot), "simulation");  // neighbours swapped: one edit
  EXPECT_EQ(nearest_name("Blocks", kRoot), "blocks");          // letter case is no edit
  EXPECT_EQ(nearest_name("asphalt", {"scree", "asfalt"}), "asfalt");  // two edits in seven letters
  EXPECT_EQ(nearest_name("tallus", {"talus", "talus-vaujany", "rock-face"}), "talus");
}

TEST(NearestName, NothingWhenNoneIsCloseOrTwoAreAsClose) {
  EXPECT_EQ(nearest_name("colour", kRoot), "");
  EXPECT_EQ(nearest_name("granite", {"talus", "road"}), "");
  EXPECT_EQ(nearest_name("x", {"y", "z"}), "");       // one edit from each: no guess
  EXPECT_EQ(nearest_name("ab", {"abcd"}), "");        // two edits in a short name: too far
  EXPECT_EQ(nearest_name("sources", kRoot), "");      // a valid name is no typo
  EXPECT_EQ(nearest_name("", kRoot), "");
  EXPECT_EQ(nearest_name_hint("colour", kRoot), "");
  EXPECT_EQ(nearest_name_hint("source", kRoot), "; the nearest is sources");
}

// A name typed short, too many edits from the long one it begins (a new user's "freeboard" and
// a candidate's "elongation"): the names beginning so, up to three, '_' and case ignored.
TEST(NearestName, ANameThatBeginsALongerOne) {
  const std::vector<std::string> barrier = {"name", "line", "free_board_diameter", "design_block"};
  EXPECT_EQ(nearest_name("freeboard", barrier), "");  // 10 edits: too far for the typo rule
  EXPECT_EQ(nearest_name_hint("freeboard", barrier), "; the nearest is free_board_diameter");
  EXPECT_EQ(nearest_name_hint("Free-Board", barrier), "; the nearest is free_board_diameter");
  const std::vector<std::string> candidate = {"mel", "sel", "elongation_mel", "elongation_sel"};
  EXPECT_EQ(nearest_name_hint("elongation", candidate),
            "; the nearest are elongation_mel or elongation_sel");
  EXPECT_EQ(nearest_name_hint("me", candidate), "; the nearest is mel");  // the typo rule first
  // Too short to mean one name, or the start of too many: nothing.
  EXPECT_EQ(nearest_name_hint("ele", candidate), "");
  EXPECT_EQ(pierre::io::detail::names_beginning_with("size", {"size_a", "size_b", "size_c", "size_d"}).size(), 4u);
  EXPECT_EQ(nearest_name_hint("size", {"size_a", "size_b", "size_c", "size_d"}), "");
}

// In the messages: an unknown key and an undefined material end with the nearest name.
TEST(NearestName, SaidAfterTheValidNames) {
  pierre::test::TempDir dir;
  auto expected_of = [&](const std::string& text) {
    try {
      (void)pierre::io::load_scenario(dir.write("s.toml", text), PIERRE_SOURCE_DIR "/rules");
    } catch (const pierre::io::InputError& e) {
      return e.expected();
    }
    return std::string("no error");
  };
  std::string key = expected_of(pierre::test::base_with(24, "[[observation_line]]"));
  EXPECT_TRUE(key.ends_with("quarries, confirmed; the nearest is observation_lines")) << key;
  EXPECT_EQ(key.rfind("one of scenario, simulation, ", 0), 0u) << key;
  const std::string material = expected_of(pierre::test::base_with(
      9, "points = [[0.0, 10.0, \"rok\"], [10.0, 0.0, \"rock\"], [20.0, 0.0, \"\"]]"));
  EXPECT_EQ(material, "a material defined in [materials] (rock); the nearest is rock");
}

}  // namespace
