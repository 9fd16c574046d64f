// The numbers a check line's reason compares: in the decimals its value and limit cells show,
// so that "height 6.00 m >= h_i 5.29 m" sits beside the cells 6.00 and 5.29 (it said 5.287), and
// with more where those decimals would print two different numbers alike.
#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "pierre/design/number_kind.hpp"

namespace {

using pierre::design::compared_texts;
using Texts = std::pair<std::string, std::string>;

TEST(ComparedTexts, InTheDecimalsOfTheirUnit) {
  EXPECT_EQ(compared_texts(6.0, 5.28712, "m"), (Texts{"6.00 m", "5.29 m"}));
  EXPECT_EQ(compared_texts(3000.0, 1571.93, "kJ"), (Texts{"3000.0 kJ", "1571.9 kJ"}));
  EXPECT_EQ(compared_texts(26.2861, 30.0, "m/s"), (Texts{"26.29 m/s", "30.00 m/s"}));
  EXPECT_EQ(compared_texts(57.2, 90.0, "%"), (Texts{"57.20 %", "90.00 %"}));
}

TEST(ComparedTexts, TwoNumbersThatDifferNeverPrintAlike) {
  // 1000.0 against 1000.04 kJ: a FAIL that read "1000.0 kJ < 1000.0 kJ".
  EXPECT_EQ(compared_texts(1000.0, 1000.04, "kJ"), (Texts{"1000.00 kJ", "1000.04 kJ"}));
  EXPECT_EQ(compared_texts(5.2901, 5.2949, "m"), (Texts{"5.290 m", "5.295 m"}));
  const auto [a, b] = compared_texts(5.0, 5.0 + 1e-7, "m");
  EXPECT_NE(a, b);
  // Equal numbers print alike, whatever the unit.
  EXPECT_EQ(compared_texts(12.0, 12.0, "m"), (Texts{"12.00 m", "12.00 m"}));
}

}  // namespace
