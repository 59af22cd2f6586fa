#pragma once
// One table cell: an estimator rendered with K seeds at a sample count (equal-spp) or a time
// budget (equal-time), scored against the reference.
#include <string_view>

#include "compare_options.h"
#include "metrics/report.h"
#include "render/render_scene.h"
#include "render/renderer.h"

namespace proxyvis {

struct CellResult {
  ReportRow row;                 // efficiency not filled yet (needs the exact row of the table)
  RenderResult first;            // the render of the first seed (images for the report)
  std::vector<float> error_map;  // its per-pixel squared error
};

// spp > 0 and time_budget == 0 for equal-spp; time_budget > 0 (spp ignored) for equal-time.
CellResult runCell(const RenderScene& scene, const CompareOptions& options, EstimatorKind kind,
                   int spp, double time_budget, const Image& reference, std::string_view table);

}  // namespace proxyvis
