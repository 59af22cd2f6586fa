#pragma once
// render-compare's ceiling phase: after the cells are rendered, a short measurement of the
// renderer's own segments against proxy and original (render/ceiling_stats.h), priced with the
// exact cells' shading cost, gives the oracle ceiling (estimate/ceiling.h) that every report row
// is compared with.
#include <vector>

#include "compare_options.h"
#include "metrics/report.h"
#include "runs.h"

namespace proxyvis {

// At most this many passes (light samples per pixel) are traced against proxy and original...
inline constexpr int kCeilingPasses = 8;
// ...and after the first two, none starts once the phase has used this share of the renders' time.
inline constexpr double kCeilingTimeShare = 0.05;

// Measures and computes the ceiling. `cells` are the rendered cells (their exact renders give
// c_s; without one, a short exact render is made). Prints one line on stderr unless quiet.
// renders_seconds >= 0 replaces the cells' render time in the time cap (a work unit, plan.h,
// runs before the cells are known).
ReportCeiling runCeilingPhase(const RenderScene& scene, const CompareOptions& options,
                              const std::vector<CellResult>& cells, double renders_seconds = -1);

// Puts the ceiling in the report and on every row (rows' `ceiling`, hence `of_ceiling`).
void applyCeiling(Report& report, const ReportCeiling& ceiling);

}  // namespace proxyvis
