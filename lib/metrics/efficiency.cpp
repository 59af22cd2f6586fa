#include "metrics/efficiency.h"

#include "util/stats.h"

namespace proxyvis {

double efficiency(double mse, double seconds) {
  if (!(mse > 0) || !(seconds > 0)) return 0;
  return 1.0 / (mse * seconds);
}

double relativeEfficiency(double mse, double seconds, double baseline_mse,
                          double baseline_seconds) {
  double e = efficiency(mse, seconds), b = efficiency(baseline_mse, baseline_seconds);
  return b > 0 ? e / b : 0;
}

SeedSummary summarizeSeeds(std::span<const double> values) {
  RunningStats stats;
  for (double v : values) stats.add(v);
  return {stats.mean(), stats.standardError(), int(stats.count())};
}

}  // namespace proxyvis
