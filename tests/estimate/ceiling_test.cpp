// The oracle ceiling (estimate/ceiling.h) against a case computed on paper, its >= 1 guarantee,
// and the explanation rules, each on a case built for it.
#include "estimate/ceiling.h"

#include <gtest/gtest.h>

#include <random>
#include <regex>

namespace proxyvis {
namespace {

// A region of n segments with per-sample quantities: P(V'=0) = p0, MSE-weighted exact variance
// var and MH' weight a (f = 1, so f^2-weighted errors equal error probabilities), and ray costs
// per class in ns.
CeilingRegionStats region(uint32_t light, double n, double p0, double var, double a, double cp0,
                          double cp1, double co0, double co1) {
  CeilingRegionStats r;
  r.light = light;
  r.segments = n;
  r.blocked = p0 * n;
  r.mh = a * n;
  r.f2_mh = a * n;
  r.visibility_var = var * n;
  r.var_fv = var * n;
  r.cost_proxy[0] = cp0 * p0 * n;
  r.cost_proxy[1] = cp1 * (1 - p0) * n;
  r.cost_original[0] = co0 * p0 * n;
  r.cost_original[1] = co1 * (1 - p0) * n;
  return r;
}

// Two regions of 1000 segments each, an outside proxy (q1 = 0), c_s = 10 ns, q_min = 0.05.
// Region A (light 0): P(V'=0) = 0.2, Var_exact = 0.2, P(MH') = 0.04, c_p = 10 | 10, c_o = 100 | 40.
//   exact:    cost 10 + 0.2*100 + 0.8*40 = 62, Var 0.2, product 12.4
//   roulette: c0 = c_s + sum P_i c_p|i = 20, b = 0.2*100 = 20, v0 = 0.2 - 0.04 = 0.16,
//             q0 = sqrt(a c0 / (v0 b)) = sqrt(0.04*20 / (0.16*20)) = 0.5,
//             Var = 0.2 + 0.04*(1/0.5 - 1) = 0.24, cost = 10 + 0.2*(10 + 0.5*100) + 0.8*10 = 30,
//             product 7.2 < 12.4: the oracle takes roulette (ceiling of light 0 = 12.4/7.2).
// Region B (light 1): P(V'=0) = 0.5, Var_exact = 0.1, P(MH') = 0.1, c_p = 10 | 40, c_o = 100 | 40.
//   v0 = 0.1 - 0.1 = 0, so q0 = 1 (culling): Var 0.1, cost 10 + 0.5*110 + 0.5*40 = 85
//   against exact's 10 + 0.5*100 + 0.5*40 = 80: the oracle keeps exact.
// Sums over 1000 samples each: exact V = 200 + 100 = 300, C = 62000 + 80000 = 142000;
// oracle V = 240 + 100 = 340, C = 30000 + 80000 = 110000.
// Ceiling = (300 * 142000) / (340 * 110000) = 42.6e6 / 37.4e6 = 1.139037...
// (At those totals the choices are stable: for A, 240*110000 + 30000*340 = 36.6e6 < exact's
// 200*110000 + 62000*340 = 43.08e6; for B, exact's 38.2e6 < roulette's 39.9e6.)
CeilingInput twoRegions() {
  CeilingInput in;
  in.regions = {region(0, 1000, 0.2, 0.2, 0.04, 10, 10, 100, 40),
                region(1, 1000, 0.5, 0.1, 0.1, 10, 40, 100, 40)};
  in.num_lights = 2;
  in.per_sample_ns = 10;
  in.proxy_class = ProxyClass::kOutside;
  in.q_min = 0.05;
  return in;
}

TEST(Ceiling, TwoRegionsAsComputedOnPaper) {
  const CeilingInput in = twoRegions();
  ClassCosts shading_only;  // every class has >= 16 segments: only c_s is taken from here
  shading_only.per_sample = 10;
  const RouletteModel a = ceilingModel(in.regions[0], shading_only);
  EXPECT_NEAR(optimalRouletteQ(a, ProxyClass::kOutside, 0.05).q0, 0.5, 1e-12);
  EXPECT_NEAR(exactCost(a), 62, 1e-9);
  EXPECT_NEAR(rouletteCost(a, {0.5, 0}), 30, 1e-9);

  const CeilingResult r = computeCeiling(in);
  EXPECT_NEAR(r.scene.var_exact, 300, 1e-9);
  EXPECT_NEAR(r.scene.cost_exact, 142000, 1e-6);
  EXPECT_NEAR(r.scene.var_oracle, 340, 1e-9);
  EXPECT_NEAR(r.scene.cost_oracle, 110000, 1e-6);
  EXPECT_NEAR(r.scene.ceiling, 42.6 / 37.4, 1e-12);
  EXPECT_EQ(r.scene.regions, 2);
  EXPECT_EQ(r.scene.regions_roulette, 1);
  ASSERT_EQ(r.lights.size(), 2u);
  EXPECT_NEAR(r.lights[0].ceiling, 12.4 / 7.2, 1e-12);
  EXPECT_EQ(r.lights[0].regions_roulette, 1);
  EXPECT_DOUBLE_EQ(r.lights[1].ceiling, 1.0);
  EXPECT_EQ(r.lights[1].regions_roulette, 0);
  // Scene-wide means: P(V'=0) = (200 + 500) / 2000, c_o|1 = 40 in both regions.
  EXPECT_NEAR(r.scene.p_blocked, 0.35, 1e-12);
  EXPECT_NEAR(r.scene.costs.original[1], 40, 1e-9);
  EXPECT_NEAR(r.scene.costs.per_sample, 10, 1e-12);
}

TEST(Ceiling, WithoutProxiesIsOne) {
  CeilingInput in = twoRegions();
  in.uses_proxies = false;
  const CeilingResult r = computeCeiling(in);
  EXPECT_DOUBLE_EQ(r.scene.ceiling, 1.0);
  EXPECT_EQ(r.scene.regions_roulette, 0);
  EXPECT_EQ(r.explanation.rfind("No proxies", 0), 0u) << r.explanation;
}

TEST(Ceiling, WithoutSegmentsIsOne) {
  CeilingInput in;
  in.regions = {CeilingRegionStats{}};
  in.regions[0].var_fv = 3;  // back-facing samples still have variance, but no rays
  const CeilingResult r = computeCeiling(in);
  EXPECT_DOUBLE_EQ(r.scene.ceiling, 1.0);
  EXPECT_EQ(r.explanation.rfind("No shadow rays", 0), 0u) << r.explanation;
}

// Choosing per region by its own Var x Cost can make the product of the sums worse than exact
// everywhere; the oracle never ends below all-exact, on any mix of regions.
TEST(Ceiling, NeverBelowOne) {
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0; trial < 200; ++trial) {
    CeilingInput in;
    in.proxy_class = trial % 3 == 0 ? ProxyClass::kGeneral : ProxyClass::kOutside;
    in.per_sample_ns = 50 * u(gen);
    for (int k = 0; k < 6; ++k) {
      const double var = 0.25 * u(gen), p0 = 0.05 + 0.9 * u(gen);
      CeilingRegionStats r = region(0, 20 + 1000 * u(gen), p0, var, var * 1.2 * u(gen),
                                    200 * u(gen), 200 * u(gen), 400 * u(gen), 400 * u(gen));
      r.f2_hm = in.proxy_class == ProxyClass::kGeneral ? 0.05 * r.segments * u(gen) : 0;
      in.regions.push_back(r);
    }
    EXPECT_GE(computeCeiling(in).scene.ceiling, 1.0) << "trial " << trial;
  }
}

int sentences(const std::string& text) {
  static const std::regex kEnd(R"(\.( |$))");
  return int(
      std::distance(std::sregex_iterator(text.begin(), text.end(), kEnd), std::sregex_iterator()));
}

// The explanation of `s` (with proxies or not) opens with `first` and has two sentences.
void expectExplanation(const CeilingSummary& s, bool has_proxies, const std::string& first) {
  const std::string text = explainCeiling(s, has_proxies);
  EXPECT_EQ(text.rfind(first, 0), 0u) << text;
  EXPECT_EQ(sentences(text), 2) << text;
}

// A scene summary where no rule fires: cheap proxy, rare errors, small shading share.
CeilingSummary paying() {
  CeilingSummary s;
  s.segments = 1000;
  s.p_mh = 0.01;
  s.visibility_var = 0.1;
  s.costs.proxy[0] = s.costs.proxy[1] = 10;
  s.costs.original[0] = s.costs.original[1] = 100;
  s.costs.per_sample = 20;
  s.cost_exact = 1000 * 120;
  s.regions = 8;
  s.regions_roulette = 5;
  s.ceiling = 1.8;
  return s;
}

TEST(CeilingExplanation, ProxyErrorsExceedVariance) {
  CeilingSummary s = paying();
  s.p_mh = 0.07;
  s.visibility_var = 0.04;
  expectExplanation(s, true,
                    "P(MH') = 0.070 exceeds the visibility variance V(1-V) = 0.040, so "
                    "correcting the proxy's errors costs more variance than it saves time.");
}

TEST(CeilingExplanation, ProxyNoCheaperWhereVisible) {
  CeilingSummary s = paying();
  s.costs.proxy[1] = 58;
  s.costs.original[1] = 56;
  expectExplanation(s, true,
                    "The proxy is no cheaper than the original where it says visible (c_p|1 = "
                    "58 ns vs c_o|1 = 56 ns).");
}

TEST(CeilingExplanation, ShadingCapsTheGain) {
  CeilingSummary s = paying();
  s.costs.per_sample = 70;
  s.cost_exact = 1000 * 100;  // exact costs 100 ns per sample, 70 of them shading
  expectExplanation(s, true,
                    "Shading costs 70 % of each sample, which caps any visibility gain at 1.4x.");
}

TEST(CeilingExplanation, TwoLimitsInOrder) {
  CeilingSummary s = paying();
  s.p_mh = 0.07;
  s.visibility_var = 0.04;
  s.costs.per_sample = 70;
  s.cost_exact = 1000 * 100;
  const std::string text = explainCeiling(s, true);
  EXPECT_NE(text.find("exceeds"), std::string::npos) << text;
  EXPECT_NE(text.find("Shading costs 70 %"), std::string::npos) << text;
  EXPECT_LT(text.find("exceeds"), text.find("Shading"));
  EXPECT_EQ(sentences(text), 2) << text;
}

TEST(CeilingExplanation, WhenTheProxyPays) {
  const std::string text = explainCeiling(paying(), true);
  EXPECT_EQ(text,
            "The proxy is cheaper where it says visible (c_p|1 = 10 ns vs c_o|1 = 100 ns) and "
            "its errors (P(MH') + P(HM') = 0.010) stay below the visibility variance V(1-V) = "
            "0.100. An oracle choosing per region uses roulette in 5 of 8 regions: ceiling "
            "1.800x.");
}

TEST(CeilingExplanation, NoProxies) {
  expectExplanation(paying(), false, "No proxies");
}

}  // namespace
}  // namespace proxyvis
