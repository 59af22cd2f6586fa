#pragma once
// The render-compare report model and its text writers (JSON, CSV, Markdown). Every row is one
// (table, estimator, spp or time budget) cell averaged over K seeds. The JSON rows carry at least
// the keys `estimator`, `spp`, `seconds`, `mse`, `relmse`, `efficiency`, `rays` (the contract
// other tools read); more keys are added freely.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "estimate/learned_summary.h"
#include "metrics/ceiling_report.h"

namespace proxyvis {

inline constexpr std::string_view kEqualSppTable = "equal-spp";
inline constexpr std::string_view kEqualTimeTable = "equal-time";

// Rays traced per render, by class (mean over seeds).
struct ReportRays {
  double proxy = 0, original = 0, probe = 0;
  double total() const { return proxy + original + probe; }
};

struct ReportRow {
  std::string table;                     // kEqualSppTable or kEqualTimeTable
  std::string estimator;                 // "exact", "culling", ...
  double spp = 0;                        // light samples per pixel reached (mean over seeds)
  double seconds = 0;                    // wall time per render (mean over seeds)
  double mse = 0, mse_stderr = 0;        // mean and standard error over seeds
  double relmse = 0, relmse_stderr = 0;  // ε = kRelMseEpsilon
  double efficiency = 0;  // 1/(MSE·time) relative to the baseline (exact) of the same table
  ReportRays rays;
  double pixels = 1;  // for rays per pixel
  int seeds = 0;
  // Beyond the contract keys; each is written under its own name in the JSON row.
  int spp_max = 0;                // most samples per pixel one seed reached
  double shading_seconds = 0;     // mean over seeds
  double visibility_seconds = 0;  // mean over seeds
  double time_budget = 0;         // equal-time budget per render; 0 (not written) for equal-spp
  double budget_overshoot_seconds = 0;  // seconds - time_budget (written with time_budget)
  std::string proxy_class;              // the class the estimators relied on ("outside", ...)
  std::vector<double> mse_per_seed;     // one per run: seed k of repeat r at r * seeds + k
  // Run-to-run spread (metrics/efficiency_spread.h): the seconds of each run (same order), the
  // efficiency of each run against the baseline's run of the same seed and repeat.
  std::vector<double> seconds_per_seed, efficiency_per_seed;
  double cpu_seconds = 0;  // process CPU time per render (mean over runs)
  int repeats = 1;         // equal-time schedule repeats (--repeats): seeds x repeats runs
  std::optional<LearnedSummary> learned;  // roulette rows only: JSON "learned"
  // The scene's oracle ceiling (metrics/ceiling_report.h), the same on every row; 0 = unknown.
  // JSON: `ceiling` and `of_ceiling` = efficiency / ceiling (null when either is unknown).
  double ceiling = 0;
};

struct Report {
  std::string title;       // what the report is (e.g. "render-compare: equal time and samples")
  std::string scene_name;  // the scene's name: the page's heading (the title when empty)
  nlohmann::json meta = nlohmann::json::object();  // scene, settings, reference, baseline...
  std::vector<ReportRow> rows;
  std::vector<std::string> notes;        // plain-text remarks (warnings, what is missing)
  std::optional<ReportCeiling> ceiling;  // JSON meta.ceiling; its own Markdown and HTML section
};

// Fills ReportRow::efficiency for every row of `table`: relative to the row of `baseline` with
// the same table and the closest spp (equal-spp) or the only baseline row (equal-time). Rows
// without a baseline get 0, written as "n/a" (tables), an empty field (CSV) and null (JSON).
void fillRelativeEfficiency(std::vector<ReportRow>& rows, std::string_view table,
                            std::string_view baseline = "exact");

// The row's efficiency as a percentage of its ceiling ("87 %"), "n/a" when either is unknown.
std::string ofCeilingText(const ReportRow& row);

nlohmann::json rowToJson(const ReportRow& row);
// {"title", "scene_name", "relmse_epsilon", "meta": {...}, "notes": [...], "rows": [...]}.
nlohmann::json reportToJson(const Report& report);

// One header line, then one line per row; numbers in full precision.
std::string reportToCsv(const std::vector<ReportRow>& rows);

// A GitHub Markdown table of the rows of `table` (all rows if `table` is empty).
std::string markdownTable(const std::vector<ReportRow>& rows, std::string_view table = {});

// Heading (scene name, else title), notes and one table per kind.
std::string reportToMarkdown(const Report& report);

}  // namespace proxyvis
