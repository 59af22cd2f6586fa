#pragma once
// A render-compare study as a plan of work units (plan/plan.h): planning it, the scene its plan
// names, and gathering the units' results into the table cells, the ceiling and the reference.
// render-compare runs a study three ways: planning it into a folder (--plan), one unit of it
// (--run-unit), and the report from every unit's result (--merge, and the single-machine run,
// which runs every unit in process first).
#include <filesystem>
#include <string>
#include <vector>

#include "plan/plan.h"
#include "scene/scene_desc.h"
#include "study/compare_options.h"
#include "study/runs.h"
#include "study/unit.h"

namespace proxyvis {

// The cells' units in the order one machine runs them: equal-spp by spp, seed by seed, every
// estimator once per seed in an order that rotates with the seed; then the equal-time runs; then
// the ceiling.
std::vector<PlannedUnit> planCellUnits(const CompareOptions& options);

// Appends the reference's partial renders for `spp` samples (rounded up to a multiple of the
// partials), or only records a cached reference of `cached_spp` > 0 samples.
void planReference(StudyPlan& plan, int spp, int cached_spp = 0);

// The plan of the cells (no reference yet) for `options`; `args` are its flags as the plan keeps
// them (the scene and paths absolute).
StudyPlan newStudyPlan(const std::vector<std::string>& args, const CompareOptions& options,
                       const SceneDesc& desc);

// `render-compare SCENE ... --out OUT --plan DIR`: writes DIR/plan.json and returns the plan. The
// reference's samples must be known before any unit runs: --reference-spp, or without
// --equal-time the automatic size from --spp.
StudyPlan writeStudyPlan(const std::vector<std::string>& args, const CompareOptions& options,
                         const SceneDesc& desc, const std::filesystem::path& dir);

// The scene description the plan's options (parsed from plan.args) give, refused when the
// scene's content changed since the plan was written.
SceneDesc plannedScene(const StudyPlan& plan, const CompareOptions& options);

// The most samples per pixel any cell render reached.
int largestSppReached(const StudyPlan& plan, const std::vector<UnitResult>& results);

// Every unit's result of the plan folder, checked against the plan (throws Error naming the
// first unit, in unit order, that is missing or foreign). Read in parallel.
std::vector<UnitResult> readUnitResults(const std::filesystem::path& dir, const StudyPlan& plan,
                                        const SceneDesc& desc);

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
