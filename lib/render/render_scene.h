#pragma once
// Everything the renderer traces against, built once per scene file:
//   - originals(): every object's original mesh (placed meshes flattened into the top-level
//     BVH, instanced meshes as Embree instances of one prototype per mesh). Primary rays and
//     exact shadow rays use it.
//   - proxies(): the same objects with each mesh's chosen proxy in place of its original (the
//     original where a mesh has no proxy).
//   - selfScene(mesh): one mesh's original in its object space, for the self-shadowing rule.
// Every object (a placed mesh or one instance) has a user id = its index in objects(), which
// Hit::user_id returns and the self-shadowing rule ignores (docs/design.md, pitfall 1): a shading
// point on object A traces A's original and the proxies of everything else.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "render/camera.h"
#include "render/light_sampler.h"
#include "render/render_scene_build.h"
#include "scene/scene_desc.h"
#include "trace/trace_scene.h"
#include "util/proxy_class.h"

namespace proxyvis {

struct RenderSceneOptions {
  // Per mesh, use the first proxy whose "kind" equals this ("outside", "inside", "general");
  // empty: the first proxy listed. Meshes without a matching proxy use their original.
  std::string proxy_kind;
  bool use_proxies = true;  // false: proxies() holds the originals (no proxy anywhere)
  // False skips a proxy not cheaper than its original, with a warning (chooseProxy in
  // scene_assembly.h says why); true keeps it.
  bool keep_larger_proxies = false;
  // How instances are traced (render_scene_build.h): Embree instances of one BVH per mesh,
  // copied into one flattened BVH (originals and proxies alike; faster to trace at the memory of
  // every instance's triangles), or auto: flattened when the estimated bytes of the flattened
  // Embree scenes fit memory_budget_bytes (< 0: defaultMemoryBudgetBytes()).
  InstanceBuild instance_build = InstanceBuild::kInstanced;
  double memory_budget_bytes = -1;
  TraceSceneOptions trace;  // Embree build options for all scenes
  bool quiet = false;       // no warnings on stderr (they are still in warnings())
};

struct RenderObject {
  uint32_t mesh = 0;      // index into SceneDesc::meshes
  int32_t instance = -1;  // index into SceneDesc::instances, -1 for a placed mesh
  Affine3f to_world;      // object space -> world
  Affine3f to_object;     // world -> object space (inverse)
  int32_t proxy = -1;     // index into SceneMeshDesc::proxies used for this object, -1 = none
};

class RenderScene {
 public:
  ~RenderScene();
  RenderScene(const RenderScene&) = delete;
  RenderScene& operator=(const RenderScene&) = delete;

  const SceneDesc& desc() const { return desc_; }
  const Camera& camera() const { return camera_; }
  const LightSampler& lights() const { return lights_; }
  const std::vector<RenderObject>& objects() const { return objects_; }

  const TraceScene& originals() const { return *originals_; }
  const TraceScene& proxies() const { return *proxies_; }
  // Original of mesh `mesh` in object space; only built for meshes that use a proxy (null
  // otherwise: their original already is in proxies()).
  const TraceScene* selfScene(uint32_t mesh) const { return self_[mesh].get(); }

  // The class the estimators may rely on: the verified class shared by every object that uses a
  // proxy, after the light checks; kGeneral if they differ, any is unverified or a check failed.
  // kGeneral too when no object uses a proxy (then proxies() equals originals()).
  ProxyClass proxyClass() const { return proxy_class_; }
  bool usesProxies() const { return uses_proxies_; }
  // Instances were copied into the flattened BVHs (RenderSceneOptions::instance_build) and the
  // scene has some: float rounding differs from instanced tracing (thin geometry such as leaf
  // cards self-intersects differently), so results of the two builds are not interchangeable.
  bool instancesFlattened() const { return build_.flat && build_.has_instances; }
  // Which build was used and why (reports say it: it is the exact baseline's configuration).
  const BuildChoice& buildChoice() const { return build_; }
  // The Embree device of every scene here (its memory monitor: bytes of the built scenes).
  const TraceDevice& device() const { return *device_; }
  // Human-readable warnings from loading (class downgrades, missing proxies).
  const std::vector<std::string>& warnings() const { return warnings_; }

  // Offset for shadow-ray origins and tnear, relative to the scene size.
  float epsilon() const { return epsilon_; }
  // Triangles of the flattened originals / proxies (every instance counted).
  uint64_t originalTriangles() const;
  uint64_t proxyTriangles() const;

 private:
  friend std::unique_ptr<RenderScene> loadRenderScene(const SceneDesc&, const RenderSceneOptions&);
  explicit RenderScene(SceneDesc desc);

  SceneDesc desc_;
  Camera camera_;
  LightSampler lights_;
  std::vector<RenderObject> objects_;
  std::unique_ptr<TraceDevice> device_;
  std::unique_ptr<TraceScene> originals_, own_proxies_;
  // own_proxies_, or originals_ when no object uses a proxy (one copy of the geometry, not two).
  const TraceScene* proxies_ = nullptr;
  std::vector<std::unique_ptr<TraceScene>> self_;
  ProxyClass proxy_class_ = ProxyClass::kGeneral;
  bool uses_proxies_ = false;
  BuildChoice build_;
  std::vector<std::string> warnings_;
  float epsilon_ = 1e-4f;
};

// The objects of a scene: placed meshes first, then instances, in file order; an object's index
// is its user id in every Embree scene. `chosen` is each mesh's proxy index (-1: none). Throws
// Error for a singular transform or a scene with nothing to render.
std::vector<RenderObject> renderObjects(const SceneDesc& desc, const std::vector<int>& chosen);

// Adds objects to `builder` with each object's geometry taken from geometry[mesh] (originals or
// proxies; null: the object is skipped), user id = the object's index. Placed meshes and, when
// `flatten`, instances go into the top-level BVH with their vertices mapped to world space;
// instances otherwise become Embree instances of one prototype per mesh, built on first use.
// `include` (one flag per object) limits it to some objects. The same calls give the same
// Embree answers, whichever process builds them (the data-parallel renderer relies on this).
void addRenderObjects(TraceSceneBuilder& builder, const std::vector<RenderObject>& objects,
                      const std::vector<const TriMesh*>& geometry, bool flatten,
                      const std::vector<bool>* include = nullptr);

// The offset for shadow-ray origins and tnear of a scene whose originals fill `bounds`
// (RenderScene::epsilon()): a fraction of the diagonal, never below an absolute floor.
float rayEpsilon(const Bounds3f& originals_bounds);

// Loads every mesh and proxy (loadMesh), builds the Embree scenes and checks the lights against
// the proxies (docs/design.md, pitfall 2: an outside proxy guarantees no HM' segments only if the
// light is outside it; an inside proxy guarantees no MH' only if the light is outside the
// original). The check is conservative: a light whose bounding box overlaps the proxy's (outside)
// or the original's (inside) world bounding box downgrades the scene's class to general, with a
// warning. The claimed classes are taken as the scene states them: apps establish them first
// (proxies/check/class_trust.h re-verifies a class whose recorded hash does not match). Throws
// Error for unreadable meshes or proxies.
std::unique_ptr<RenderScene> loadRenderScene(const SceneDesc& desc,
                                             const RenderSceneOptions& options = {});
std::unique_ptr<RenderScene> loadRenderScene(const std::filesystem::path& scene_file,
                                             const RenderSceneOptions& options = {});

}  // namespace proxyvis
