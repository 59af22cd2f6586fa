#pragma once
// render-compare's ceiling: a short measurement of the renderer's own segments against proxy and
// original (render/ceiling_stats.h), made by the study's ceiling unit, priced at the merge with
// the exact cells' shading cost, gives the oracle ceiling (estimate/ceiling.h) that every report
// row is compared with.
#include <nlohmann/json_fwd.hpp>
#include <vector>

#include "metrics/report.h"
#include "render/ceiling_stats.h"
#include "study/compare_options.h"
#include "study/runs.h"

namespace proxyvis {

// At most this many passes (light samples per pixel) are traced against proxy and original...
inline constexpr int kCeilingPasses = 8;
// ...and after the first two, none starts once the phase has used this share of the renders' time.
inline constexpr double kCeilingTimeShare = 0.05;

// What the ceiling unit measured; the ceiling itself needs c_s, which the exact cells' renders
// give, so it is computed where they are known (finishCeiling).
struct CeilingUnitMeasurement {
  CeilingMeasurement measurement;
  double seconds = 0;  // wall time of the unit's measurement (and of its own render, if made)
  double pixels = 0;   // of the image (the per-pixel MSE of exact at 1 spp)

  bool operator==(const CeilingUnitMeasurement&) const = default;
};

// True when no cell of the study is an exact render: then the ceiling unit makes its own short
// exact render to price c_s (with exact among the estimators, the cells' renders serve, as in a
// single run, and the unit renders nothing).
bool ceilingNeedsOwnRender(const CompareOptions& options);

// The ceiling unit's work: the measurement, its time cap a share of the planned renders' time
// (infinite: the pass cap alone). `own_exact` (when ceilingNeedsOwnRender) receives the short
// exact render.
CeilingUnitMeasurement measureCeiling(const RenderScene& scene, const CompareOptions& options,
                                      double planned_seconds, RenderResult* own_exact);

// The ceiling from the unit's measurement, c_s priced with `exact_renders` (at least one: the
// exact cells' first renders, or the unit's own) and the scene's verified proxy class. Prints one
// line on stderr unless quiet.
ReportCeiling finishCeiling(const CeilingUnitMeasurement& unit,
                            const std::vector<const RenderResult*>& exact_renders,
                            ProxyClass proxy_class, bool uses_proxies,
                            const CompareOptions& options);

// The measurement in a unit result's header, every number exactly: the CeilingMeasurement's keys
// (render/ceiling_stats.h) with "seconds" and "pixels".
void to_json(nlohmann::json& j, const CeilingUnitMeasurement& unit);
void from_json(const nlohmann::json& j, CeilingUnitMeasurement& unit);

// Puts the ceiling in the report and on every row (rows' `ceiling`, hence `of_ceiling`).
void applyCeiling(Report& report, const ReportCeiling& ceiling);

}  // namespace proxyvis
