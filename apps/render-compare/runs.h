#pragma once
// One table cell: an estimator rendered with K seeds at a sample count (equal-spp) or a time
// budget (equal-time), scored against the reference.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "compare_options.h"
#include "metrics/report.h"
#include "render/render_scene.h"
#include "render/renderer.h"

namespace proxyvis {

struct CellResult {
  ReportRow row;       // errors filled by scoreCell(), efficiency by the caller (needs exact's row)
  RenderResult first;  // the render of the first seed (images for the report)
  uint64_t first_seed = 0;               // its RenderSettings::seed (image metadata)
  std::vector<Image> radiance_per_seed;  // kept until scoreCell()
  std::vector<float> error_map;          // per-pixel squared error of the first seed
};

// Renders the cell with K seeds. spp > 0 and time_budget == 0 for equal-spp; time_budget > 0
// (spp ignored) for equal-time. Rendering comes before scoring so that the reference can be
// sized by the samples every cell actually reached.
CellResult runCell(const RenderScene& scene, const CompareOptions& options, EstimatorKind kind,
                   int spp, double time_budget, std::string_view table);

// Throws Error naming `scene` if `image` has an inf or NaN pixel: every MSE and efficiency would
// then be inf or NaN, and a table of those says nothing. `what` names the render.
void requireFinitePixels(const Image& image, const std::filesystem::path& scene,
                         const std::string& what);

// Throws Error naming `scene` if a row's MSE, relMSE or efficiency is not finite.
void requireFiniteRows(const std::vector<ReportRow>& rows, const std::filesystem::path& scene);

// MSE, relMSE and their standard errors over the seeds; frees the per-seed images.
void scoreCell(CellResult& cell, const Image& reference);

}  // namespace proxyvis
