#include "proxies/check/scene_pairs.h"

#include <fmt/core.h>
#include <tbb/parallel_for.h>

#include <memory>

#include "mesh/io/mesh_io.h"
#include "proxies/check/scene_segments.h"
#include "proxies/check/scene_stream.h"
#include "scene/transform.h"
#include "util/progress.h"

namespace proxyvis {

namespace {

// Every pair's segments from one shared stream of the scene's draws: a primary ray into the whole
// scene per index serves every proxy, instead of one per proxy.
std::vector<Classification> classifyScenePairs(const PairCheckOptions& o, const SceneDesc& scene,
                                               const TraceScene& full,
                                               const std::vector<ScenePair>& pairs) {
  TraceDevice device;
  std::vector<std::unique_ptr<TraceScene>> scenes;
  std::vector<MeshPlacements> placements(pairs.size());
  std::vector<StreamTarget> targets(pairs.size());
  for (size_t i = 0; i < pairs.size(); ++i) {
    const ScenePair& c = pairs[i];
    const SceneMeshDesc& mesh = scene.meshes[c.mesh];
    // A placed mesh's segments are in world space: so are its meshes here. Instances map their
    // segments into object space instead.
    Bounds3f both;
    for (const TriMesh* m : {&c.original, &c.proxy_mesh}) {
      TriMesh placed;
      if (mesh.place) m = &(placed = transformedMesh(*m, mesh.transform));
      TraceSceneBuilder builder(device);
      builder.addMesh(*m);
      scenes.push_back(builder.build());
      both.extend(m->bounds());
    }
    // A segment outside the box of both misses both: only the others are counted.
    placements[i] = mesh.place ? placedMeshPlacements(c.mesh, both, o.seed)
                               : instancedMeshPlacements(scene, c.mesh, both, o.seed);
    targets[i] = {scenes[2 * i].get(), scenes[2 * i + 1].get(), &placements[i]};
  }
  ClassifyOptions co;
  co.segments = o.rays;
  co.max_attempts = o.rays * kSceneAttemptsPerRay;
  co.quiet = o.quiet;
  co.max_error_segments = o.max_error_segments;
  return classifySceneStream(worldSceneSegments(full, scene, o.seed), targets, co);
}

void checkScenePair(PairCheckOptions po, const SceneDesc& scene, const Classification* classified,
                    ScenePair& c) {
  const SceneMeshDesc& mesh = scene.meshes[c.mesh];
  const ProxyRef& ref = mesh.proxies[c.proxy];
  po.quiet = true;
  if (classified) {
    po.classified = classified;
    po.max_attempts = po.rays * kSceneAttemptsPerRay;
    po.distribution_name = "scene";
    po.distribution_note =
        mesh.place
            ? "camera primary hits on the other objects (an object's own shadow rays use its "
              "original) to uniform light samples, those crossing the box of original or proxy; a "
              "light sample inside the proxy would void the outside guarantee (docs/design.md, "
              "pitfall 2)"
            : "camera primary hits on the other objects to uniform light samples, those crossing "
              "the box of an instance of this mesh (original or proxy), each mapped into the "
              "object space of one such instance";
  }
  // Without an expectation, the class the scene claims is what must hold (docs/design.md,
  // pitfall 4).
  if (!po.expect && ref.verified_class) po.expect = ref.verified_class;
  c.report = checkPair(c.original, c.proxy_mesh, po);
  c.report.label = fmt::format("{} / {} ({})", mesh.name, ref.kind, ref.method);
  // A placed mesh is traced as float copies of its placed vertices, rounded again: its class
  // must hold on those too (docs/clearance.md).
  if (mesh.place && !mesh.transform.isIdentity()) {
    c.report.exact_placed = checkContainment(transformedMesh(c.original, mesh.transform),
                                             transformedMesh(c.proxy_mesh, mesh.transform));
    finishVerdicts(c.report);
  }
}

}  // namespace

std::vector<ScenePair> checkScenePairs(const SceneDesc& scene, const PairCheckOptions& options,
                                       bool scene_distribution) {
  // The scene distribution traces primary rays against every object of the scene.
  TraceDevice device;
  std::unique_ptr<TraceScene> full;
  if (scene_distribution) full = buildFullScene(device, scene);
  std::vector<ScenePair> checked;
  for (uint32_t m = 0; m < scene.meshes.size(); ++m)
    for (size_t p = 0; p < scene.meshes[m].proxies.size(); ++p) {
      checked.emplace_back();
      checked.back().mesh = m;
      checked.back().proxy = p;
    }
  const size_t pairs = checked.size();
  tbb::parallel_for(size_t(0), pairs, [&](size_t i) {
    ScenePair& c = checked[i];
    const SceneMeshDesc& mesh = scene.meshes[c.mesh];
    // Object space: where the class was proved, and what the exact check tests. Rounding a
    // placement's transform in float can make surfaces that touch there cross by an ulp.
    c.original = loadMesh(mesh.file);
    c.proxy_mesh = loadMesh(mesh.proxies[c.proxy].file);
  });
  std::vector<Classification> classified;
  if (full) classified = classifyScenePairs(options, scene, *full, checked);
  // The exact checks and distances, pairs in parallel, one progress bar over them.
  Progress progress("proxy-check", pairs, options.quiet || pairs < 2);
  tbb::parallel_for(size_t(0), pairs, [&](size_t i) {
    checkScenePair(options, scene, full ? &classified[i] : nullptr, checked[i]);
    progress.update();
  });
  progress.done();
  return checked;
}

}  // namespace proxyvis
