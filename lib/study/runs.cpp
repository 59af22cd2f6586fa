#include "study/runs.h"

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

RenderSettings runSettings(const CompareOptions& options, EstimatorKind kind, int spp,
                           double time_budget, int run) {
  RenderSettings settings;
  settings.estimator = options.render.estimatorSetup(kind);
  settings.spp = time_budget > 0 ? INT_MAX : spp;
  settings.time_budget = time_budget;
  settings.seed = hashKeys(options.common.seed, uint64_t(run));
  settings.quiet = options.common.quiet;
  return settings;
}

RunScore scoreRun(const Image& radiance, const Image& reference) {
  return {meanSquaredError(radiance.pixels, reference.pixels),
          relativeMeanSquaredError(radiance.pixels, reference.pixels)};
}

void addRun(CellResult& cell, RenderResult r, const RunScore& score, const Image& reference,
            const std::filesystem::path& scene, const CompareOptions& options, EstimatorKind kind,
            std::string_view table, int run, int runs) {
  requireFinitePixels(r.radiance, scene,
                      fmt::format("the {} render (seed {})", estimatorName(kind), run + 1));
  ReportRow& row = cell.row;
  row.seconds_per_seed.push_back(r.seconds);
  cell.spp_reached.push_back(r.spp);
  cell.shading_seconds.push_back(r.shading_seconds);
  cell.visibility_seconds.push_back(r.visibility_seconds);
  cell.cpu_seconds.push_back(r.cpu_seconds);
  row.rays.proxy += double(r.rays.proxy) / runs;
  row.rays.original += double(r.rays.original) / runs;
  row.rays.probe += double(r.rays.probe) / runs;
  if (!options.common.quiet)
    std::fprintf(stderr, "render-compare: %-13s %-10s seed %d/%d: %5d spp %7.3f s\n",
                 estimatorName(kind), std::string(table).c_str(), run + 1, runs, r.spp, r.seconds);
  cell.mse_per_run.push_back(score.mse);
  cell.relmse_per_run.push_back(score.relmse);
  if (run == 0) {
    cell.error_map = squaredErrorPerPixel(r.radiance.pixels, reference.pixels, 3);
    row.proxy_class = proxyClassName(r.proxy_class);
    if (kind == EstimatorKind::kRoulette) row.learned = r.learned;
    cell.first = std::move(r);
    cell.first_seed = options.common.seed;
  }
}

void finishCell(CellResult& cell, EstimatorKind kind, std::string_view table, double time_budget,
                int seeds, int repeats) {
  ReportRow& row = cell.row;
  row.table = std::string(table);
  row.estimator = estimatorName(kind);
  row.spp = summarizeSeeds(cell.spp_reached).mean;
  row.seconds = summarizeSeeds(row.seconds_per_seed).mean;
  row.pixels = double(cell.first.radiance.width) * cell.first.radiance.height;
  row.seeds = seeds;
  row.repeats = repeats;
  row.spp_max = int(*std::max_element(cell.spp_reached.begin(), cell.spp_reached.end()));
  row.shading_seconds = summarizeSeeds(cell.shading_seconds).mean;
  row.visibility_seconds = summarizeSeeds(cell.visibility_seconds).mean;
  row.cpu_seconds = summarizeSeeds(cell.cpu_seconds).mean;
  if (time_budget > 0) {
    // The last pass is fitted to the budget (render_session.cpp), but the first pass and the
    // final bookkeeping still take what they take: the table's time is what was measured.
    row.time_budget = time_budget;
    row.budget_overshoot_seconds = row.seconds - time_budget;
  }
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

void scoreCell(CellResult& cell) {
  // One MSE per run, in run order (ReportRow::mse_per_seed pairs with seconds_per_seed).
  const std::vector<double>& mse = cell.mse_per_run;
  SeedSummary m = summarizeSeeds(mse), rel = summarizeSeeds(cell.relmse_per_run);
  ReportRow& row = cell.row;
  row.mse = m.mean;
  row.mse_stderr = m.standard_error;
  row.relmse = rel.mean;
  row.relmse_stderr = rel.standard_error;
  row.mse_per_seed = mse;
}

}  // namespace proxyvis
