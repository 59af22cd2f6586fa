#pragma once
// Embree 3 tracing: a device, and scenes built from meshes and instances of meshes (so the 12 M
// triangle Nature scene costs the memory of its prototypes). Occlusion queries for segments,
// closest-hit queries, per-scene ray counters. Thread-safe; results independent of thread count.
//
// Self-shadowing: a ray leaving object A must not hit A's own proxy. Every query takes an
// optional `ignore_user_id`: geometry (flattened mesh or instance) added with that user id is
// invisible to that query, exactly. The Debian Embree 3.13.5 supports both context filters and
// ray masks (RTC_DEVICE_PROPERTY_{FILTER_FUNCTION,RAY_MASK}_SUPPORTED = 1); two exact strategies
// (TraceSceneOptions::ignore) use them:
//  - kFilter: an RTCIntersectContext filter rejects A's hits (scenes carry
//    RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION). One traversal, but it walks A's BVH rejecting A's
//    own hits.
//  - kMaskThenFilter: each top-level geometry carries one of 32 mask bits from its user id;
//    pass 1 traces with A's bit cleared (never entering A, nor the ~1/32 of others sharing it);
//    only if it finds nothing, pass 2 traces the geometry with that bit alone under the filter.
//    Embree tests masks of instances before entering them, of triangles only in the leaves.
//  - kAuto (default): kMaskThenFilter if the scene has at least as many instances as flattened
//    meshes, else kFilter. Measured (bench_trace, segments leaving one of 1000 dragons, 2
//    threads, CPU time): instanced dragons 1.16x and instanced box proxies 1.09-1.15x the
//    filter's speed with kMaskThenFilter; flattened box proxies 0.89-0.93x.
// Ray masks alone are not exact beyond 32 objects. Queries without an ignored id pay nothing.
//
// Invalid segments: a NaN or infinite origin or direction, a NaN tnear/tfar or an infinite
// tnear throw proxyvis::Error (Embree's answer for such rays is undefined). tfar = +inf is a
// ray; tnear > tfar is an empty segment and is never occluded.
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "mesh/tri_mesh.h"
#include "util/affine3.h"
#include "util/segment.h"

struct RTCDeviceTy;
struct RTCSceneTy;

namespace proxyvis {

// Passed as ignore_user_id when nothing is to be ignored; a geometry whose user id is kIgnoreNone
// can therefore never be ignored. kInvalidId marks "no instance" in Hit.
inline constexpr uint32_t kIgnoreNone = ~0u;
inline constexpr uint32_t kInvalidId = ~0u;

struct Hit {
  bool hit = false;
  float t = 0;
  Vec3f ng;            // geometric normal (world space, not normalized; winding as in the mesh)
  float u = 0, v = 0;  // barycentrics: p = (1-u-v)*v0 + u*v1 + v*v2
  uint32_t prim_id = 0;
  // The mesh hit: the geometry id addMesh returned for a flattened mesh, or the prototype id
  // addPrototype returned when an instance was hit.
  uint32_t geom_id = 0;
  uint32_t instance_id = kInvalidId;  // id addInstance returned, or kInvalidId for a mesh
  uint32_t user_id = 0;               // the id given to addMesh/addInstance
};

// Owns one RTCDevice and registers one error callback that turns Embree errors into messages;
// the builder turns pending messages into proxyvis::Error. Must outlive every builder and scene
// made with it (the callback writes into it).
class TraceDevice {
 public:
  TraceDevice();
  ~TraceDevice();
  TraceDevice(const TraceDevice&) = delete;
  TraceDevice& operator=(const TraceDevice&) = delete;
  RTCDeviceTy* handle() const { return device_; }

  // Messages reported by Embree since the last call ("RTC_ERROR_...: text", one per line);
  // empty if none. Thread-safe.
  std::string takeErrors();
  // Throws proxyvis::Error naming `what` if Embree reported anything since the last call.
  void throwIfError(const std::string& what);
  // Bytes Embree has allocated on this device (BVHs, geometry buffers, build scratch), now and
  // at most since construction, from its memory monitor callback.
  uint64_t bytesInUse() const;
  uint64_t peakBytes() const;

  struct ErrorLog;

 private:
  RTCDeviceTy* device_ = nullptr;
  std::unique_ptr<ErrorLog> log_;
};

enum class IgnoreStrategy { kAuto, kFilter, kMaskThenFilter };

struct TraceSceneOptions {
  // How queries with an ignore_user_id exclude that geometry (see the top of this file).
  IgnoreStrategy ignore = IgnoreStrategy::kAuto;
  // RTC_SCENE_FLAG_ROBUST: watertight triangle test and conservative traversal. The default mode
  // lets segments aimed exactly at a shared edge or vertex slip through (measured: 4 % of
  // edge-aimed, 11 % of vertex-aimed segments; robust: 0 % and 0.3 %, tests/trace/
  // watertight_test.cpp); robust tracing costs 12-19 % more (bench_trace --robust). Random
  // segments almost never come that close, so sampling code may use the default; exact checks
  // should not.
  bool robust = false;
  // RTC_BUILD_QUALITY_HIGH (spatial splits) for meshes; MEDIUM otherwise. Building a 100 k
  // triangle mesh costs tens of milliseconds either way; tracing speed measured the same within
  // noise on the dragon scenes (bench_trace --medium-quality).
  bool high_quality = true;
};

class TraceScene;

// Collects meshes and instances, then builds one committed Embree scene.
// Vertex and index data are copied into Embree-owned buffers (rtcSetNewGeometryBuffer, which pads
// vertex buffers for 16-byte loads itself), so a TriMesh may be destroyed after
// addMesh/addPrototype returns. Ids are dense and start at 0: geometry ids (addMesh) and instance
// ids (addInstance) share one numbering (top-level geometries); prototype ids their own.
// Not thread-safe: one thread builds.
class TraceSceneBuilder {
 public:
  explicit TraceSceneBuilder(TraceDevice& device, const TraceSceneOptions& options = {});
  ~TraceSceneBuilder();
  TraceSceneBuilder(const TraceSceneBuilder&) = delete;
  TraceSceneBuilder& operator=(const TraceSceneBuilder&) = delete;

