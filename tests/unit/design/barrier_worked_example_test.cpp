// The worked test of design-checks.md §1: thesis-2015 on Table 4.1's own inputs reproduces
// Table 4.1 (at its printed 3 significant figures), and Table D.2's height fits to the
// observations reproduce Table 4.2's P(h > h_i) within ±0.15 percentage points.
#include <gtest/gtest.h>

#include <cmath>

#include "barrier_fixtures.hpp"
#include "pierre/design/barrier_check.hpp"

namespace {

using namespace pierre;

// x rounded to 3 significant figures.
double sig3(double x) {
  const double e = std::floor(std::log10(std::abs(x)));
  const double scale = std::pow(10.0, 2 - e);
  return std::round(x * scale) / scale;
}

struct Screen {
  double v_p, h_k;                       // Table 4.1's v_p (= v_t γF) and the P95 bounce height
  double sel, mel, h_i;                  // exact values from the formulas (design-checks.md)
  double sel_printed, mel_printed, h_i_printed;  // Table 4.1
  double lambda, k;                      // Table D.2, jump height fit to the observations
  double p_h_exact, p_h_printed;         // S(h_i) and Table 4.2's printed P(h > h_i), %
};

const Screen kScreens[] = {
    {24.0, 3.42, 1066.9, 1386.9, 4.02, 1070, 1390, 4.02, 1.55, 1.37, 2.50, 2.4},
    {24.9, 3.56, 1148.4, 1492.9, 4.16, 1150, 1490, 4.16, 1.81, 1.23, 6.18, 6.2},
};

design::DesignValues values_for(const Screen& s, const design::BarrierRuleSet& r) {
  design::DesignInputs in;
  in.v_k = s.v_p / 1.16;  // Table 4.1's v_p ÷ γF, unrounded
  in.h_k = s.h_k;
  in.volume = 1.26;
  in.density = 2800;
  in.free_board_diameter = 1.2;
  const auto d = design::design_values(r, test::etag027(), in);
  EXPECT_TRUE(d.ok()) << d.error;
  return *d;
}

TEST(BarrierWorkedExample, Table41DesignMassEnergiesAndHeight) {
  for (const Screen& s : kScreens) {
    SCOPED_TRACE(s.v_p);
    const design::DesignValues d = values_for(s, test::thesis_2015());
    EXPECT_NEAR(d.v_d, s.v_p, 1e-12);
    EXPECT_NEAR(d.m_d, 3704.4, 1e-9);
    EXPECT_NEAR(d.E_d_kJ, s.sel, 0.05);
    EXPECT_NEAR(d.SEL_req_kJ, s.sel, 0.05);
    EXPECT_NEAR(d.MEL_req_kJ, s.mel, 0.05);
    EXPECT_NEAR(d.free_board, 0.6, 1e-12);
    EXPECT_NEAR(d.h_d, s.h_k, 1e-12);
    EXPECT_NEAR(d.h_i, s.h_i, 1e-12);
    // Table 4.1 as printed, at its 3 significant figures.
    EXPECT_NEAR(sig3(d.m_d), 3700, 1e-9);
    EXPECT_NEAR(sig3(d.SEL_req_kJ), s.sel_printed, 1e-9);
    EXPECT_NEAR(sig3(d.MEL_req_kJ), s.mel_printed, 1e-9);
    EXPECT_NEAR(sig3(d.h_i), s.h_i_printed, 1e-9);
  }
}

// design-checks.md's worked test says class 6 and 4 with its eight-class table; with ETAG 027's
// nine (class 4 = MEL 1500 kJ) the same SEL 1500 kJ is class 7, and MEL alone is still class 4.
TEST(BarrierWorkedExample, EnergyClassBothIsSevenMelAloneIsFour) {
  for (const Screen& s : kScreens) {
    SCOPED_TRACE(s.v_p);
    const design::DesignValues both = values_for(s, test::thesis_2015());
    ASSERT_TRUE(both.energy_class);
    EXPECT_EQ(both.energy_class->number, 7);  // SEL 1500 >= 1067 / 1148; class 6's 1000 is not
    auto mel_only = test::thesis_2015();
    mel_only.design_on = design::DesignOn::mel;
    const design::DesignValues mel = values_for(s, mel_only);
    ASSERT_TRUE(mel.energy_class);
    EXPECT_EQ(mel.energy_class->number, 4);  // MEL 1500 >= 1387 / 1493; class 3's 1000 is not
  }
}

TEST(BarrierWorkedExample, Table42HeightExceedanceFromTableD2Fits) {
  for (const Screen& s : kScreens) {
    SCOPED_TRACE(s.v_p);
    const design::DesignValues d = values_for(s, test::thesis_2015());
    design::ExceedanceInputs ex;
    ex.SEL_req_kJ = d.SEL_req_kJ;
    ex.MEL_req_kJ = d.MEL_req_kJ;
    ex.h_i = d.h_i;
    ex.h_max_sim = 10;
    ex.observed_height = stats::WeibullFit{s.k, s.lambda, 0, 0};
    const auto rows = design::exceedance_rows(ex);
    ASSERT_EQ(rows.size(), 4u);
    EXPECT_EQ(rows[2].what, "P(h > h_i)");
    EXPECT_DOUBLE_EQ(rows[2].threshold, d.h_i);
    ASSERT_TRUE(rows[2].observed_weibull);
    const double pct = 100 * *rows[2].observed_weibull;
    EXPECT_NEAR(pct, s.p_h_exact, 0.005);     // exp(-(h_i/λ)^k)
    EXPECT_NEAR(pct, s.p_h_printed, 0.15);    // Table 4.2
    // No simulated fit was given: the simulated columns are empty (NaN), not zero.
    EXPECT_TRUE(std::isnan(rows[2].simulated_weibull));
    EXPECT_FALSE(rows[0].observed_weibull);   // no observed energy fit
  }
}

}  // namespace
