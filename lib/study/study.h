#pragma once
// A render-compare study as a plan of work units (plan/plan.h): planning it and the scene its plan
// names (study_merge.h gathers the units' results into the cells, the ceiling and the reference).
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

}  // namespace proxyvis
