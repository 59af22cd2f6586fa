#pragma once
// The out-of-core renderer's cache of built originals: one entry per mesh (the Embree scene of
// every object of that mesh), loaded on demand from its file and evicted least recently used
// once the entries would exceed the budget. Bytes are what Embree reports for the built scene
// (its memory monitor), measured when the entry is built. Not thread-safe: the renderer acquires
// one mesh at a time and traces its queue in parallel.
#include <cstdint>
#include <functional>
#include <list>
#include <memory>
#include <vector>

#include "trace/trace_scene.h"

namespace proxyvis {

// What loading one mesh gives: its built scene and what it cost.
struct GeometryLoad {
  std::unique_ptr<TraceScene> scene;
  uint64_t bytes = 0;        // the built scene's bytes (Embree's memory monitor)
  uint64_t file_bytes = 0;   // bytes read from disk (the file's size)
  double read_seconds = 0;   // reading and decoding the file (Draco, OBJ, PLY, ...)
  double build_seconds = 0;  // building the BVH
};

struct GeometryCacheStats {
  uint64_t loads = 0;  // misses: files read, decoded and built
  uint64_t hits = 0;   // acquisitions of a resident entry
  uint64_t evictions = 0;
  uint64_t bytes_read = 0;  // file bytes of every load
  double read_seconds = 0, build_seconds = 0;
  uint64_t resident_bytes = 0, peak_resident_bytes = 0;
  // The resident entries plus the load in progress, at most (the budget holds this).
  uint64_t peak_loading_bytes = 0;
  double loadSeconds() const { return read_seconds + build_seconds; }
};

class GeometryCache {
 public:
  using Loader = std::function<GeometryLoad(uint32_t mesh)>;
  // `expected_bytes[m]`: mesh m's built bytes as measured when the scene was scanned (what its
  // entry holds once resident); `load_peak_bytes[m]`: what loading it takes at its peak (its
  // decoded triangles and build scratch beside the scene being built; empty: the built bytes).
  // Before a load, entries are evicted until the resident ones plus the load's peak fit the
  // budget, so the resident bytes and a load in progress together never exceed it.
  // `budget_bytes`: what the entries (and a load) may hold together.
  GeometryCache(std::vector<uint64_t> expected_bytes, uint64_t budget_bytes, Loader loader,
                std::vector<uint64_t> load_peak_bytes = {});

  // The scene of `mesh`, loaded on a miss after evicting least recently used entries until its
  // load fits (a load larger than the whole budget is made alone). Valid until the next call.
  const TraceScene& acquire(uint32_t mesh);
  bool resident(uint32_t mesh) const { return entries_[mesh].scene != nullptr; }
  uint64_t budgetBytes() const { return budget_; }
  const GeometryCacheStats& stats() const { return stats_; }

 private:
  struct Entry {
    std::unique_ptr<TraceScene> scene;
    uint64_t bytes = 0;
    std::list<uint32_t>::iterator lru;  // position in lru_ while resident
  };
  void evictOne();

  std::vector<uint64_t> expected_, load_peak_;
  uint64_t budget_;
  Loader loader_;
  std::vector<Entry> entries_;
  std::list<uint32_t> lru_;  // most recently used first
  GeometryCacheStats stats_;
};

}  // namespace proxyvis
