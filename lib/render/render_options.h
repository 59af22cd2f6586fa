#pragma once
// The flags of every program that renders a scene (render, render-compare): image size, proxy
// choice, BVH build and the estimators' settings, with their ranges, and what they become
// (RenderSceneOptions, EstimatorSetup). One place, so the two programs cannot drift apart.
#include <CLI/CLI.hpp>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "estimate/visibility_estimator.h"
#include "render/render_scene.h"
#include "scene/scene_desc.h"

namespace proxyvis {

// The ranges of the numeric flags: what a run can use, so that a typo fails at once instead of
// running for days or bypassing the scene's own limits.
inline constexpr uint64_t kMaxSpp = 1 << 24;  // also the largest automatic reference
inline constexpr double kMaxRenderSeconds = 86400;
inline constexpr uint64_t kMaxProbes = 4096;

struct RenderFlags {
  int width = 0, height = 0;  // 0 (not given) = the scene's resolution
  std::string proxy_kind;     // which proxy of each mesh ("outside", "inside", "general")
  double q_min = 0.05;
  int probes = 16;
  bool probes_given = false;  // --probes was on the command line (the data-parallel renderer,
                              // which has no probes, refuses it rather than ignore it)
  // Roulette's cost model: "measured" (per region, from timed rays and queries: its choices then
  // depend on timing and are not bit-reproducible, the estimate stays unbiased) or five numbers
  // in ns "c_p0,c_p1,c_o0,c_o1,c_s" (fixed: the same seed gives the same image at any thread
  // count).
  std::string roulette_costs = "measured";
  // How instances are traced: "instanced" (one BVH per mesh), "flat" (every instance copied into
  // one BVH), "auto" (flat when the flattened Embree scenes' estimated bytes fit the memory
  // budget: render_scene_build.h).
  std::string build = "auto";
  double memory_budget_gib = -1;  // --memory-budget in GiB; < 0: defaultMemoryBudgetBytes()

  std::optional<ClassCosts> fixed_costs;  // parsed from roulette_costs by resolve()

  // Parses roulette_costs; throws Error for a bad value.
  void resolve();
  // --width/--height into the scene's camera.
  void applyTo(SceneDesc& scene) const;
  RenderSceneOptions sceneOptions(bool quiet) const;
  // The estimator's setup from these flags (the renderer fills in regions and the class).
  EstimatorSetup estimatorSetup(EstimatorKind kind) const;
};

// "a,b,,c" -> {"a", "b", "c"} (the flags' comma-separated lists).
std::vector<std::string> splitCommaList(const std::string& list);

// Adds --width, --height, --proxy-kind, --q-min, --probes, --build, --memory-budget,
// --roulette-costs.
void addRenderFlags(CLI::App& app, RenderFlags& flags);

}  // namespace proxyvis
