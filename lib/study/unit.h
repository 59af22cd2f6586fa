#pragma once
// One work unit of a render-compare study (plan/plan.h): what it renders, what it keeps, and its
// result file units/K.result (plan/unit_file.h) with the marker units/K.done written last.
#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <vector>

#include "plan/plan.h"
#include "render/render_scene.h"
#include "render/renderer.h"
#include "study/ceiling_phase.h"
#include "study/compare_options.h"
#include "study/scene_facts.h"

namespace proxyvis {

struct UnitResult {
  // equal-spp and reference: one render; equal-time: one per estimator of --estimators, in
  // that order. Renders of the first seed keep every image, the others their radiance only.
  std::vector<RenderResult> renders;
  // The ceiling unit: its measurement (the ceiling is computed by the merge, studyCeiling), and
  // in `renders` its own short exact render when the study has no exact cell.
  std::optional<CeilingUnitMeasurement> ceiling;
  SceneFacts facts;

  bool operator==(const UnitResult&) const = default;
};

// The header of a unit result besides its stamp (plan/unit_stamp.h): {"facts", "renders" (their
// numbers: the images are the unit file's), "ceiling" (the ceiling unit only)}.
void to_json(nlohmann::json& j, const UnitResult& r);
void from_json(const nlohmann::json& j, UnitResult& r);

// Renders unit `unit` of `plan` (options parsed from the plan).
UnitResult runUnit(const RenderScene& scene, const SceneFacts& facts, const CompareOptions& options,
                   const StudyPlan& plan, size_t unit);

// Writes the result (temporary name, then rename), then the marker.
void writeUnitResult(const std::filesystem::path& dir, const StudyPlan& plan, size_t unit,
                     const UnitResult& result);

// Reads unit `unit`'s result and checks that it belongs to `plan` (its stamp: index, kind, scene
// hash, seed, build and study) and that its images are `width` x `height` RGB; throws Error
// naming the file otherwise, or when it is missing.
UnitResult readUnitResult(const std::filesystem::path& dir, const StudyPlan& plan, size_t unit,
                          int width, int height);

}  // namespace proxyvis
