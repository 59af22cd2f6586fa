#pragma once
// The three ways render-compare runs a study (plan.h): planning it into a folder (--plan), one
// unit of it (--run-unit), and gathering the units' results for the report (--merge, and the
// single-machine run, which runs every unit in process first).
#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>
#include <vector>

#include "compare_options.h"
#include "plan.h"
#include "runs.h"
#include "scene/scene_desc.h"
#include "unit.h"

namespace proxyvis {

// The plan of the cells (no reference yet) for `options`, parsed from `app`.
StudyPlan newStudyPlan(const CLI::App& app, const CompareOptions& options, const SceneDesc& desc);

// `render-compare SCENE ... --out OUT --plan DIR`: writes DIR/plan.json. The reference's samples
// must be known before any unit runs: --reference-spp, or without --equal-time the automatic
// size from --spp.
int writeStudyPlan(const CLI::App& app, const CompareOptions& options, const SceneDesc& desc,
                   const std::filesystem::path& dir);

// The most samples per pixel any cell render reached.
int largestSppReached(const StudyPlan& plan, const std::vector<UnitResult>& results);

// A plan folder's study, options and scene description, every unit's result checked against
// the plan (throws Error naming the first unit that is missing or foreign).
struct MergeInputs {
  StudyPlan plan;
  CompareOptions options;
  SceneDesc desc;
  std::vector<UnitResult> results;
};
MergeInputs readMergeInputs(const std::filesystem::path& dir);

// The table cells from the units' results, in table order (equal-spp by spp, then equal-time;
// estimators in --estimators order), with the stems that name their images. The runs of a cell
// are added in seed order, whatever order the units ran in.
struct StudyCells {
  std::vector<CellResult> cells;
  std::vector<std::string> stems;
};
StudyCells assembleCells(const CompareOptions& options, const StudyPlan& plan,
                         std::vector<UnitResult>& results, const std::filesystem::path& scene);

// The ceiling from the ceiling unit's measurement, c_s priced with the exact cells' first renders
// (or the unit's own exact render when the study has none), its share of the renders' time
// filled in from the cells.
ReportCeiling studyCeiling(const CompareOptions& options, const StudyPlan& plan,
                           const std::vector<UnitResult>& results,
                           const std::vector<CellResult>& cells);

// The reference's partial renders, in partial order.
std::vector<const Image*> referencePartials(const StudyPlan& plan,
                                            const std::vector<UnitResult>& results,
                                            double& seconds);

}  // namespace proxyvis
