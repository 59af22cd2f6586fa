#include "proxies/check/scene_segments.h"

#include <memory>

#include "mesh/mesh_io.h"
#include "render/camera.h"
#include "render/light_sampler.h"
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

}  // namespace proxyvis
