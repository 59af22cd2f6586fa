#include "estimate/class_probabilities.h"

#include <gtest/gtest.h>

namespace proxyvis {
namespace {

TEST(ClassProbabilities, DerivedQuantitiesMatchDefinitions) {
  const ClassProbabilities c{0.2, 0.1, 0.3, 0.4};
  EXPECT_DOUBLE_EQ(c.vAvg(), 0.7);
  EXPECT_DOUBLE_EQ(c.fHit(), 0.2 / 0.3);
  EXPECT_DOUBLE_EQ(c.fMiss(), 0.4 / 0.7);
  EXPECT_DOUBLE_EQ(c.errorGivenProxyBlocked(), 0.3 / 0.5);
  EXPECT_DOUBLE_EQ(c.errorGivenProxyVisible(), 0.1 / 0.5);
  // The paper's parametrisation gives back the class probabilities.
  const double v = c.vAvg();
  EXPECT_NEAR((1 - v) * (1 - c.fHit()), c.hm, 1e-15);
  EXPECT_NEAR(v * (1 - c.fMiss()), c.mh, 1e-15);
}

TEST(ClassProbabilities, PriorKeepsPossibleClassesPositiveAndImpossibleOnesZero) {
  ClassCounts counts;
  for (int i = 0; i < 10; ++i) counts.add(true, true);  // only MM' observed
  const auto out = estimateClassProbabilities(counts, ProxyClass::kOutside, 0.5);
  EXPECT_EQ(out.hm, 0.0);  // outside: HM' impossible
  EXPECT_GT(out.hh, 0.0);
  EXPECT_GT(out.mh, 0.0);
  EXPECT_NEAR(out.mm, 10.5 / 11.5, 1e-15);
  const auto in = estimateClassProbabilities(counts, ProxyClass::kInside, 0.5);
  EXPECT_EQ(in.mh, 0.0);
  EXPECT_GT(in.hm, 0.0);
  const auto gen = estimateClassProbabilities(counts, ProxyClass::kGeneral, 0.5);
  EXPECT_NEAR(gen.hh + gen.hm + gen.mh + gen.mm, 1.0, 1e-15);
  EXPECT_NEAR(gen.hm, 0.5 / 12, 1e-15);
}

TEST(ClassProbabilities, PossibleClasses) {
  EXPECT_FALSE(classPossible(ProxyClass::kOutside, false, true));
  EXPECT_TRUE(classPossible(ProxyClass::kOutside, true, false));
  EXPECT_FALSE(classPossible(ProxyClass::kInside, true, false));
  EXPECT_TRUE(classPossible(ProxyClass::kInside, false, true));
  EXPECT_TRUE(classPossible(ProxyClass::kGeneral, false, true));
  EXPECT_TRUE(classPossible(ProxyClass::kGeneral, true, false));
}

}  // namespace
}  // namespace proxyvis
