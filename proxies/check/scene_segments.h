#pragma once
// The `scene` segment distribution: what the renderer traces. Segment i starts at a shading point
// (the camera's primary hit through a uniformly jittered film position, Rng(seed, i)) and ends at
// a uniform area sample on the scene's lights. Uses lib/render's Camera and LightSampler so the
// distribution is the renderer's.
#include <cstdint>
#include <string>

#include <functional>
#include <memory>
#include <vector>

#include "proxies/check/box_tree.h"
#include "proxies/check/ray_classify.h"
#include "scene/scene_desc.h"

namespace proxyvis {

// One draw of the scene distribution in world space: segment `index` from the camera's primary
// hit (Rng(seed, index)) to a uniform light sample; `hit_user` is the user id (mesh index) of the
// object hit. valid = false: the primary ray hit nothing.
struct WorldSegment {
  Segment segment;
  uint32_t hit_user = 0;
  bool valid = false;
};
using WorldSegmentSource = std::function<WorldSegment(uint64_t index)>;

// The world draws of the scene distribution (thread-safe). Throws Error if the scene has no
// lights. `full` must outlive the source.
WorldSegmentSource worldSceneSegments(const TraceScene& full, const SceneDesc& scene,
                                      uint64_t seed);

// Where a mesh's original and proxy lie in the world: one placement per instance, or one
// (identity) for a placed mesh whose original and proxy are given in world space. Each has the
// world box of original and proxy together.
struct MeshPlacements {
  uint32_t mesh = 0;  // its user id in the full scene
  uint64_t seed = 0;
  std::vector<Affine3f> to_object;
  std::unique_ptr<BoxTree> world_boxes;
};

// A placed mesh: `both` is the world box of its original and proxy (already in world space).
MeshPlacements placedMeshPlacements(uint32_t mesh, const Bounds3f& both, uint64_t seed);
// An instanced mesh: `both` is the box of original and proxy in object space. Throws Error if the
// mesh has no instance or one is singular.
MeshPlacements instancedMeshPlacements(const SceneDesc& scene, uint32_t mesh, const Bounds3f& both,
                                       uint64_t seed);

// The segment of `world` for this mesh: none (false) when the draw hit nothing, starts on the
// mesh itself, or crosses no placement's box; else mapped into the object space of one crossed
// placement, chosen uniformly by a hash of (seed, index). `scratch` is reused storage.
bool segmentForMesh(const MeshPlacements& m, uint64_t index, const WorldSegment& world,
                    Segment& out, std::vector<uint32_t>& scratch);

// `full` holds every object of the scene (user id = mesh index). Primary hits on geometry whose
// user id is `exclude_user_id` are skipped (the generator returns false): the renderer traces an
// object's own shadow rays against its original, never its proxy (docs/design.md, pitfall 1).
// Throws Error if the scene has no lights. `full` and `scene` must outlive the generator.
SegmentGenerator sceneSegments(const TraceScene& full, const SceneDesc& scene,
                               uint32_t exclude_user_id, uint64_t seed);

// `generator` restricted to the segments that cross `box` (the others give none): a segment that
// passes outside the box of both original and proxy misses both and says nothing about the proxy.
SegmentGenerator segmentsCrossing(SegmentGenerator generator, const Bounds3f& box);

// The scene distribution for a mesh that only appears through instances, in its object space:
// each world segment of sceneSegments (excluding shading points on its instances) is mapped into
// the object space of one of the mesh's instances whose world box it crosses (chosen by a hash
// of the index when several do). A segment that crosses no instance's box gives none: it would
// miss both original and proxy. `object_bounds`: the box of the original and its proxy together
// in object space. Throws Error if the mesh has no instance or one is singular.
SegmentGenerator instanceSceneSegments(const TraceScene& full, const SceneDesc& scene,
                                       uint32_t mesh_index, const Bounds3f& object_bounds,
                                       uint64_t seed);

// Every placed mesh (addMesh, transformed) and every instance (addPrototype/addInstance) of the
// scene, user id = mesh index; meshes are loaded with loadMesh.
std::unique_ptr<TraceScene> buildFullScene(TraceDevice& device, const SceneDesc& scene);

// `mesh` with `transform` applied to its vertices in float: what the tracer traces for a mesh
// placed with a transform (TraceSceneBuilder::addMesh), so a placed class is checked on it.
TriMesh transformedMesh(const TriMesh& mesh, const Affine3f& transform);

}  // namespace proxyvis
