#pragma once
// State shared by TraceSceneBuilder (which fills it) and TraceScene (which queries it).
#include <embree3/rtcore.h>
#include <tbb/enumerable_thread_specific.h>

#include <atomic>
#include <cstdint>
#include <vector>

#include "trace/trace_scene.h"

namespace proxyvis {

// One rays-traced counter per thread, on its own cache line. Only its thread writes it (a relaxed
// load + store, no locked read-modify-write); raysTraced() reads all of them.
struct alignas(64) RayCounter {
  std::atomic<uint64_t> rays{0};
  void add(uint64_t n) {
    rays.store(rays.load(std::memory_order_relaxed) + n, std::memory_order_relaxed);
  }
};

// The ray-mask bit of a user id (Fibonacci hashing, top 5 bits), so that ids 0, 1, 2, ... and
// ids in steps of 32 both spread over the 32 bits. Every top-level geometry's mask is the bit of
// its user id; see trace_scene.cpp for how ignoring uses it.
inline uint32_t maskBit(uint32_t user_id) {
  return 1u << ((user_id * 0x9E3779B1u) >> 27);
}

// Per top-level geometry (a flattened mesh or an instance), indexed by Embree's geometry id.
struct TopGeometry {
  uint32_t user_id = 0;
  uint32_t prototype = kInvalidId;  // kInvalidId for a flattened mesh
  float normal_xf[3][3] = {
      {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};  // cofactor of the instance's linear part
};

struct TraceScene::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::vector<RTCScene> prototypes;
  std::vector<TopGeometry> geometries;
  // user ids alone, contiguous, for the filter function's lookup
  std::vector<uint32_t> user_ids;
  Bounds3f bounds;
  uint64_t triangles = 0;
  IgnoreStrategy ignore = IgnoreStrategy::kFilter;
  // ets_key_per_instance: local() is a native TLS lookup, not a hash of the thread id.
  mutable tbb::enumerable_thread_specific<RayCounter, tbb::cache_aligned_allocator<RayCounter>,
                                          tbb::ets_key_per_instance>
      counters;

  ~Impl() {
    for (RTCScene s : prototypes) rtcReleaseScene(s);
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }
};

}  // namespace proxyvis
