#include "runs.h"

#include <fmt/core.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdio>

#include "metrics/efficiency.h"
#include "metrics/image_error.h"
#include "util/error.h"
#include "util/rng.h"

namespace proxyvis {

namespace {

ReportLearned toReportLearned(const LearnedSummary& l) {
  ReportLearned r;
  r.regions = int(l.regions);
  r.regions_roulette = int(l.regions_roulette);
  r.p_proxy_blocked = l.p_proxy_blocked;
  r.error_given_blocked = l.error_given_blocked;
  r.error_given_visible = l.error_given_visible;
  r.var_exact = l.var_exact;
  for (int i = 0; i < 2; ++i) {
    r.cost_proxy[i] = l.costs.proxy[i];
    r.cost_original[i] = l.costs.original[i];
  }
  r.cost_per_sample = l.costs.per_sample;
  r.predicted_efficiency = l.predicted_efficiency;
  return r;
}

}  // namespace

CellResult runCell(const RenderScene& scene, const CompareOptions& options, EstimatorKind kind,
                   int spp, double time_budget, std::string_view table) {
  std::vector<double> seconds, spp_reached, shading, visibility;
  CellResult cell;
  ReportRow& row = cell.row;
  for (int k = 0; k < options.seeds; ++k) {
    RenderSettings settings;
    settings.estimator = options.render.estimatorSetup(kind);
    settings.spp = time_budget > 0 ? INT_MAX : spp;
    settings.time_budget = time_budget;
    // Seed k of every cell is the same stream key: estimators differ only in what they trace.
    settings.seed = hashKeys(options.common.seed, uint64_t(k));
    settings.quiet = options.common.quiet;
    RenderResult r = render(scene, settings);
    requireFinitePixels(r.radiance, scene.desc().path,
                        fmt::format("the {} render (seed {})", estimatorName(kind), k + 1));
    seconds.push_back(r.seconds);
    spp_reached.push_back(r.spp);
    shading.push_back(r.shading_seconds);
    visibility.push_back(r.visibility_seconds);
    row.rays.proxy += double(r.rays.proxy) / options.seeds;
    row.rays.original += double(r.rays.original) / options.seeds;
    row.rays.probe += double(r.rays.probe) / options.seeds;
    if (!options.common.quiet)
      std::fprintf(stderr, "render-compare: %-13s %-10s seed %d/%d: %5d spp %7.3f s\n",
                   estimatorName(kind), std::string(table).c_str(), k + 1, options.seeds, r.spp,
                   r.seconds);
    cell.radiance_per_seed.push_back(r.radiance);
    if (k == 0) {
      row.proxy_class = proxyClassName(r.proxy_class);
      if (kind == EstimatorKind::kRoulette) row.learned = toReportLearned(r.learned);
      cell.first = std::move(r);
      cell.first_seed = options.common.seed;
    }
  }
  row.table = std::string(table);
  row.estimator = estimatorName(kind);
  row.spp = summarizeSeeds(spp_reached).mean;
  row.seconds = summarizeSeeds(seconds).mean;
  row.pixels = double(cell.first.radiance.width) * cell.first.radiance.height;
  row.seeds = options.seeds;
  row.spp_max = int(*std::max_element(spp_reached.begin(), spp_reached.end()));
  row.shading_seconds = summarizeSeeds(shading).mean;
  row.visibility_seconds = summarizeSeeds(visibility).mean;
  if (time_budget > 0) {
    // The last pass is fitted to the budget (renderer.cpp), but the first pass and the final
    // bookkeeping still take what they take: the table's time is what was measured.
    row.time_budget = time_budget;
    row.budget_overshoot_seconds = row.seconds - time_budget;
  }
  return cell;
}

void requireFinitePixels(const Image& image, const std::filesystem::path& scene,
                         const std::string& what) {
  const auto bad = std::find_if(image.pixels.begin(), image.pixels.end(),
                                [](float v) { return !std::isfinite(v); });
  if (bad == image.pixels.end()) return;
  const size_t pixel = size_t(bad - image.pixels.begin()) / size_t(std::max(image.channels, 1));
  throw Error(scene.string(),
              fmt::format("{} has a non-finite pixel ({} at x={}, y={})", what, *bad,
                          pixel % size_t(std::max(image.width, 1)),
                          pixel / size_t(std::max(image.width, 1))),
              "a radiance of the scene overflows single-precision floats, so no error or "
              "efficiency can be computed",
              "scale the scene's light and material values down");
}

void requireFiniteRows(const std::vector<ReportRow>& rows, const std::filesystem::path& scene) {
  for (const ReportRow& r : rows)
    if (!std::isfinite(r.mse) || !std::isfinite(r.relmse) || !std::isfinite(r.efficiency))
      throw Error(scene.string(),
                  fmt::format("the {} row of {} has a non-finite error (MSE {}, relMSE {}, "
                              "efficiency {})",
                              r.estimator, r.table, r.mse, r.relmse, r.efficiency),
                  "the squared errors overflow: the scene's radiance is too large",
                  "scale the scene's light and material values down");
}

void scoreCell(CellResult& cell, const Image& reference) {
  std::vector<double> mse, relmse;
  for (const Image& image : cell.radiance_per_seed) {
    mse.push_back(meanSquaredError(image.pixels, reference.pixels));
    relmse.push_back(relativeMeanSquaredError(image.pixels, reference.pixels));
  }
  cell.error_map = squaredErrorPerPixel(cell.first.radiance.pixels, reference.pixels, 3);
  cell.radiance_per_seed.clear();
  SeedSummary m = summarizeSeeds(mse), rel = summarizeSeeds(relmse);
  ReportRow& row = cell.row;
  row.mse = m.mean;
  row.mse_stderr = m.standard_error;
  row.relmse = rel.mean;
  row.relmse_stderr = rel.standard_error;
  row.mse_per_seed = mse;
}

}  // namespace proxyvis
