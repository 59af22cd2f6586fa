#pragma once
// The render-compare report model and its text writers (JSON, CSV, Markdown). Every row is one
// (table, estimator, spp or time budget) cell averaged over K seeds. The JSON rows carry at least
// the keys `estimator`, `spp`, `seconds`, `mse`, `relmse`, `efficiency`, `rays` (the contract
// other tools read); more keys are added freely.
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

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
  nlohmann::json extra = nlohmann::json::object();  // more keys for the JSON row (e.g. timings)
};

struct Report {
  std::string title;
  nlohmann::json meta = nlohmann::json::object();  // scene, settings, reference, baseline...
  std::vector<ReportRow> rows;
  std::vector<std::string> notes;  // plain-text remarks (warnings, what is missing)
};

// Fills ReportRow::efficiency for every row of `table`: relative to the row of `baseline` with
// the same table and the closest spp (equal-spp) or the only baseline row (equal-time). Rows
// without a baseline get 0, written as "n/a" (tables), an empty field (CSV) and null (JSON).
void fillRelativeEfficiency(std::vector<ReportRow>& rows, std::string_view table,
                            std::string_view baseline = "exact");

nlohmann::json rowToJson(const ReportRow& row);
// {"title", "relmse_epsilon", "meta": {...}, "notes": [...], "rows": [...]}.
nlohmann::json reportToJson(const Report& report);

// One header line, then one line per row; numbers in full precision.
std::string reportToCsv(const std::vector<ReportRow>& rows);

// A GitHub Markdown table of the rows of `table` (all rows if `table` is empty).
std::string markdownTable(const std::vector<ReportRow>& rows, std::string_view table = {});

// Title, notes and one table per kind.
std::string reportToMarkdown(const Report& report);

}  // namespace proxyvis
