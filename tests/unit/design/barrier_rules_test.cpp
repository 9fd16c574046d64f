// Factor resolution (peila-ronco-2009 for every data-quality combination), data-quality
// questions, energy-class selection at its edges, residual height categories, rule column.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "barrier_fixtures.hpp"
#include "pierre/design/barrier_rules.hpp"

namespace {

using namespace pierre;
using design::DesignOn;

TEST(BarrierFactors, GivenValueResolvesToItself) {
  const auto r = test::thesis_2015();
  const auto f = design::resolve_factor(r.gamma_F, {});
  ASSERT_TRUE(f.ok()) << f.error;
  EXPECT_DOUBLE_EQ(f->value, 1.16);
  EXPECT_NE(f->how.find("given"), std::string::npos);
}

TEST(BarrierFactors, PeilaRoncoEveryDataQualityCombination) {
  const auto r = test::peila_ronco_2009();
  for (const char* traj : {"back-analysed", "literature"})
    for (const char* topo : {"high", "low"})
      for (const char* vol : {"surveyed", "estimated"}) {
        SCOPED_TRACE(std::string(traj) + " " + topo + " " + vol);
        const std::map<std::string, std::string> a = {
            {"trajectory", traj}, {"topography", topo}, {"block_volume", vol}};
        const double tr = std::string(traj) == "back-analysed" ? 1.02 : 1.10;
        const double dp = std::string(topo) == "high" ? 1.02 : 1.10;
        const double vf = std::string(vol) == "surveyed" ? 1.02 : 1.10;
        const auto gF = design::resolve_factor(r.gamma_F, a);
        const auto gM = design::resolve_factor(r.gamma_M, a);
        const auto gh = design::resolve_factor(r.gamma_h, a);
        ASSERT_TRUE(gF.ok() && gM.ok() && gh.ok());
        EXPECT_DOUBLE_EQ(gF->value, tr * dp);
        EXPECT_DOUBLE_EQ(gM->value, vf * 1.0);
        EXPECT_DOUBLE_EQ(gh->value, tr * dp);
        EXPECT_NE(gF->how.find(std::string("trajectory = ") + traj), std::string::npos) << gF->how;
        EXPECT_NE(gF->how.find(std::string("topography = ") + topo), std::string::npos) << gF->how;
      }
}

TEST(BarrierFactors, MissingOrUnknownAnswerFailsNamingTheOptions) {
  const auto r = test::peila_ronco_2009();
  const auto missing = design::resolve_factor(r.gamma_F, {{"trajectory", "literature"}});
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.error.find("topography"), std::string::npos) << missing.error;
  EXPECT_NE(missing.error.find("\"high\""), std::string::npos) << missing.error;
  EXPECT_NE(missing.error.find("\"low\""), std::string::npos) << missing.error;
  const auto wrong =
      design::resolve_factor(r.gamma_F, {{"trajectory", "guessed"}, {"topography", "high"}});
  ASSERT_FALSE(wrong.ok());
  EXPECT_NE(wrong.error.find("guessed"), std::string::npos) << wrong.error;
  EXPECT_NE(wrong.error.find("\"back-analysed\""), std::string::npos) << wrong.error;
}

TEST(BarrierFactors, QuestionsAreTheChoicesOfEveryPartOnce) {
  const auto q = design::data_quality_questions(test::peila_ronco_2009());
  ASSERT_EQ(q.size(), 3u);
  EXPECT_EQ(q.at("trajectory").size(), 2u);  // asked by γF and γh: listed once
  EXPECT_EQ(q.at("topography").size(), 2u);
  EXPECT_EQ(q.at("block_volume").size(), 2u);
  EXPECT_TRUE(design::data_quality_questions(test::thesis_2015()).empty());
}

TEST(EnergyClassSelection, BoundsAreInclusive) {
  const auto t = test::etag027();
  EXPECT_EQ(design::select_energy_class(t, DesignOn::mel, 3000, 0)->number, 6);
  EXPECT_EQ(design::select_energy_class(t, DesignOn::mel, 3000.001, 0)->number, 7);
  EXPECT_EQ(design::select_energy_class(t, DesignOn::sel, 0, 1000)->number, 6);
  EXPECT_EQ(design::select_energy_class(t, DesignOn::sel, 0, 1000.001)->number, 7);
  EXPECT_EQ(design::select_energy_class(t, DesignOn::mel, 1500, 0)->number, 4);
  EXPECT_EQ(design::select_energy_class(t, DesignOn::mel, 1500.001, 0)->number, 5);
}

TEST(EnergyClassSelection, ClassZeroHasNoSel) {
  const auto t = test::etag027();
  EXPECT_EQ(design::select_energy_class(t, DesignOn::mel, 50, 50)->number, 0);
  EXPECT_EQ(design::select_energy_class(t, DesignOn::sel, 50, 50)->number, 1);
  EXPECT_EQ(design::select_energy_class(t, DesignOn::both, 50, 50)->number, 1);
}

TEST(EnergyClassSelection, BothTakesTheStricterOfMelAndSel) {
  const auto t = test::etag027();
  // MEL 900 alone: class 3; SEL 900 alone: class 6 (1000); both: 6.
  EXPECT_EQ(design::select_energy_class(t, DesignOn::mel, 900, 900)->number, 3);
  EXPECT_EQ(design::select_energy_class(t, DesignOn::both, 900, 900)->number, 6);
  // MEL 2500 with SEL 500: MEL governs (class 6, SEL 1000 >= 500).
  EXPECT_EQ(design::select_energy_class(t, DesignOn::both, 2500, 500)->number, 6);
}

TEST(EnergyClassSelection, AboveTheClosedClassesIsTheOpenEndedOne) {
  const auto t = test::etag027();
  const auto c = design::select_energy_class(t, DesignOn::mel, 4500.5, 0);
  ASSERT_TRUE(c);
  EXPECT_EQ(c->number, 8);
  EXPECT_TRUE(c->open_ended);
  EXPECT_EQ(design::select_energy_class(t, DesignOn::mel, 4500, 0)->number, 7);
  auto closed = t;
  closed.classes.pop_back();
  EXPECT_FALSE(design::select_energy_class(closed, DesignOn::mel, 4500.5, 0));
  EXPECT_FALSE(design::select_energy_class(closed, DesignOn::sel, 0, 1600));
}

TEST(ResidualHeight, CategoriesAtTheirBounds) {
  const design::ResidualHeightCategories c{0.5, 0.3, ""};
  EXPECT_EQ(design::residual_height_category(c, 3.0, 6.0), "A");  // 50 %
  EXPECT_EQ(design::residual_height_category(c, 2.9, 6.0), "B");
  EXPECT_EQ(design::residual_height_category(c, 1.9, 6.0), "B");  // 31.7 %
  EXPECT_EQ(design::residual_height_category(c, 1.5, 5.0), "C");  // 30 %
  EXPECT_EQ(design::residual_height_category(c, 0.0, 5.0), "C");
  EXPECT_EQ(design::residual_height_category(c, 1.0, 0.0), "");
}

TEST(RuleReference, ClauseWhenGivenElseTheName) {
  auto r = test::thesis_2015();
  r.clauses["energy.mel"] = "§4.7 Table 4.1";
  EXPECT_EQ(design::rule_reference(r, "energy.mel"), "thesis-2015 §4.7 Table 4.1");
  EXPECT_EQ(design::rule_reference(r, "reach"), "thesis-2015");
}

}  // namespace
