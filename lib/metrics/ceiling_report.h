#pragma once
// The oracle ceiling in a render-compare report: the attainable gain over exact that the run's
// own measurements allow, per light and for the whole scene, with the sentence saying what limits
// it (estimate/ceiling.h computes it; this is how a report shows it).
// JSON: report.meta.ceiling; every row also carries `ceiling` and `of_ceiling`
// (metrics/report.h).
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "estimate/ceiling.h"

namespace proxyvis {

struct ReportCeiling {
  // The scene's ceiling (efficiency relative to exact), each light's, and the two sentences
  // saying what limits the gain. The per-light table has one line per light ("0", "1", ...) and
  // the scene's last ("all").
  CeilingResult result;
  std::string model;     // the model's simplifications, stated
  int passes = 0;        // light samples per pixel traced by the measurement
  double seconds = 0;    // its wall time
  double run_share = 0;  // its time over the renders' time
  // The model's MSE of exact at 1 sample per pixel (mean over pixels and RGB of Var[f V]): an
  // exact row at N spp should be near it / N (plus the reference's own variance), a check that
  // the variances are in the MSE's units.
  double exact_mse_1spp = 0;

  double value() const { return result.scene.ceiling; }
};

// report.json's meta.ceiling (an output only: nothing reads it back, so there is no from_json).
void to_json(nlohmann::json& j, const ReportCeiling& c);
// A "## Ceiling" section: the explanation, the per-light table, how it was measured.
std::string ceilingMarkdown(const ReportCeiling& c);
// The same as an HTML section (<h2>, paragraphs, a table); every text escaped.
std::string ceilingHtml(const ReportCeiling& c);

}  // namespace proxyvis
