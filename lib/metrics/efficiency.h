#pragma once
// Efficiency of an estimator = 1 / (MSE · time) (Veach's efficiency; docs/design.md), and
// statistics over K independent seeds.
#include <span>

namespace proxyvis {

// 1 / (mse · seconds); 0 when either is not positive (an undefined efficiency is reported as 0,
// never as infinity, so tables and plots stay finite).
double efficiency(double mse, double seconds);

// Efficiency of (mse, seconds) divided by that of the baseline (exact): > 1 means better than
// the baseline at equal time. 0 if either efficiency is undefined.
double relativeEfficiency(double mse, double seconds, double baseline_mse, double baseline_seconds);

// Mean and standard error of the mean of K values (one per seed); stderr is 0 for K < 2.
struct SeedSummary {
  double mean = 0;
  double standard_error = 0;
  int count = 0;
};
SeedSummary summarizeSeeds(std::span<const double> values);

}  // namespace proxyvis
