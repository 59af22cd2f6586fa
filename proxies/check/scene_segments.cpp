#include "proxies/check/scene_segments.h"

#include <algorithm>
#include <memory>
#include <optional>
#include <vector>

#include "mesh/io/mesh_io.h"
#include "render/camera.h"
#include "render/light_sampler.h"
#include "scene/transform.h"
#include "util/error.h"
#include "util/rng.h"

namespace proxyvis {

TriMesh transformedMesh(const TriMesh& mesh, const Affine3f& transform) {
  TriMesh m = mesh;
  for (Vec3f& v : m.vertices) v = transform.apply(v);
  return m;
}

std::unique_ptr<TraceScene> buildFullScene(TraceDevice& device, const SceneDesc& scene) {
  TraceSceneBuilder builder(device);
  std::vector<int64_t> prototype(scene.meshes.size(), -1);
  for (uint32_t i = 0; i < scene.meshes.size(); ++i) {
    const SceneMeshDesc& d = scene.meshes[i];
    bool instanced = false;
    for (const SceneInstanceDesc& inst : scene.instances) instanced = instanced || inst.mesh == i;
    if (!d.place && !instanced) continue;
    const TriMesh mesh = loadSceneMesh(d);
    if (d.place) builder.addMesh(transformedMesh(mesh, d.transform), i);
    if (instanced) prototype[i] = builder.addPrototype(mesh);
  }
  for (const SceneInstanceDesc& inst : scene.instances)
    builder.addInstance(uint32_t(prototype[inst.mesh]), inst.transform, inst.mesh);
  return builder.build();
}

WorldSegmentSource worldSceneSegments(const TraceScene& full, const SceneDesc& scene,
                                      uint64_t seed) {
  if (scene.lights.empty())
    throw Error(scene.path.string(), "the scene has no lights",
                "the scene distribution ends segments on light samples",
                "use --distribution sphere");
  auto camera = std::make_shared<Camera>(scene.camera);
  auto lights = std::make_shared<LightSampler>(scene.lights);
  // Offsets relative to the scene size keep segment ends off the surfaces they start on.
  const float eps = 1e-5f * std::max(1.0f, full.bounds().diagonal());
  return [&full, camera, lights, seed, eps](uint64_t index) {
    WorldSegment w;
    Rng rng(seed, index);
    const float fx = rng.uniformFloat() * float(camera->width());
    const float fy = rng.uniformFloat() * float(camera->height());
    Segment primary{camera->eye(), 0, camera->direction(fx, fy),
                    std::numeric_limits<float>::infinity()};
    const Hit hit = full.intersect(primary);
    if (!hit.hit) return w;
    Vec3f n = normalize(hit.ng);
    if (dot(n, primary.dir) > 0) n = -n;  // the side the camera sees
    const Vec3f p = primary.org + hit.t * primary.dir + eps * n;
    const float u0 = rng.uniformFloat(), u1 = rng.uniformFloat(), u2 = rng.uniformFloat();
    const LightSample ls = lights->sample(u0, u1, u2);
    w.segment.org = p;
    w.segment.dir = ls.point - p;
    w.segment.tnear = 0;
    w.segment.tfar = 1.0f - 1e-4f;  // stop short of the light itself
    w.hit_user = hit.user_id;
    w.valid = true;
    return w;
  };
}

SegmentGenerator sceneSegments(const TraceScene& full, const SceneDesc& scene,
                               uint32_t exclude_user_id, uint64_t seed) {
  WorldSegmentSource world = worldSceneSegments(full, scene, seed);
  return [world, exclude_user_id](uint64_t index, Segment& out) {
    const WorldSegment w = world(index);
    if (!w.valid || w.hit_user == exclude_user_id) return false;
    out = w.segment;
    return true;
  };
}

SegmentGenerator segmentsCrossing(SegmentGenerator generator, const Bounds3f& box) {
  return [generator = std::move(generator), box](uint64_t index, Segment& out) {
    return generator(index, out) && segmentCrossesBox(out, box);
  };
}

MeshPlacements placedMeshPlacements(uint32_t mesh, const Bounds3f& both, uint64_t seed) {
  MeshPlacements m;
  m.mesh = mesh;
  m.seed = seed;
  m.to_object.push_back(Affine3f{});
  m.world_boxes = std::make_unique<BoxTree>(std::vector<Bounds3f>{both});
  return m;
}

MeshPlacements instancedMeshPlacements(const SceneDesc& scene, uint32_t mesh, const Bounds3f& both,
                                       uint64_t seed) {
  MeshPlacements m;
  m.mesh = mesh;
  m.seed = seed;
  std::vector<Bounds3f> boxes;
  for (const SceneInstanceDesc& inst : scene.instances) {
    if (inst.mesh != mesh) continue;
    const std::optional<Affine3f> inv = inverse(inst.transform);
    if (!inv) throw Error(scene.path.string(), "singular instance transform");
    m.to_object.push_back(*inv);
    boxes.push_back(transformedBounds(both, inst.transform));
  }
  if (boxes.empty())
    throw Error(scene.path.string(), "mesh has no instances",
                "the instanced scene distribution needs at least one");
  m.world_boxes = std::make_unique<BoxTree>(std::move(boxes));
  return m;
}

bool segmentForMesh(const MeshPlacements& m, uint64_t index, const WorldSegment& world,
                    Segment& out, std::vector<uint32_t>& scratch) {
  if (!world.valid || world.hit_user == m.mesh) return false;
  scratch.clear();
  m.world_boxes->crossed(world.segment, scratch);
  if (scratch.empty()) return false;
  // Reservoir sampling of one crossed placement, uniform among them, in increasing order.
  const uint64_t pick = hashKeys(m.seed ^ 0x5bd1e995u, index);
  uint32_t crossing = 0, chosen = 0;
  for (const uint32_t k : scratch) {
    ++crossing;
    if (hashKeys(pick, k) % crossing == 0) chosen = k;
  }
  const Affine3f& to_object = m.to_object[chosen];
  out = world.segment;
  out.org = to_object.apply(world.segment.org);
  out.dir = applyLinear(to_object, world.segment.dir);  // same t range: the map is affine
  return true;
}

SegmentGenerator instanceSceneSegments(const TraceScene& full, const SceneDesc& scene,
                                       uint32_t mesh_index, const Bounds3f& object_bounds,
                                       uint64_t seed) {
  auto placements = std::make_shared<MeshPlacements>(
      instancedMeshPlacements(scene, mesh_index, object_bounds, seed));
  WorldSegmentSource world = worldSceneSegments(full, scene, seed);
  return [world, placements](uint64_t index, Segment& out) {
    thread_local std::vector<uint32_t> scratch;
    return segmentForMesh(*placements, index, world(index), out, scratch);
  };
}

}  // namespace proxyvis
