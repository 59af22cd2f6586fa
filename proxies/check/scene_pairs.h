#pragma once
// proxy-check SCENE.json: every (mesh, proxy) pair of a scene checked, under the sphere
// distribution or the scene's own (docs/classification.md). Instanced or placed, a proxy's exact
// check and distances are in object space, where its class was proved (containment does not
// change under an affine, invertible placement; the placement's float rounding could make
// touching surfaces cross). Under the scene distribution a placed mesh is traced in world space,
// where its segments are; an instanced one maps them into object space.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "mesh/tri_mesh.h"
#include "proxies/check/pair_check.h"
#include "scene/scene_desc.h"

namespace proxyvis {

// Draws per prototype until the requested segments are classified; a prototype that the scene's
// segments rarely cross stops after this many attempts per requested segment, with a warning.
inline constexpr uint64_t kSceneAttemptsPerRay = 1000;

// One (mesh, proxy) pair of the scene: its meshes and its check.
struct ScenePair {
  uint32_t mesh = 0;
  size_t proxy = 0;              // in the mesh's proxies
  TriMesh original, proxy_mesh;  // object space
  PairCheckReport report;
};

// Checks every pair with `options` (its rays, seed, expectation; without one, the class the
// scene claims must hold), under the scene distribution when `scene_distribution`: one shared
// stream of the scene's draws serves every pair. Pairs run in parallel under one progress bar.
std::vector<ScenePair> checkScenePairs(const SceneDesc& scene, const PairCheckOptions& options,
                                       bool scene_distribution);

}  // namespace proxyvis