  // A mesh placed directly in the top-level BVH (flattened). Returns its geometry id.
  // Throws Error (naming mesh.source) for an index out of range or a non-finite vertex.
  uint32_t addMesh(const TriMesh& mesh, uint32_t user_id = 0);
  // The mesh with its vertices mapped by `to_world`, written straight into Embree's buffer (a
  // flattened instance costs no temporary copy of the mesh).
  uint32_t addMesh(const TriMesh& mesh, const Affine3f& to_world, uint32_t user_id);
  // A mesh to be instanced; builds its BVH now. Returns a prototype id for addInstance.
  uint32_t addPrototype(const TriMesh& mesh);
  // An instance of a prototype with an affine transform. Returns the instance id (a top-level
  // geometry id, Hit::instance_id). Throws Error for an unknown prototype or a non-finite matrix.
  uint32_t addInstance(uint32_t prototype, const Affine3f& transform, uint32_t user_id = 0);

  // Builds the top-level BVH. The builder is empty afterwards and may be reused.
  std::unique_ptr<TraceScene> build();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// All queries are const and thread-safe. Results depend only on the segment, never on the thread
// or the batch it is traced in.
class TraceScene {
 public:
  ~TraceScene();

  // True if anything blocks the segment (t in [tnear, tfar]), ignoring geometry whose user id is
  // ignore_user_id.
  bool occluded(const Segment& s, uint32_t ignore_user_id = kIgnoreNone) const;
  // Batch form: out[i] = 1 if segs[i] is occluded, else 0; out.size() must equal segs.size().
  // Parallel over chunks of the batch with TBB (rtcOccluded1 per segment). If any segment is
  // invalid, throws Error naming the first invalid index (out is then unspecified).
  void occluded(std::span<const Segment> segs, std::span<uint8_t> out,
                uint32_t ignore_user_id = kIgnoreNone) const;
  // Closest hit along org + t*dir, t in [tnear, tfar].
  Hit intersect(const Segment& ray, uint32_t ignore_user_id = kIgnoreNone) const;
  // Every user id whose geometry the segment crosses in [tnear, tfar], each once with its
  // nearest crossing t, appended to `out` in no particular order. One traversal that rejects
  // every hit (a context filter), so nothing is missed behind a first hit.
  struct UserHit {
    uint32_t user_id = 0;
    float t = 0;
  };
  void hitsAlong(const Segment& s, std::vector<UserHit>& out) const;
  // Which groups of listed geometry the segment crosses in [tnear, tfar]: candidate i's user id
  // belongs to group candidates[i].group (< found.size()); found[g] becomes 1 if the segment
  // crosses geometry of a user id of group g, else 0 (as far as traced: see stop_after). Returns
  // the number of groups found. Only geometry whose ray-mask bit a candidate shares is traversed
  // (other geometry sharing the bit is traversed and its hits rejected), and the traversal stops
  // as soon as stop_after groups are found, so with a few candidates this costs a small fraction
  // of hitsAlong(). A group's crossing may be found at any of its crossings, not the nearest.
  struct Candidate {
    uint32_t user_id = 0;
    uint32_t group = 0;
  };
  size_t crossedGroups(const Segment& s, std::span<const Candidate> candidates,
                       std::span<uint8_t> found, size_t stop_after) const;

  // Box containing all geometry; for instances, the transformed corners of the prototype box.
  // Empty (Bounds3f::empty()) for an empty scene.
  Bounds3f bounds() const;
  uint64_t triangleCount() const;  // counting every instance's triangles
  uint32_t geometryCount() const;  // top-level geometries: meshes + instances
  // The strategy queries with an ignore_user_id use (kAuto resolved at build time).
  IgnoreStrategy ignoreStrategy() const;

  // Rays traced since construction or resetCounters() (occlusion and closest-hit, single and
  // batch). Counted in per-thread slots, so counting costs no shared cache line per ray; each
  // live TraceScene holds one native thread-local key for them (a process has ~1000).
  // raysTraced() may be called while other threads trace; resetCounters() must not be.
  uint64_t raysTraced() const;
  void resetCounters();

  RTCSceneTy* handle() const;

  struct Impl;

 private:
  friend class TraceSceneBuilder;
  explicit TraceScene(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace proxyvis
