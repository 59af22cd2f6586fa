#include "metrics/report.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "metrics/efficiency.h"
#include "metrics/efficiency_spread.h"
#include "metrics/image_error.h"

namespace proxyvis {

namespace {

const ReportRow* findBaseline(const std::vector<ReportRow>& rows, std::string_view table,
                              std::string_view baseline, double spp) {
  const ReportRow* best = nullptr;
  double best_distance = std::numeric_limits<double>::infinity();
  for (const ReportRow& r : rows) {
    if (r.table != table || r.estimator != baseline) continue;
    double distance = table == kEqualTimeTable ? 0 : std::abs(r.spp - spp);
    if (distance < best_distance) best = &r, best_distance = distance;
  }
  return best;
}

std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string formatValueWithError(double value, double error) {
  if (error > 0) return fmt::format("{:.3e} ± {:.1e}", value, error);
  return fmt::format("{:.3e}", value);
}

std::string tableTitle(std::string_view table) {
  if (table == kEqualSppTable) return "Equal samples per pixel";
  if (table == kEqualTimeTable) return "Equal time";
  return std::string(table);
}

}  // namespace

std::string ofCeilingText(const ReportRow& r) {
  return r.ceiling > 0 && r.efficiency > 0 ? fmt::format("{:.0f} %", 100 * r.efficiency / r.ceiling)
                                           : "n/a";
}

void fillRelativeEfficiency(std::vector<ReportRow>& rows, std::string_view table,
                            std::string_view baseline) {
  std::vector<ReportRow> copy = rows;  // baselines are read from the unmodified rows
  for (ReportRow& r : rows) {
    if (r.table != table) continue;
    const ReportRow* b = findBaseline(copy, table, baseline, r.spp);
    r.efficiency = b ? relativeEfficiency(r.mse, r.seconds, b->mse, b->seconds) : 0;
    if (b) fillEfficiencySpread(r, *b);
  }
}

nlohmann::json rowToJson(const ReportRow& r) {
  double px = r.pixels > 0 ? r.pixels : 1;
  nlohmann::json j = {
      {"table", r.table},
      {"estimator", r.estimator},
      {"spp", r.spp},
      {"seconds", r.seconds},
      {"mse", r.mse},
      {"mse_stderr", r.mse_stderr},
      {"relmse", r.relmse},
      {"relmse_stderr", r.relmse_stderr},
      // 0 = undefined (no baseline row, or a zero MSE or time): null, never a number.
      {"efficiency", r.efficiency > 0 ? nlohmann::json(r.efficiency) : nlohmann::json()},
      {"rays", {{"proxy", r.rays.proxy}, {"original", r.rays.original}, {"probe", r.rays.probe}}},
      {"rays_per_pixel",
       {{"proxy", r.rays.proxy / px},
        {"original", r.rays.original / px},
        {"probe", r.rays.probe / px}}},
      {"seeds", r.seeds},
      {"spp_max", r.spp_max},
      {"shading_seconds", r.shading_seconds},
      {"visibility_seconds", r.visibility_seconds},
      {"proxy_class", r.proxy_class},
      {"mse_per_seed", r.mse_per_seed}};
  if (r.time_budget > 0) {
    j["time_budget"] = r.time_budget;
    j["budget_overshoot_seconds"] = r.budget_overshoot_seconds;
  }
  addEfficiencySpreadKeys(j, r);
  if (r.learned) j["learned"] = *r.learned;
  j["ceiling"] = r.ceiling > 0 ? nlohmann::json(r.ceiling) : nlohmann::json();
  j["of_ceiling"] = r.ceiling > 0 && r.efficiency > 0 ? nlohmann::json(r.efficiency / r.ceiling)
                                                      : nlohmann::json();
  return j;
}

nlohmann::json reportToJson(const Report& report) {
  nlohmann::json rows = nlohmann::json::array();
  for (const ReportRow& r : report.rows) rows.push_back(rowToJson(r));
  nlohmann::json meta = report.meta;
  if (report.ceiling) meta["ceiling"] = *report.ceiling;
  return {{"title", report.title},
          {"scene_name", report.scene_name},
          {"relmse_epsilon", kRelMseEpsilon},
          {"efficiency_definition", "1/(MSE*seconds) relative to exact"},
          {"meta", meta},
          {"notes", report.notes},
          {"rows", rows}};
}

std::string reportToCsv(const std::vector<ReportRow>& rows) {
  std::string out =
      "table,estimator,spp,seconds,mse,mse_stderr,relmse,relmse_stderr,efficiency,"
      "rays_proxy,rays_original,rays_probe,seeds\n";
  for (const ReportRow& r : rows)
    out += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{}\n", csvField(r.table),
                       csvField(r.estimator), r.spp, r.seconds, r.mse, r.mse_stderr, r.relmse,
                       r.relmse_stderr, r.efficiency > 0 ? fmt::format("{}", r.efficiency) : "",
                       r.rays.proxy, r.rays.original, r.rays.probe, r.seeds);
  return out;
}

std::string markdownTable(const std::vector<ReportRow>& rows, std::string_view table) {
  std::string out =
      "| estimator | spp | time (s) | MSE ± s.e. | relMSE ± s.e. | efficiency vs exact | "
      "of ceiling | rays/px proxy | rays/px original | rays/px probe |\n"
      "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const ReportRow& r : rows) {
    if (!table.empty() && r.table != table) continue;
    double px = r.pixels > 0 ? r.pixels : 1;
    out +=
        fmt::format("| {} | {:.1f} | {:.3f} | {} | {} | {} | {} | {:.1f} | {:.1f} | {:.1f} |\n",
                    r.estimator, r.spp, r.seconds, formatValueWithError(r.mse, r.mse_stderr),
                    formatValueWithError(r.relmse, r.relmse_stderr), efficiencyText(r),
                    ofCeilingText(r), r.rays.proxy / px, r.rays.original / px, r.rays.probe / px);
  }
  return out;
}

std::string reportToMarkdown(const Report& report) {
  std::string out = "# " + (report.scene_name.empty() ? report.title : report.scene_name) + "\n\n";
  if (!report.scene_name.empty() && !report.title.empty()) out += report.title + "\n\n";
  for (const std::string& note : report.notes) out += "- " + note + "\n";
  if (!report.notes.empty()) out += "\n";
  out += fmt::format(
      "MSE over pixels and RGB in linear radiance; relMSE = mean((I−I_ref)²/(I_ref²+ε)), "
      "ε = {:g}; efficiency = 1/(MSE·time) relative to `exact` of the same table, "
      "[lowest–highest, s.e.] of the same ratio run by run against exact's run with the same seed; "
      "± is the standard error over seeds.\n",
      kRelMseEpsilon);
  for (std::string_view table : {kEqualSppTable, kEqualTimeTable}) {
    bool any = false;
    for (const ReportRow& r : report.rows) any = any || r.table == table;
    if (!any) continue;
    out += "\n## " + tableTitle(table) + "\n\n" + markdownTable(report.rows, table);
  }
  if (report.ceiling) out += ceilingMarkdown(*report.ceiling);
  return out;
}

}  // namespace proxyvis
