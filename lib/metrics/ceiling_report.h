#pragma once
// The oracle ceiling in a render-compare report: the attainable gain over exact that the run's
// own measurements allow (estimate/ceiling.h), per light and for the whole scene, with the
// sentence saying what limits it. Plain numbers, so that pv_metrics stays free of the estimators.
// JSON: report.meta.ceiling; every row also carries `ceiling` and `of_ceiling`
// (metrics/report.h).
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace proxyvis {

// One line of the per-light table (the last line, light "all", is the whole scene).
struct ReportCeilingLight {
  std::string light;  // "0", "1", ... or "all"
  double segments = 0;
  double p_blocked = 0, p_mh = 0, p_hm = 0;                  // P(V'=0), P(MH'), P(HM')
  double visibility_var = 0;                                 // mean V_p(1-V_p)
  double cost_proxy[2] = {0, 0}, cost_original[2] = {0, 0};  // ns per ray given V' = 0, 1
  double cost_shading = 0;                                   // c_s, ns per sample
  int regions = 0, regions_roulette = 0;
  double ceiling = 1;
};

struct ReportCeiling {
  double value = 1;         // the scene's ceiling (efficiency relative to exact)
  std::string explanation;  // two sentences: what limits the gain
  std::string model;        // the model's simplifications, stated
  int passes = 0;           // light samples per pixel traced by the measurement
  double seconds = 0;       // its wall time
  double run_share = 0;     // its time over the renders' time
  // The model's MSE of exact at 1 sample per pixel (mean over pixels and RGB of Var[f V]): an
  // exact row at N spp should be near it / N (plus the reference's own variance), a check that
  // the variances are in the MSE's units.
  double exact_mse_1spp = 0;
  std::vector<ReportCeilingLight> lights;
};

// report.json's meta.ceiling (an output only: nothing reads it back, so there is no from_json).
void to_json(nlohmann::json& j, const ReportCeilingLight& l);
void to_json(nlohmann::json& j, const ReportCeiling& c);
// A "## Ceiling" section: the explanation, the per-light table, how it was measured.
std::string ceilingMarkdown(const ReportCeiling& c);
// The same as an HTML section (<h2>, paragraphs, a table); every text escaped.
std::string ceilingHtml(const ReportCeiling& c);

}  // namespace proxyvis
