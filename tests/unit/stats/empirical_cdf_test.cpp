// F_n(b) = #{x <= b} / n, worked by hand.
#include "pierre/stats/empirical_cdf.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace pierre::stats {
namespace {

TEST(EmpiricalCdf, OneToFourByHand) {
  const std::vector<double> x{4, 2, 3, 1};
  const std::vector<double> breaks{0, 1, 2.5, 4, 5};
  const std::vector<double> expected{0, 0.25, 0.5, 1, 1};  // right-continuous: F(1) counts 1
  EXPECT_EQ(empirical_cdf(x, breaks), expected);
}

TEST(EmpiricalCdf, TiesCountTogether) {
  const std::vector<double> x{1, 1, 1, 2};
  const std::vector<double> breaks{0.999, 1, 2};
  const std::vector<double> expected{0, 0.75, 1};
  EXPECT_EQ(empirical_cdf(x, breaks), expected);
}

TEST(EmpiricalCdf, CensoredValuesStayInTheDenominator) {
  // Two of four blocks left the profile (+inf): F never passes 1/2 on finite breaks.
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const std::vector<double> x{1, kInf, 2, kInf};
  const std::vector<double> breaks{1, 100};
  const std::vector<double> expected{0.25, 0.5};
  EXPECT_EQ(empirical_cdf(x, breaks), expected);
}

TEST(EmpiricalCdf, NaNLeftOutAndEmptyGivesNaN) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> x{kNaN, 1, 3};
  const std::vector<double> breaks{2};
  EXPECT_EQ(empirical_cdf(x, breaks)[0], 0.5);  // n = 2, not 3
  const std::vector<double> none;
  EXPECT_TRUE(std::isnan(empirical_cdf(none, breaks)[0]));
}

}  // namespace
}  // namespace pierre::stats
