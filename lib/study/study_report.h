#pragma once
// The report of a render-compare study from its units' results, shared by the single-machine
// run and --merge so that the two cannot drift: cells assembled in unit order, scored against the
// reference, the tables (JSON, CSV, Markdown), images, heat-maps and HTML written to a staged
// folder, which is committed.
#include <optional>
#include <vector>

#include "metrics/report.h"
#include "plan/plan.h"
#include "scene/scene_desc.h"
#include "study/compare_options.h"
#include "study/reference.h"
#include "study/study_merge.h"
#include "study/unit.h"
#include "util/staged_folder.h"

namespace proxyvis {

// Writes the report of the merged cells (study_merge.h) against `reference` into `folder` and
// commits it (then --json's copy). Returns the report.
Report reportStudy(const CompareOptions& options, const SceneDesc& desc, StudyMerge::Cells cells,
                   const Reference& reference, StagedFolder& folder);

}  // namespace proxyvis
