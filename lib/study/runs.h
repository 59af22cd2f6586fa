#pragma once
// The table cells: an estimator rendered with K seeds at a sample count (equal-spp) or a time
// budget (equal-time, K seeds x R repeats), scored against the reference. The estimators of a
// table take turns on the machine so that drift in its speed lands on all of them alike:
// seed by seed for equal-spp (runs.cpp), slice by slice within each seed for equal-time
// (runs_interleaved.cpp).
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "metrics/report.h"
#include "render/render_scene.h"
#include "render/renderer.h"
#include "study/compare_options.h"

namespace proxyvis {

struct CellResult {
  ReportRow row;       // errors filled by scoreCell(), efficiency by the caller (needs exact's row)
  RenderResult first;  // the render of the first seed (images for the report)
  uint64_t first_seed = 0;       // its RenderSettings::seed (image metadata)
  std::vector<float> error_map;  // per-pixel squared error of the first seed
  // Per run, in run order: its errors against the reference (scoreRun), summed up by scoreCell().
  std::vector<double> mse_per_run, relmse_per_run;
  // Per run, summed up by finishCell().
  std::vector<double> spp_reached, shading_seconds, visibility_seconds, cpu_seconds;
};

// The settings of run `run` of a cell: run r * seeds + k is seed k of repeat r, and its stream
// key is the same in every cell, so estimators differ only in what they trace.
RenderSettings runSettings(const CompareOptions& options, EstimatorKind kind, int spp,
                           double time_budget, int run);

// A run's errors against the reference, computed as its render arrives (the images of the
// other seeds are then dropped: a merge's memory does not grow with its units).
struct RunScore {
  double mse = 0, relmse = 0;
};
RunScore scoreRun(const Image& radiance, const Image& reference);

// Adds run `run` (of `runs`) with its score to the cell; the first run's render is kept with its
// error map against `reference`. `table` only names it on stderr, `scene` in errors.
void addRun(CellResult& cell, RenderResult r, const RunScore& score, const Image& reference,
            const std::filesystem::path& scene, const CompareOptions& options, EstimatorKind kind,
            std::string_view table, int run, int runs);

// The row's means over the runs (after every addRun()). time_budget > 0 for equal-time.
void finishCell(CellResult& cell, EstimatorKind kind, std::string_view table, double time_budget,
                int seeds, int repeats);

// Run `run` of the equal-time cells: one render per estimator in options.estimator_list order,
// interleaved (runs_interleaved.cpp): a warm-up of each estimator, then round-robin slices. The
// equal-spp renders are one render() each, the estimators alternating seed by seed (plan.cpp).
std::vector<RenderResult> runEqualTimeRun(const RenderScene& scene, const CompareOptions& options,
                                          double time_budget, int run);

// How the equal-time renders were timed: a report note, and the same facts for the JSON meta.
std::string interleavedTimingNote(const CompareOptions& options);
nlohmann::json interleavedTimingMeta(const CompareOptions& options);

// Throws Error naming `scene` if `image` has an inf or NaN pixel: every MSE and efficiency would
// then be inf or NaN, and a table of those says nothing. `what` names the render.
void requireFinitePixels(const Image& image, const std::filesystem::path& scene,
                         const std::string& what);

// Throws Error naming `scene` if a row's MSE, relMSE or efficiency is not finite.
void requireFiniteRows(const std::vector<ReportRow>& rows, const std::filesystem::path& scene);

// MSE, relMSE and their standard errors over the runs' scores.
void scoreCell(CellResult& cell);

}  // namespace proxyvis
