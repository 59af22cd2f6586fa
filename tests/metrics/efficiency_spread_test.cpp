// The efficiency's run-to-run spread: each run against the baseline's run of the same seed and
// repeat, its lowest, highest and standard error, in the tables and the JSON.
#include "metrics/efficiency_spread.h"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "metrics/html_report.h"
#include "metrics/report.h"

namespace proxyvis {
namespace {

ReportRow timedRow(std::string estimator, std::vector<double> mse, std::vector<double> seconds) {
  ReportRow r;
  r.table = std::string(kEqualTimeTable);
  r.estimator = std::move(estimator);
  double m = 0, t = 0;
  for (size_t i = 0; i < mse.size(); ++i) m += mse[i] / double(mse.size());
  for (size_t i = 0; i < seconds.size(); ++i) t += seconds[i] / double(seconds.size());
  r.mse = m;
  r.seconds = t;
  r.mse_per_seed = std::move(mse);
  r.seconds_per_seed = std::move(seconds);
  r.seeds = 2;
  r.repeats = 2;
  r.pixels = 4;
  return r;
}

// Exact's four runs, and roulette's: per run, efficiency = (mse_e * t_e) / (mse_r * t_r):
//   run 0: (4 * 1) / (2 * 1) = 2;  run 1: (4 * 1) / (4 * 1) = 1;
//   run 2: (2 * 2) / (1 * 1) = 4;  run 3: (3 * 1) / (1 * 1.5) = 2.
// Mean 2.25, sample standard deviation sqrt(((0.25)^2 + 1.25^2 + 1.75^2 + 0.25^2) / 3)
// = sqrt(4.75 / 3), standard error that / 2.
std::vector<ReportRow> sampleRows() {
  return {timedRow("exact", {4, 4, 2, 3}, {1, 1, 2, 1}),
          timedRow("roulette", {2, 4, 1, 1}, {1, 1, 1, 1.5})};
}

TEST(EfficiencySpread, EachRunAgainstTheBaselinesRunOfTheSameSeed) {
  std::vector<ReportRow> rows = sampleRows();
  fillRelativeEfficiency(rows, kEqualTimeTable);
  EXPECT_EQ(rows[1].efficiency_per_seed, (std::vector<double>{2, 1, 4, 2}));
  const EfficiencySpread s = efficiencySpread(rows[1]);
  EXPECT_EQ(s.runs, 4);
  EXPECT_DOUBLE_EQ(s.min, 1);
  EXPECT_DOUBLE_EQ(s.max, 4);
  EXPECT_NEAR(s.standard_error, std::sqrt(4.75 / 3) / 2, 1e-12);
  // The baseline against itself: 1 in every run.
  const EfficiencySpread e = efficiencySpread(rows[0]);
  EXPECT_DOUBLE_EQ(e.min, 1);
  EXPECT_DOUBLE_EQ(e.max, 1);
  EXPECT_DOUBLE_EQ(e.standard_error, 0);
  // The headline stays the ratio of means: (3.25 * 1.25) / (2 * 1.125).
  EXPECT_NEAR(rows[1].efficiency, 3.25 * 1.25 / (2 * 1.125), 1e-12);
}

TEST(EfficiencySpread, RunsThatDoNotPairUpGiveNoSpread) {
  std::vector<ReportRow> rows = sampleRows();
  rows[0].mse_per_seed.pop_back();  // exact has 3 runs, roulette 4
  rows[0].seconds_per_seed.pop_back();
  fillRelativeEfficiency(rows, kEqualTimeTable);
  EXPECT_TRUE(rows[1].efficiency_per_seed.empty());
  EXPECT_EQ(efficiencySpread(rows[1]).runs, 0);
  EXPECT_GT(rows[1].efficiency, 0);  // the ratio of means is still there
  rows = sampleRows();
  rows[1].mse_per_seed[2] = 0;  // an undefined run: no partial spread
  fillRelativeEfficiency(rows, kEqualTimeTable);
  EXPECT_TRUE(rows[1].efficiency_per_seed.empty());
}

TEST(EfficiencySpread, TablesAndJsonShowIt) {
  std::vector<ReportRow> rows = sampleRows();
  fillRelativeEfficiency(rows, kEqualTimeTable);
  EXPECT_EQ(efficiencyText(rows[1]), "1.81× [1.00–4.00, s.e. 0.63]");
  ReportRow single = rows[1];
  single.efficiency_per_seed.resize(1);  // one run: no spread to give
  EXPECT_EQ(efficiencyText(single), "1.81×");
  single.efficiency = 0;
  EXPECT_EQ(efficiencyText(single), "n/a");

  EXPECT_NE(markdownTable(rows).find("| 1.81× [1.00–4.00, s.e. 0.63] |"), std::string::npos);
  Report report;
  report.rows = rows;
  EXPECT_NE(reportToHtml(report, {}).find("1.81× [1.00–4.00, s.e. 0.63]"), std::string::npos);

  const nlohmann::json j = nlohmann::json::parse(reportToJson(report).dump());
  const nlohmann::json& r = j.at("rows").at(1);
  EXPECT_DOUBLE_EQ(r.at("efficiency_min").get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(r.at("efficiency_max").get<double>(), 4.0);
  EXPECT_NEAR(r.at("efficiency_stderr").get<double>(), std::sqrt(4.75 / 3) / 2, 1e-12);
  EXPECT_EQ(r.at("efficiency_per_seed").size(), 4u);
  EXPECT_EQ(r.at("seconds_per_seed").size(), 4u);
  EXPECT_EQ(r.at("repeats").get<int>(), 2);
  // Without paired runs the spread keys are null, never a made-up number.
  report.rows[1].efficiency_per_seed.clear();
  const nlohmann::json k = nlohmann::json::parse(reportToJson(report).dump());
  EXPECT_TRUE(k["rows"][1]["efficiency_min"].is_null());
  EXPECT_TRUE(k["rows"][1]["efficiency_stderr"].is_null());
}

}  // namespace
}  // namespace proxyvis
