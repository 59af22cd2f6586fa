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
    const TriMesh mesh = loadMesh(d.file);
    if (d.place) builder.addMesh(transformedMesh(mesh, d.transform), i);
    if (instanced) prototype[i] = builder.addPrototype(mesh);
  }
  for (const SceneInstanceDesc& inst : scene.instances)
    builder.addInstance(uint32_t(prototype[inst.mesh]), inst.transform, inst.mesh);
  return builder.build();
}

SegmentGenerator sceneSegments(const TraceScene& full, const SceneDesc& scene,
                               uint32_t exclude_user_id, uint64_t seed) {
  if (scene.lights.empty())
    throw Error(scene.path.string(), "the scene has no lights",
                "the scene distribution ends segments on light samples",
                "use --distribution sphere");
  auto camera = std::make_shared<Camera>(scene.camera);
  auto lights = std::make_shared<LightSampler>(scene.lights);
  // Offsets relative to the scene size keep segment ends off the surfaces they start on.
  const float eps = 1e-5f * std::max(1.0f, full.bounds().diagonal());
  return [&full, camera, lights, exclude_user_id, seed, eps](uint64_t index, Segment& out) {
    Rng rng(seed, index);
    const float fx = rng.uniformFloat() * float(camera->width());
    const float fy = rng.uniformFloat() * float(camera->height());
    Segment primary{camera->eye(), 0, camera->direction(fx, fy),
                    std::numeric_limits<float>::infinity()};
    const Hit hit = full.intersect(primary);
    if (!hit.hit || hit.user_id == exclude_user_id) return false;
    Vec3f n = normalize(hit.ng);
    if (dot(n, primary.dir) > 0) n = -n;  // the side the camera sees
    const Vec3f p = primary.org + hit.t * primary.dir + eps * n;
    const float u0 = rng.uniformFloat(), u1 = rng.uniformFloat(), u2 = rng.uniformFloat();
    const LightSample ls = lights->sample(u0, u1, u2);
    out.org = p;
    out.dir = ls.point - p;
    out.tnear = 0;
    out.tfar = 1.0f - 1e-4f;  // stop short of the light itself
    return true;
  };
}

namespace {

bool segmentCrossesBox(const Segment& s, const Bounds3f& b) {
  float t0 = s.tnear, t1 = s.tfar;
  for (int a = 0; a < 3; ++a) {
    const float inv = 1.0f / s.dir[a];
    float ta = (b.lo[a] - s.org[a]) * inv, tb = (b.hi[a] - s.org[a]) * inv;
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (!(t0 <= t1)) return false;  // also false for NaN (a zero direction on a slab's edge)
  }
  return true;
}

}  // namespace

SegmentGenerator segmentsCrossing(SegmentGenerator generator, const Bounds3f& box) {
  return [generator = std::move(generator), box](uint64_t index, Segment& out) {
    return generator(index, out) && segmentCrossesBox(out, box);
  };
}

SegmentGenerator instanceSceneSegments(const TraceScene& full, const SceneDesc& scene,
                                       uint32_t mesh_index, const Bounds3f& object_bounds,
                                       uint64_t seed) {
  struct Placement {
    Affine3f to_object;
    Bounds3f world;
  };
  auto placements = std::make_shared<std::vector<Placement>>();
  for (const SceneInstanceDesc& inst : scene.instances) {
    if (inst.mesh != mesh_index) continue;
    const std::optional<Affine3f> inv = inverse(inst.transform);
    if (!inv) throw Error(scene.path.string(), "singular instance transform");
    placements->push_back({*inv, transformedBounds(object_bounds, inst.transform)});
  }
  if (placements->empty())
    throw Error(scene.path.string(), "mesh has no instances",
                "the instanced scene distribution needs at least one");
  SegmentGenerator world = sceneSegments(full, scene, mesh_index, seed);
  return [world, placements, seed](uint64_t index, Segment& out) {
    Segment s;
    if (!world(index, s)) return false;
    uint32_t crossing = 0, chosen = 0;
    const uint64_t pick = hashKeys(seed ^ 0x5bd1e995u, index);
    for (uint32_t k = 0; k < placements->size(); ++k) {
      if (!segmentCrossesBox(s, (*placements)[k].world)) continue;
      // Reservoir sampling of one crossed instance, uniform among them.
      ++crossing;
      if (hashKeys(pick, k) % crossing == 0) chosen = k;
    }
    if (crossing == 0) return false;
    const Affine3f& m = (*placements)[chosen].to_object;
    out = s;
    out.org = m.apply(s.org);
    out.dir = applyLinear(m, s.dir);  // same t range: the map is affine
    return true;
  };
}

}  // namespace proxyvis
