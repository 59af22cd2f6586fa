// The ceiling arithmetic of ceiling_table.h on hand-made statistics whose answers follow from the
// formulas of docs/estimators.md by hand (values below are computed here, not by the code).
#include "ceiling_table.h"

#include <gtest/gtest.h>

namespace proxyvis::ecosys {
namespace {

// One pixel, one light; `n` samples of each (V', V) pair with proxy / original costs in ticks.
void addSamples(CeilingStats& s, int n, bool vp, bool v, uint64_t cp, uint64_t co) {
  for (int i = 0; i < n; ++i) s.add(0, 0, vp, v, cp, co);
}

// The rows of one light, "sun", for an outside proxy with q_min = 0.05 and one tick per ns;
// `c_s_ns` is the per-sample cost outside visibility. With `train`, the held-out oracle.
std::vector<CeilingRow> sunRows(const CeilingStats& s, double c_s_ns = 0.0,
                                const CeilingStats* train = nullptr) {
  return ceilingRows(s, {"sun"}, {1.0}, ProxyClass::kOutside, 0.05, c_s_ns, 1.0, train);
}

// Statistics of one pixel holding `n` samples of the single (V', V) pair, proxy rays costing 1
// tick and original rays 10.
CeilingStats onePairStats(int n, bool vp, bool v) {
  CeilingStats s(1, 1, 1, 16, 1000);
  addSamples(s, n, vp, v, 1, 10);
  s.finish();
  return s;
}

TEST(CeilingTable, ErrorFreeCheapOutsideProxyGivesTheHandComputedCeiling) {
  // 50 HH' and 50 MM' at one pixel: V_p(1-V_p) = 100/99 * 1/4, P(MH') = 0. Proxy rays cost 1,
  // original rays 10. Exact: 0.5*10 + 0.5*10 = 10. Roulette with no error seen: q0 = q_min = 0.05,
  // q1 = 0 (outside), cost 0.5*(1 + 0.05*10) + 0.5*1 = 1.25, same variance: ceiling 10/1.25 = 8.
  // Culling (q0 = 1): cost 0.5*11 + 0.5*1 = 6, ratio 10/6.
  CeilingStats s(1, 1, 1, 16, 1000);
  addSamples(s, 50, false, false, 1, 10);
  addSamples(s, 50, true, true, 1, 10);
  s.finish();
  const auto rows = sunRows(s);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_NEAR(rows[0].var_exact, 100.0 / 99 * 0.25, 1e-12);
  EXPECT_NEAR(rows[0].ceiling_shadow, 8.0, 1e-9);
  EXPECT_NEAR(rows[0].culling_shadow, 10.0 / 6.0, 1e-9);
  // c_s = 10 ns added to every sample: (10 + 10) / (10 + 1.25) at the same q (the optimum moves
  // only where there are errors to correct).
  const auto with_cs = sunRows(s, 10.0);
  EXPECT_NEAR(with_cs[0].ceiling_render, 20.0 / 11.25, 1e-9);
  EXPECT_EQ(rows[0].regions_roulette, 1);
}

TEST(CeilingTable, ProxyWrongWhereExactHasNoVarianceFallsBackToExact) {
  // Every segment visible (V_p = 1: exact has no variance) but the proxy blocks all of them: any
  // q0 < 1 adds variance to a noise-free estimate, so the oracle keeps exact: ceiling 1.
  const CeilingStats s = onePairStats(100, false, true);
  const auto rows = sunRows(s);
  EXPECT_DOUBLE_EQ(rows[0].p_mh, 1.0);
  EXPECT_DOUBLE_EQ(rows[0].ceiling_shadow, 1.0);
  EXPECT_EQ(rows[0].regions_roulette, 0);
  // Culling traces both rays on every segment: 10 / (1 + 10).
  EXPECT_NEAR(rows[0].culling_shadow, 10.0 / 11.0, 1e-9);
}

TEST(CeilingTable, NoVarianceAndNoErrorsLetsTheCheaperProxyWin) {
  // Every pixel fully lit and the proxy never wrong (MM' only): both estimators are exact, so the
  // oracle takes the cheaper one: proxy 1 against original 10, ceiling 10.
  const CeilingStats s = onePairStats(100, true, true);
  const auto rows = sunRows(s);
  EXPECT_DOUBLE_EQ(rows[0].var_exact, 0.0);
  EXPECT_NEAR(rows[0].ceiling_shadow, 10.0, 1e-9);
  EXPECT_EQ(rows[0].regions_roulette, 1);
}

TEST(CeilingTable, HeldOutOracleIsScoredOnSamplesItDidNotDecideFrom) {
  // Decided on 100 HH' (no error seen: roulette, q0 = q_min = 0.05); scored on 99 HH' + 1 MH':
  // V_p(1-V_p) = 100/99 * 0.01 * 0.99 = 0.01, roulette adds 0.01 * (1/0.05 - 1) = 0.19, its cost
  // 1 + 0.05 * 10 = 1.5 against exact's 10: 0.01 * 10 / (0.2 * 1.5) = 1/3. Deciding on the scored
  // samples themselves keeps exact (ceiling 1).
  CeilingStats train(1, 1, 1, 16, 1000), scored(1, 1, 1, 16, 1000);
  addSamples(train, 100, false, false, 1, 10);
  addSamples(scored, 99, false, false, 1, 10);
  addSamples(scored, 1, false, true, 1, 10);
  train.finish();
  scored.finish();
  const auto held = sunRows(scored, 0.0, &train);
  EXPECT_NEAR(held[0].ceiling_shadow, 1.0 / 3.0, 1e-9);
  const auto self = sunRows(scored);
  EXPECT_DOUBLE_EQ(self[0].ceiling_shadow, 1.0);
}

TEST(CeilingTable, PreemptedRaysCountForProbabilitiesButNotForCosts) {
  CeilingStats s(1, 1, 1, 16, 100);
  addSamples(s, 20, true, true, 2, 4);
  addSamples(s, 1, true, true, 5000, 4);  // preempted: over the 100-tick cap
  s.finish();
  EXPECT_EQ(s.preempted(), 1u);
  const auto rows = sunRows(s);
  EXPECT_EQ(rows[0].segments, 21u);
  EXPECT_DOUBLE_EQ(rows[0].c_p[1], 2.0);
  EXPECT_DOUBLE_EQ(rows[0].c_o[1], 4.0);
}

TEST(CeilingTable, MixWeightsLightsAndAddsAMixRow) {
  // Light 0: the error-free case of the first test (ceiling 8, exact cost 10, roulette 1.25);
  // light 1: exact only (ceiling 1, cost 10, 100 MH' with V = 1). Mix 3:1 by weight:
  // var_exact = 0.75 v0 + 0.25 * 0, cost_exact = 10, oracle cost 0.75*1.25 + 0.25*10 = 3.4375,
  // same variance: ceiling 10 / 3.4375.
  CeilingStats s(2, 1, 1, 16, 1000);
  addSamples(s, 50, false, false, 1, 10);
  addSamples(s, 50, true, true, 1, 10);
  for (int i = 0; i < 100; ++i) s.add(1, 0, false, true, 1, 10);
  s.finish();
  const auto rows =
      ceilingRows(s, {"sun", "sky"}, {3.0, 1.0}, ProxyClass::kOutside, 0.05, 0.0, 1.0);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[2].light, "mix");
  EXPECT_DOUBLE_EQ(rows[2].weight, 1.0);
  EXPECT_NEAR(rows[0].weight, 0.75, 1e-12);
  EXPECT_NEAR(rows[2].ceiling_shadow, 10.0 / 3.4375, 1e-9);
  EXPECT_NEAR(rows[2].p_mh, 0.25, 1e-12);
}

}  // namespace
}  // namespace proxyvis::ecosys
