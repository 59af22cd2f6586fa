// Roulette correction: measured variance and rays against the closed forms, and the optimal q
// against a grid search of Var x Cost (docs/design.md).
#include "estimate/roulette.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "estimate/sample_estimators.h"
#include "moments.h"
#include "test_mixes.h"
#include "util/stats.h"

namespace proxyvis {
namespace {

constexpr uint64_t kSeed = 777;
constexpr double kAlpha = 0.01;

struct Case {
  ProxyClass cls;
  RouletteQ q;
};

TEST(Roulette, MeasuredVarianceAndRaysMatchClosedForms) {
  const std::vector<Case> cases = {
      {ProxyClass::kOutside, {0.3, 0.0}},   {ProxyClass::kOutside, {1.0, 0.0}},
      {ProxyClass::kInside, {0.0, 0.4}},    {ProxyClass::kGeneral, {0.2, 0.5}},
      {ProxyClass::kGeneral, {0.05, 0.05}}, {ProxyClass::kGeneral, {1.0, 1.0}},
  };
  const double z = sidakZ(kAlpha, 3 * cases.size());
  constexpr size_t kN = 200000;
  for (size_t k = 0; k < cases.size(); ++k) {
    const ClassProbabilities c = test::mixFor(cases[k].cls);
    const SyntheticTracer tracer({c}, test::tracerSeed(kSeed, k));
    std::vector<double> x(kN);
    RayCounts counts;
    for (size_t i = 0; i < kN; ++i) {
      Rng rng(kSeed, hashKeys(k, i));
      x[i] = rouletteSample(tracer, SyntheticTracer::segment(0, i), cases[k].q, rng.uniformDouble(),
                            counts)
                 .estimate;
    }
    const test::Moments m = test::moments(x);
    const RouletteModel model = RouletteModel::fromPoint(c, ClassCosts{});
    const double var = rouletteVariance(model, cases[k].q);
    SCOPED_TRACE(testing::Message() << "case " << k << " q=(" << cases[k].q.q0 << ","
                                    << cases[k].q.q1 << ") seed " << kSeed);
    EXPECT_LE(std::abs(m.mean - c.vAvg()), z * std::sqrt(var / double(kN)));
    EXPECT_LE(std::abs(m.variance - var), z * m.variance_se)
        << "measured " << m.variance << " formula " << var;
    // With unit costs, Cost = 1 + expected original rays.
    const double orig = rouletteCost(model, cases[k].q) - 1.0;
    EXPECT_EQ(counts.proxy, kN);
    EXPECT_LE(std::abs(double(counts.original) / kN - orig),
              z * std::sqrt(orig * (1 - orig) / double(kN)) + 1e-12);
  }
}

// Models spanning the measured ranges of docs/design.md, measured costs and beyond, with per-class
// costs.
std::vector<std::pair<RouletteModel, ProxyClass>> randomModels() {
  std::vector<std::pair<RouletteModel, ProxyClass>> out;
  Rng rng(kSeed, 1);
  for (int k = 0; k < 60; ++k) {
    const ProxyClass cls = k % 3 == 0   ? ProxyClass::kOutside
                           : k % 3 == 1 ? ProxyClass::kInside
                                        : ProxyClass::kGeneral;
    ClassProbabilities c{rng.uniformDouble(), rng.uniformDouble() * 0.2, rng.uniformDouble() * 0.2,
                         rng.uniformDouble()};
    if (cls == ProxyClass::kOutside) c.hm = 0;
    if (cls == ProxyClass::kInside) c.mh = 0;
    const double s = c.hh + c.hm + c.mh + c.mm;
    c = {c.hh / s, c.hm / s, c.mh / s, c.mm / s};
    ClassCosts costs;
    for (int i = 0; i < 2; ++i) {
      costs.proxy[i] = 0.2 + rng.uniformDouble();
      costs.original[i] = costs.proxy[i] * (1.0 + 9.0 * rng.uniformDouble());
    }
    if (k % 2 == 0) costs.per_sample = 3 * rng.uniformDouble();
    RouletteModel m = RouletteModel::fromPoint(c, costs);
    // Per-pixel variance smaller than the pooled one, as in a region of several points.
    m.var_exact *= 0.2 + 0.8 * rng.uniformDouble();
    out.push_back({m, cls});
  }
  return out;
}

double product(const RouletteModel& m, const RouletteQ& q) {
  return rouletteVariance(m, q) * rouletteCost(m, q);
}

TEST(Roulette, OptimalQBeatsEveryGridPoint) {
  constexpr double kQMin = 0.05;
  constexpr int kSteps = 380;  // grid step 0.0025 over [q_min, 1]
  int clamped = 0, interior = 0;
  for (const auto& [m, cls] : randomModels()) {
    const RouletteQ q = optimalRouletteQ(m, cls, kQMin);
    if (cls == ProxyClass::kOutside) {
      EXPECT_EQ(q.q1, 0.0);
    }
    if (cls == ProxyClass::kInside) {
      EXPECT_EQ(q.q0, 0.0);
    }
    const double f = product(m, q);
    double best = INFINITY;
    for (int a = 0; a <= kSteps; ++a)
      for (int b = 0; b <= kSteps; ++b) {
        RouletteQ g{kQMin + (1 - kQMin) * a / kSteps, kQMin + (1 - kQMin) * b / kSteps};
        if (cls == ProxyClass::kOutside) g.q1 = 0;
        if (cls == ProxyClass::kInside) g.q0 = 0;
        best = std::min(best, product(m, g));
      }
    EXPECT_LE(f, best * (1 + 1e-12)) << "q=(" << q.q0 << "," << q.q1 << ")";
    EXPECT_GE(f, best * (1 - 1e-3));
    const double qi = cls == ProxyClass::kInside ? q.q1 : q.q0;
    (qi == 1.0 || qi == kQMin) ? ++clamped : ++interior;
  }
  // The models exercise both the clamped and the interior optimum.
  EXPECT_GT(clamped, 5);
  EXPECT_GT(interior, 5);
}

TEST(Roulette, InteriorOptimumIsTheClosedForm) {
  // General proxy with small errors: q_i = sqrt(P(err|V'=i) cbar_p / (c_o|i (V(1-V) - errors))).
  const ClassProbabilities c{0.40, 0.01, 0.02, 0.57};
  ClassCosts costs;
  costs.proxy[0] = 1.0;
  costs.proxy[1] = 0.5;
  costs.original[0] = 8.0;
  costs.original[1] = 3.0;
  const RouletteModel m = RouletteModel::fromPoint(c, costs);
  const RouletteQ q = optimalRouletteQ(m, ProxyClass::kGeneral, 0.01);
  const double cbar_p = c.proxyBlocked() * 1.0 + c.proxyVisible() * 0.5;
  const double b = m.var_exact - c.mh - c.hm;
  EXPECT_NEAR(q.q0, std::sqrt(c.errorGivenProxyBlocked() * cbar_p / (8.0 * b)), 1e-9);
  EXPECT_NEAR(q.q1, std::sqrt(c.errorGivenProxyVisible() * cbar_p / (3.0 * b)), 1e-9);
}

TEST(Roulette, PerSampleCostEntersBothCosts) {
  const ClassProbabilities c{0.30, 0.0, 0.05, 0.65};
  ClassCosts costs;
  costs.proxy[0] = costs.proxy[1] = 10;
  costs.original[0] = costs.original[1] = 100;
  const RouletteModel m = RouletteModel::fromPoint(c, costs);
  costs.per_sample = 1000;
  const RouletteModel ms = RouletteModel::fromPoint(c, costs);
  const RouletteQ q{0.3, 0.0};
  EXPECT_DOUBLE_EQ(rouletteCost(ms, q), rouletteCost(m, q) + 1000);
  EXPECT_DOUBLE_EQ(exactCost(ms), exactCost(m) + 1000);
  // Costly shading makes variance dearer: the optimal q grows towards 1.
  EXPECT_GT(optimalRouletteQ(ms, ProxyClass::kOutside, 0.05).q0,
            optimalRouletteQ(m, ProxyClass::kOutside, 0.05).q0);
}

TEST(Roulette, ErrorsAboveExactVarianceGiveCulling) {
  // docs/design.md, measured costs foliage: P(MH') = 0.2 > V(1-V) = 0.0475 -> q0 = 1 (plain
  // culling).
  const ClassProbabilities c{0.05, 0.0, 0.20, 0.75};
  const RouletteModel m = RouletteModel::fromPoint(c, ClassCosts{});
  const RouletteQ q = optimalRouletteQ(m, ProxyClass::kOutside, 0.05);
  EXPECT_EQ(q.q0, 1.0);
  EXPECT_EQ(q.q1, 0.0);
}

TEST(Roulette, PossibleErrorClassNeverGetsZero) {
  const ClassProbabilities c{0.5, 0.0, 0.0, 0.5};  // no error observed, general proxy
  const RouletteQ q =
      optimalRouletteQ(RouletteModel::fromPoint(c, ClassCosts{}), ProxyClass::kGeneral, 0.05);
  EXPECT_EQ(q.q0, 0.05);
  EXPECT_EQ(q.q1, 0.05);
}

// The one-choice optimum both roulettes use (optimalRouletteQ here, forwarding in lib/distributed):
// the grid's best q of (v0 + a/q)(c0 + b q), and the clamps.
TEST(EfficiencyOptimalQ, MatchesAGridSearchAndClamps) {
  struct Case {
    double v0, a, c0, b;
  };
  for (const Case& c : {Case{0.2, 0.01, 1.0, 5.0}, Case{0.05, 0.02, 3.0, 1.0},
                        Case{0.3, 0.001, 0.5, 20.0}, Case{0.01, 0.05, 1.0, 0.5}}) {
    const double q = efficiencyOptimalQ(c.v0, c.a, c.c0, c.b, 1e-3);
    auto product = [&](double x) { return (c.v0 + c.a / x) * (c.c0 + c.b * x); };
    double best = 1, best_product = product(1);
    for (int i = 1; i <= 100000; ++i) {
      const double x = 1e-3 + (1 - 1e-3) * i / 100000.0;
      if (product(x) < best_product) best = x, best_product = product(x);
    }
    EXPECT_NEAR(q, best, 1e-4) << c.v0 << " " << c.a << " " << c.c0 << " " << c.b;
    EXPECT_EQ(q, std::clamp(std::sqrt(c.a * c.c0 / (c.v0 * c.b)), 1e-3, 1.0));
  }
  EXPECT_EQ(efficiencyOptimalQ(0.2, 0, 1, 1, 0.05), 0.05);  // nothing to correct
  EXPECT_EQ(efficiencyOptimalQ(0, 0.1, 1, 1, 0.05), 1.0);   // the errors outweigh V(1-V)
  EXPECT_EQ(efficiencyOptimalQ(-0.1, 0.1, 1, 1, 0.05), 1.0);
  EXPECT_EQ(efficiencyOptimalQ(0.2, 0.1, 1, 0, 0.05), 1.0);      // a free correction
  EXPECT_EQ(efficiencyOptimalQ(0.2, 1e-9, 1, 1e6, 0.05), 0.05);  // clamped to the floor
}

}  // namespace
}  // namespace proxyvis
