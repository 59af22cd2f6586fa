// estimate/learned_summary.h: what roulette learned, written in unit results and report rows,
// read back exactly.
#include "estimate/learned_summary.h"

#include <gtest/gtest.h>

#include "tests/support/json_round_trip.h"

namespace proxyvis {
namespace {

LearnedSummary randomLearned(test::RandomValues& v) {
  LearnedSummary l;
  v.fill(l.regions, l.regions_roulette, l.p_proxy_blocked, l.error_given_blocked,
         l.error_given_visible, l.var_exact, l.predicted_efficiency, l.costs.proxy,
         l.costs.original, l.costs.per_sample);
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
