#pragma once
// The `scene` segment distribution: what the renderer traces. Segment i starts at a shading point
// (the camera's primary hit through a uniformly jittered film position, Rng(seed, i)) and ends at
// a uniform area sample on the scene's lights. Uses lib/render's Camera and LightSampler so the
// distribution is the renderer's.
#include <cstdint>
#include <string>

#include "proxies/check/ray_classify.h"
#include "scene/scene_desc.h"

namespace proxyvis {

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

// `mesh` with `transform` applied to its vertices.
TriMesh transformedMesh(const TriMesh& mesh, const Affine3f& transform);

}  // namespace proxyvis
