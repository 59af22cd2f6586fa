#pragma once
// Run-to-run spread of a row's efficiency. A row's efficiency is the ratio of means (its mean MSE
// and time against the baseline's); beside it the report gives the same ratio per run, each run
// (seed, and repeat of the equal-time schedule) against the baseline's run with the same seed
// and repeat, which render-compare interleaves with it: the lowest, the highest and the
// standard error of their mean. A spread that covers 1 says the row is not told apart from the
// baseline by these runs.
#include <nlohmann/json.hpp>
#include <string>

#include "metrics/report.h"

namespace proxyvis {

// Fills row.efficiency_per_seed from row and baseline's per-run MSEs and seconds (same order);
// leaves it empty when the runs do not pair up (other counts) or a ratio is undefined.
void fillEfficiencySpread(ReportRow& row, const ReportRow& baseline);

struct EfficiencySpread {
  double min = 0, max = 0, standard_error = 0;
  int runs = 0;  // 0: no spread (no paired runs)
};
EfficiencySpread efficiencySpread(const ReportRow& row);

// The efficiency as the tables show it: "1.21×", with the spread over two or more runs
// "1.21× [1.10–1.30, s.e. 0.03]", or "n/a".
std::string efficiencyText(const ReportRow& row);

// The JSON row keys efficiency_per_seed, efficiency_min, efficiency_max and efficiency_stderr
// (null when there is no spread), plus seconds_per_seed, cpu_seconds and repeats.
void addEfficiencySpreadKeys(nlohmann::json& json_row, const ReportRow& row);

}  // namespace proxyvis
