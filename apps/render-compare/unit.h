#pragma once
// One work unit of a render-compare study (plan.h): what it renders, what it keeps, and its file
// units/K.result with the marker units/K.done written last.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "ceiling_phase.h"
#include "metrics/report.h"
#include "plan.h"
#include "proxies/check/class_trust.h"
#include "render/render_scene.h"
#include "render/renderer.h"

namespace proxyvis {

// What the report says about the loaded scene; every unit records it, so the merge needs no
// scene loading (only the scene description, for image metadata).
struct SceneFacts {
  ProxyClass proxy_class = ProxyClass::kGeneral;
  bool uses_proxies = false;
  bool instances_flattened = false;
  // The BVH build every render used (RenderScene::buildChoice()): name, reason, description.
  std::string build, build_reason, build_description;
  uint64_t original_triangles = 0, proxy_triangles = 0;
  std::vector<std::string> warnings;
  nlohmann::json proxy_classes = nlohmann::json::array();  // report.meta.proxy_classes
  std::vector<std::string> trust_notes;  // one per proxy whose claimed class was not taken as is
};
SceneFacts sceneFacts(const RenderScene& scene, const std::vector<ProxyTrust>& trust);

struct UnitResult {
  // equal-spp and reference: one render; equal-time: one per estimator of --estimators, in
  // that order. Renders of the first seed keep every image, the others their radiance only.
  std::vector<RenderResult> renders;
  // The ceiling unit: its measurement (the ceiling is computed by the merge, studyCeiling), and
  // in `renders` its own short exact render when the study has no exact cell.
  std::optional<CeilingUnitMeasurement> ceiling;
  SceneFacts facts;
};

// Renders unit `unit` of `plan` (options parsed from the plan).
UnitResult runUnit(const RenderScene& scene, const SceneFacts& facts, const CompareOptions& options,
                   const StudyPlan& plan, size_t unit);

// DIR/units/K.result and DIR/units/K.done.
std::filesystem::path unitResultPath(const std::filesystem::path& dir, size_t unit);
std::filesystem::path unitDonePath(const std::filesystem::path& dir, size_t unit);

// Writes the result (temporary name, then rename), then the marker.
void writeUnitResult(const std::filesystem::path& dir, const StudyPlan& plan, size_t unit,
                     const UnitResult& result);

// Reads unit `unit`'s result and checks that it belongs to `plan` (its index, kind, scene hash,
// seed, build and study); throws Error naming the file otherwise, or when it is missing.
UnitResult readUnitResult(const std::filesystem::path& dir, const StudyPlan& plan, size_t unit);

// `render-compare --run-unit DIR K`: reads the plan, loads the scene (checking its hash against
// the plan's), renders unit K with SLURM_CPUS_PER_TASK threads when set, writes its result.
int runUnitCommand(const std::filesystem::path& dir, size_t unit, bool quiet);

}  // namespace proxyvis
