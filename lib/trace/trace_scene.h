#pragma once
// Embree 3 tracing: a device, and scenes built from meshes and instances of meshes (so the 12 M
// triangle Nature scene costs the memory of its prototypes). Occlusion queries for segments,
// closest-hit queries, per-scene ray counters. Thread-safe; results independent of thread count.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "mesh/tri_mesh.h"

struct RTCDeviceTy;
struct RTCSceneTy;

namespace proxyvis {

// Row-major 3x4 affine transform (the upper three rows of a 4x4): p' = M * [p, 1].
struct Affine3f {
  float m[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};
  Vec3f apply(const Vec3f& p) const {
    return {m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
            m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
            m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]};
  }
  static Affine3f translation(const Vec3f& t) {
    Affine3f a;
    a.m[0][3] = t.x; a.m[1][3] = t.y; a.m[2][3] = t.z;
    return a;
  }
};

// A shadow segment: points org + t*dir for t in [tnear, tfar]. dir need not be normalized.
struct Segment {
  Vec3f org;
  float tnear = 0;
  Vec3f dir;
  float tfar = 1;
};

struct Hit {
  bool hit = false;
  float t = 0;
  Vec3f ng;            // geometric normal (world space, not normalized)
  float u = 0, v = 0;  // barycentrics
  uint32_t prim_id = 0;
  uint32_t geom_id = 0;      // geometry in the scene that was hit
  uint32_t instance_id = 0;  // instance index, or ~0u when a flattened mesh was hit
  uint32_t user_id = 0;      // the id given to addMesh/addInstance
};

// Owns one RTCDevice and registers an error callback that turns Embree errors into messages.
class TraceDevice {
 public:
  TraceDevice();
  ~TraceDevice();
  TraceDevice(const TraceDevice&) = delete;
  TraceDevice& operator=(const TraceDevice&) = delete;
  RTCDeviceTy* handle() const { return device_; }

 private:
  RTCDeviceTy* device_ = nullptr;
};

class TraceScene;

// Collects meshes and instances, then builds one committed Embree scene.
// Vertex and index data are copied into Embree-owned buffers, so a TriMesh may be destroyed
// after addMesh/addPrototype returns.
class TraceSceneBuilder {
 public:
  explicit TraceSceneBuilder(TraceDevice& device);
  ~TraceSceneBuilder();

  // A mesh placed directly in the top-level BVH (flattened). Returns its geometry id.
  uint32_t addMesh(const TriMesh& mesh, uint32_t user_id = 0);
  // A mesh to be instanced; returns a prototype id for addInstance.
  uint32_t addPrototype(const TriMesh& mesh);
  // An instance of a prototype with an affine transform. Returns the instance index.
  uint32_t addInstance(uint32_t prototype, const Affine3f& transform, uint32_t user_id = 0);

  // Builds the BVHs. The builder is empty afterwards.
  std::unique_ptr<TraceScene> build();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

class TraceScene {
 public:
  ~TraceScene();

  // True if anything blocks the segment (t in [tnear, tfar]).
  bool occluded(const Segment& s) const;
  // Batch form: out[i] = 1 if segs[i] is occluded. Parallel over the batch with TBB.
  void occluded(std::span<const Segment> segs, std::span<uint8_t> out) const;
  // Closest hit along org + t*dir, t in [tnear, tfar].
  Hit intersect(const Segment& ray) const;

  Bounds3f bounds() const;
  uint64_t triangleCount() const;  // counting every instance's triangles

  // Rays traced since construction or resetCounters() (occlusion and closest-hit).
  uint64_t raysTraced() const;
  void resetCounters();

  RTCSceneTy* handle() const;

 private:
  friend class TraceSceneBuilder;
  TraceScene();
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace proxyvis
