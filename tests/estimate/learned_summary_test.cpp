// estimate/learned_summary.h: what roulette learned, written in unit results and report rows,
// read back exactly.
#include "estimate/learned_summary.h"

#include <gtest/gtest.h>

#include "tests/support/json_round_trip.h"

namespace proxyvis {
namespace {

LearnedSummary randomLearned(test::RandomValues& v) {
  LearnedSummary l;
  l.regions = v.u32();
  l.regions_roulette = v.u32();
  l.p_proxy_blocked = v.number();
  l.error_given_blocked = v.number();
  l.error_given_visible = v.number();
  l.var_exact = v.number();
  l.predicted_efficiency = v.number();
  for (int i = 0; i < 2; ++i) {
    l.costs.proxy[i] = v.number();
    l.costs.original[i] = v.number();
  }
  l.costs.per_sample = v.number();
  return l;
}

PROXYVIS_JSON_PROPERTY_TESTS(LearnedSummaryJson, LearnedSummary, randomLearned, 7)

TEST(LearnedSummaryJson, KeysAreTheReportsContract) {
  LearnedSummary l;
  l.regions = 12;
  l.costs.proxy[1] = 7;
  l.costs.per_sample = 3;
  const nlohmann::json j = l;
  EXPECT_EQ(j.at("regions"), 12);
  EXPECT_EQ(j.at("cost_proxy"), nlohmann::json::array({1.0, 7.0}));
  EXPECT_EQ(j.at("cost_original"), nlohmann::json::array({1.0, 1.0}));
  EXPECT_EQ(j.at("cost_per_sample"), 3.0);
  EXPECT_EQ(j.size(), 10u);
}

}  // namespace
}  // namespace proxyvis
