// The paper's selection estimator: measured variance against the corrected closed form
// (docs/design.md), the slides' misprint rejected, and the optimal probabilities against a grid.
#include "estimate/selection.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "estimate/sample_estimators.h"
#include "moments.h"
#include "test_mixes.h"
#include "util/stats.h"

namespace proxyvis {
namespace {

constexpr uint64_t kSeed = 20140625;  // fixed; never retuned
constexpr double kAlpha = 0.01;       // family-wise, per test

// Estimates at n independent light samples of one shading point with class mix c.
std::vector<double> sampleSelection(const ClassProbabilities& c, const SelectionProbabilities& p,
                                    size_t n, uint64_t stream, RayCounts& counts) {
  const SyntheticTracer tracer({c}, test::tracerSeed(kSeed, stream));
  std::vector<double> x(n);
  for (size_t i = 0; i < n; ++i) {
    Rng rng(kSeed, hashKeys(stream, i));
    x[i] = selectionSample(tracer, SyntheticTracer::segment(0, i), p, rng.uniformDouble(), counts);
  }
  return x;
}

struct Case {
  ProxyClass cls;
  SelectionProbabilities p;
};

std::vector<Case> varianceCases() {
  std::vector<Case> cases;
  for (ProxyClass cls : {ProxyClass::kOutside, ProxyClass::kInside, ProxyClass::kGeneral}) {
    const ClassProbabilities c = test::mixFor(cls);
    cases.push_back({cls, equalProbabilities(cls)});
    cases.push_back({cls, optimalProbabilities(c, cls)});
    cases.push_back({cls, costHeuristicProbabilities(optimalProbabilities(c, cls), c.error())});
  }
  cases.push_back({ProxyClass::kGeneral, {0.5, 0.1, 0.4}});
  cases.push_back({ProxyClass::kGeneral, {0.2, 0.5, 0.3}});
  return cases;
}

TEST(Selection, MeasuredVarianceMatchesCorrectedFormula) {
  const auto cases = varianceCases();
  const double z = sidakZ(kAlpha, 2 * cases.size());  // a mean and a variance check per case
  constexpr size_t kN = 200000;
  for (size_t k = 0; k < cases.size(); ++k) {
    const ClassProbabilities c = test::mixFor(cases[k].cls);
    RayCounts counts;
    const test::Moments m = test::moments(sampleSelection(c, cases[k].p, kN, k, counts));
    const double var = selectionVariance(c, cases[k].p);
    SCOPED_TRACE(testing::Message() << "case " << k << " class " << proxyClassName(cases[k].cls)
                                    << " p=(" << cases[k].p.p0 << "," << cases[k].p.p_plus << ","
                                    << cases[k].p.p_minus << ") seed " << kSeed);
    EXPECT_LE(std::abs(m.mean - c.vAvg()), z * std::sqrt(var / double(kN)));
    EXPECT_LE(std::abs(m.variance - var), z * m.variance_se)
        << "measured " << m.variance << " formula " << var;
    // Rays: one proxy ray per sample, originals only in correction branches that need them.
    const SelectionRays rays = selectionRays(c, cases[k].p);
    EXPECT_EQ(counts.proxy, kN);
    const double sd_orig = std::sqrt(rays.original * (1 - rays.original) / double(kN));
    EXPECT_LE(std::abs(double(counts.original) / kN - rays.original), z * sd_orig + 1e-12);
  }
}

// The talk slides print the HM' term over p+ instead of p-. With p+ != p- and P(HM') > 0 the
// two formulas differ; Monte Carlo must accept the corrected one and reject the slide's.
TEST(Selection, SlideMisprintIsRejectedByMonteCarlo) {
  const ClassProbabilities c = test::generalMix();
  const SelectionProbabilities p{0.5, 0.1, 0.4};
  const double correct = selectionVariance(c, p);
  const double slide = selectionVarianceSlideMisprint(c, p);
  ASSERT_GT(std::abs(slide - correct), 0.3);  // the case is chosen so that they differ clearly
  RayCounts counts;
  const test::Moments m = test::moments(sampleSelection(c, p, 400000, 99, counts));
  const double z = sidakZ(kAlpha, 2);
  EXPECT_LE(std::abs(m.variance - correct), z * m.variance_se)
      << "measured " << m.variance << " corrected formula " << correct;
  EXPECT_GT(std::abs(m.variance - slide), z * m.variance_se)
      << "measured " << m.variance << " slide formula " << slide;
}

TEST(Selection, EqualProbabilitiesDropVerifiedBranches) {
  const auto g = equalProbabilities(ProxyClass::kGeneral);
  EXPECT_DOUBLE_EQ(g.p0 + g.p_plus + g.p_minus, 1.0);
  EXPECT_DOUBLE_EQ(g.p_plus, 1.0 / 3);
  const auto o = equalProbabilities(ProxyClass::kOutside);
  EXPECT_EQ(o.p_minus, 0.0);
  EXPECT_DOUBLE_EQ(o.p0, 0.5);
  const auto i = equalProbabilities(ProxyClass::kInside);
  EXPECT_EQ(i.p_plus, 0.0);
  EXPECT_DOUBLE_EQ(i.p_minus, 0.5);
}

// Grid over the simplex (restricted to the branches the class allows), step 1/400.
double gridMinimumVariance(const ClassProbabilities& c, ProxyClass cls) {
  double best = INFINITY;
  constexpr int kSteps = 400;
  for (int a = 1; a <= kSteps; ++a)
    for (int b = 0; a + b <= kSteps; ++b) {
      SelectionProbabilities p{a / double(kSteps), b / double(kSteps),
                               (kSteps - a - b) / double(kSteps)};
      if (cls == ProxyClass::kOutside && p.p_minus > 0) continue;
      if (cls == ProxyClass::kInside && p.p_plus > 0) continue;
      best = std::min(best, selectionVariance(c, p));
    }
  return best;
}

TEST(Selection, OptimalProbabilitiesBeatEveryGridPoint) {
  const std::vector<std::pair<ClassProbabilities, ProxyClass>> cases = {
      {test::outsideMix(), ProxyClass::kOutside},
      {test::insideMix(), ProxyClass::kInside},
      {test::generalMix(), ProxyClass::kGeneral},
      {{0.05, 0.2, 0.3, 0.45}, ProxyClass::kGeneral},
      {{0.7, 0.0, 0.01, 0.29}, ProxyClass::kOutside}};
  for (const auto& [c, cls] : cases) {
    const SelectionProbabilities p = optimalProbabilities(c, cls);
    EXPECT_NEAR(p.p0 + p.p_plus + p.p_minus, 1.0, 1e-12);
    const double opt = selectionVariance(c, p);
    const double grid = gridMinimumVariance(c, cls);
    EXPECT_LE(opt, grid + 1e-12);
    EXPECT_GE(opt, grid - 1e-3);  // and the grid gets close: the optimum is not an outlier
  }
}

TEST(Selection, CostHeuristicScalesCorrectionBranches) {
  const SelectionProbabilities opt{0.5, 0.3, 0.2};
  const SelectionProbabilities p = costHeuristicProbabilities(opt, 0.0625);  // 0.0625^(1/4) = 1/2
  EXPECT_DOUBLE_EQ(p.p_plus, 0.15);
  EXPECT_DOUBLE_EQ(p.p_minus, 0.1);
  EXPECT_DOUBLE_EQ(p.p0, 0.75);
}

TEST(Selection, ZeroProbabilityForPossibleErrorGivesInfiniteVariance) {
  EXPECT_TRUE(std::isinf(selectionVariance(test::generalMix(), {0.5, 0.5, 0.0})));
  EXPECT_TRUE(std::isfinite(selectionVariance(test::outsideMix(), {0.5, 0.5, 0.0})));
}

}  // namespace
}  // namespace proxyvis
