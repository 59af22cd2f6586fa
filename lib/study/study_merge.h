#pragma once
// The report's inputs gathered unit by unit, so that memory does not grow with the number of
// units: the reference's partial renders are summed as they come (in partial order), then each
// cell unit's renders are scored against the finished reference and added to their cells at
// once; only the first seed's render of each cell (the report's images), the ceiling unit's
// result and the numbers are kept. The cells' runs arrive in run order in any plan order that
// keeps each cell's units in seed order, as the plan's order does (study.h, planCellUnits).
#include <filesystem>
#include <map>
#include <optional>
#include <tuple>
#include <vector>

#include "metrics/image_variance.h"
#include "plan/plan.h"
#include "scene/scene_desc.h"
#include "study/compare_options.h"
#include "study/reference.h"
#include "study/runs.h"
#include "study/unit.h"

namespace proxyvis {

class StudyMerge {
 public:
  StudyMerge(const CompareOptions& options, const StudyPlan& plan, const SceneDesc& desc);

  // The reference: its partial renders in partial order, then finishReference() (written to
  // `dir`), or an earlier run's cached reference.
  void addReferencePartial(const RenderResult& partial);
  void finishReference(bool flattened, const std::filesystem::path& dir);
  void useCachedReference(Reference reference);
  const Reference& reference() const { return *reference_; }

  // The scores of a cell unit's renders against the reference (pure: may run in parallel).
  std::vector<RunScore> score(const UnitResult& result) const;
  // Unit `unit` (equal-spp, equal-time or ceiling) with its scores, added to its cells.
  void addCellUnit(size_t unit, UnitResult result, const std::vector<RunScore>& scores);

  // The cells in table order with their rows' means and errors, their image stems, the ceiling
  // and the scene's facts (of the first cell unit added), once every cell unit is in.
  struct Cells {
    std::vector<CellResult> cells;
    std::vector<std::string> stems;
    ReportCeiling ceiling;
    SceneFacts facts;
  };
  Cells finish();

 private:
  const CompareOptions& o_;
  const StudyPlan& plan_;
  const SceneDesc& desc_;
  ImageVarianceAccumulator partials_;
  double reference_seconds_ = 0;
  std::optional<Reference> reference_;
  Cells out_;
  bool have_facts_ = false;
  std::map<std::tuple<int, EstimatorKind>, size_t> equal_spp_;  // (spp, estimator) -> cell
  size_t first_equal_time_ = 0;                                 // cell of estimator 0
  std::optional<UnitResult> ceiling_unit_;
};

// A plan folder's units merged in unit order (the reference's first), read in parallel batches:
// throws Error naming the first unit that is missing or foreign.
StudyMerge::Cells mergeUnitFiles(StudyMerge& merge, const std::filesystem::path& dir,
                                 const StudyPlan& plan, const SceneDesc& desc,
                                 const std::filesystem::path& report_dir);

}  // namespace proxyvis
