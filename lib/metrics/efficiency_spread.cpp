#include "metrics/efficiency_spread.h"

#include <fmt/format.h>

#include <algorithm>

#include "metrics/efficiency.h"

namespace proxyvis {

void fillEfficiencySpread(ReportRow& row, const ReportRow& baseline) {
  row.efficiency_per_seed.clear();
  const size_t n = row.mse_per_seed.size();
  if (n == 0 || row.seconds_per_seed.size() != n || baseline.mse_per_seed.size() != n ||
      baseline.seconds_per_seed.size() != n)
    return;
  std::vector<double> ratios;
  for (size_t i = 0; i < n; ++i) {
    const double e = relativeEfficiency(row.mse_per_seed[i], row.seconds_per_seed[i],
                                        baseline.mse_per_seed[i], baseline.seconds_per_seed[i]);
    if (!(e > 0)) return;  // one undefined run: no spread rather than a partial one
    ratios.push_back(e);
  }
  row.efficiency_per_seed = std::move(ratios);
}

EfficiencySpread efficiencySpread(const ReportRow& row) {
  EfficiencySpread s;
  const std::vector<double>& v = row.efficiency_per_seed;
  if (v.empty()) return s;
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  s.min = *lo;
  s.max = *hi;
  s.standard_error = summarizeSeeds(v).standard_error;
  s.runs = int(v.size());
  return s;
}

std::string efficiencyText(const ReportRow& row) {
  if (!(row.efficiency > 0)) return "n/a";
  const EfficiencySpread s = efficiencySpread(row);
  if (s.runs < 2) return fmt::format("{:.2f}×", row.efficiency);
  return fmt::format("{:.2f}× [{:.2f}–{:.2f}, s.e. {:.2f}]", row.efficiency, s.min, s.max,
                     s.standard_error);
}

void addEfficiencySpreadKeys(nlohmann::json& j, const ReportRow& row) {
  const EfficiencySpread s = efficiencySpread(row);
  const auto orNull = [&](double v) { return s.runs > 0 ? nlohmann::json(v) : nlohmann::json(); };
  j["efficiency_per_seed"] = row.efficiency_per_seed;
  j["efficiency_min"] = orNull(s.min);
  j["efficiency_max"] = orNull(s.max);
  j["efficiency_stderr"] = orNull(s.standard_error);
  j["seconds_per_seed"] = row.seconds_per_seed;
  j["cpu_seconds"] = row.cpu_seconds;
  j["repeats"] = row.repeats;
}

}  // namespace proxyvis
