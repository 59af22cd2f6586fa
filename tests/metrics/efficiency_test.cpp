#include "metrics/efficiency.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace proxyvis {
namespace {

TEST(Efficiency, IsInverseOfMseTimesTime) {
  EXPECT_DOUBLE_EQ(efficiency(0.01, 2.0), 50.0);
  EXPECT_DOUBLE_EQ(efficiency(0.0, 2.0), 0.0);
  EXPECT_DOUBLE_EQ(efficiency(0.1, 0.0), 0.0);
}

TEST(Efficiency, RelativeToExact) {
  // Half the MSE in the same time is twice as efficient; the same MSE in twice the time is half.
  EXPECT_DOUBLE_EQ(relativeEfficiency(0.5e-3, 1.0, 1e-3, 1.0), 2.0);
  EXPECT_DOUBLE_EQ(relativeEfficiency(1e-3, 2.0, 1e-3, 1.0), 0.5);
  // The paper's equal-time numbers: exact 4.461e-7 vs outside proxies 5.36e-6 → 0.0832.
  EXPECT_NEAR(relativeEfficiency(5.36e-6, 1.0, 4.461e-7, 1.0), 4.461e-7 / 5.36e-6, 1e-12);
  EXPECT_DOUBLE_EQ(relativeEfficiency(1e-3, 1.0, 0.0, 1.0), 0.0);
}

TEST(Efficiency, StandardErrorOverSeeds) {
  // Values 1, 2, 3, 6: mean 3, sample variance (4+1+0+9)/3 = 14/3, s.e. = sqrt(14/3/4).
  std::vector<double> v = {1, 2, 3, 6};
  SeedSummary s = summarizeSeeds(v);
  EXPECT_EQ(s.count, 4);
  EXPECT_DOUBLE_EQ(s.mean, 3.0);
  EXPECT_NEAR(s.standard_error, std::sqrt(14.0 / 12.0), 1e-12);
  std::vector<double> one = {5};
  EXPECT_EQ(summarizeSeeds(one).standard_error, 0.0);
}

}  // namespace
}  // namespace proxyvis
