// Names, parsing and bad setups of the runtime estimators.
#include <gtest/gtest.h>

#include <string>

#include "estimate/visibility_estimator.h"
#include "util/error.h"

namespace proxyvis {
namespace {

TEST(EstimatorFactory, NamesRoundTrip) {
  const auto kinds = allEstimators();
  ASSERT_EQ(kinds.size(), 6u);
  for (EstimatorKind k : kinds) EXPECT_EQ(parseEstimatorName(estimatorName(k)), k);
}

TEST(EstimatorFactory, UnknownNameListsTheValidOnes) {
  try {
    parseEstimatorName("rouette");
    FAIL() << "no error";
  } catch (const Error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("rouette"), std::string::npos) << msg;
    EXPECT_NE(msg.find("paper-optimal"), std::string::npos) << msg;
  }
}

TEST(EstimatorFactory, BadSetupsAreErrors) {
  EstimatorSetup s;
  s.kind = EstimatorKind::kRoulette;
  s.q_min = 0;
  EXPECT_THROW(makeEstimator(s), Error);
  s.q_min = 0.05;
  s.num_regions = 0;
  EXPECT_THROW(makeEstimator(s), Error);
  s.num_regions = 1;
  s.probes_per_point = -1;
  EXPECT_THROW(makeEstimator(s), Error);
}

TEST(EstimatorFactory, OnlyProbeEstimatorsAskForProbes) {
  for (EstimatorKind k : allEstimators()) {
    EstimatorSetup s;
    s.kind = k;
    s.probes_per_point = 12;
    const bool probes = k == EstimatorKind::kPaperOptimal || k == EstimatorKind::kPaperCost;
    EXPECT_EQ(makeEstimator(s)->probesPerPoint(), probes ? 12 : 0) << estimatorName(k);
  }
}

}  // namespace
}  // namespace proxyvis
