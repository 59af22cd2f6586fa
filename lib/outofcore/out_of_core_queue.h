#pragma once
// The out-of-core renderer's queues (out_of_core_render.h): a batch's segment flags, the (mesh,
// sample) pairs gathered per thread and per mesh, the order meshes are visited in, and which
// meshes a shadow segment must be traced against under each policy.
#include <tbb/enumerable_thread_specific.h>

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "outofcore/geometry_cache.h"
#include "outofcore/out_of_core_render.h"
#include "outofcore/out_of_core_scene.h"
#include "util/segment.h"

namespace proxyvis {

// A segment's flags in a batch: blocked (by its own mesh, an inside proxy, an original or the
// roulette's skip), and "the proxies' answer was wrong" for the mesh being traced.
constexpr uint8_t kBlocked = 1, kWrong = 2;
// What a queued (segment, mesh) pair may take while the batch is gathered: its item index in a
// thread's list of that mesh, and the list's room to grow (a vector at most doubles).
constexpr uint64_t kPairBytes = 2 * sizeof(uint32_t);

// (mesh, item) pairs gathered in parallel into per-thread lists per mesh; a mesh's queue is
// taken, in item order, when the mesh is visited, and the threads' lists of it are freed then.
// The order only matters for the trace's memory access and the order of the queue's sums,
// never for an answer.
class QueueBuilder {
 public:
  explicit QueueBuilder(size_t meshes)
      : lists_([meshes] { return std::vector<std::vector<uint32_t>>(meshes); }), meshes_(meshes) {}
  void add(uint32_t mesh, uint32_t item) { lists_.local()[mesh].push_back(item); }
  // Pairs per mesh, and `total` their sum.
  std::vector<uint64_t> counts(uint64_t& total) const {
    std::vector<uint64_t> n(meshes_, 0);
    total = 0;
    for (const auto& local : lists_)
      for (size_t m = 0; m < meshes_; ++m) n[m] += local[m].size(), total += local[m].size();
    return n;
  }
  // Bytes the lists hold now (their capacity).
  uint64_t bytes() const {
    uint64_t b = 0;
    for (const auto& local : lists_)
      for (const auto& l : local) b += l.capacity() * sizeof(uint32_t);
    return b;
  }
  // Every queued item once, in order.
  std::vector<uint32_t> items() const {
    std::vector<uint32_t> all;
    for (const auto& local : lists_)
      for (const auto& l : local) all.insert(all.end(), l.begin(), l.end());
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end()), all.end());
    return all;
  }
  // Mesh m's queue in item order.
  std::vector<uint32_t> take(uint32_t m) {
    size_t n = 0;
    for (const auto& local : lists_) n += local[m].size();
    std::vector<uint32_t> queue;
    queue.reserve(n);
    for (auto& local : lists_) {
      queue.insert(queue.end(), local[m].begin(), local[m].end());
      std::vector<uint32_t>().swap(local[m]);
    }
    std::sort(queue.begin(), queue.end());
    return queue;
  }

 private:
  tbb::enumerable_thread_specific<std::vector<std::vector<uint32_t>>> lists_;
  size_t meshes_;
};

// The meshes with a queue, the resident ones first (no load), then by index.
std::vector<uint32_t> visitOrder(const std::vector<uint64_t>& counts, const GeometryCache& cache);

// Queues segment `item` (from a point on a mesh `own_mesh` object) on the other meshes it must
// be traced against under `policy`; none when the boxes or proxies decide it (`flags` is then
// marked blocked if an inside proxy blocks it). The own mesh was traced in the primary pass
// (ownMeshShadows). Returns the pairs queued.
uint32_t queueSegment(const OutOfCoreScene& scene, OutOfCorePolicy policy, const Segment& s,
                      uint32_t own_mesh, uint32_t item, QueueBuilder& builder, uint8_t& flags);

// proxies-roulette: the product of the factors 1/q of each sample a batch queued (a float:
// exact for q = 1/2^k, otherwise within float rounding of the product). A sample never queued
// has no slot: its factor is 1.
class RouletteFactors {
 public:
  void clear() { items_.clear(), factors_.clear(); }
  // Slots for `items` (sorted, each once), every factor 1.
  void reset(std::vector<uint32_t> items) {
    items_ = std::move(items);
    factors_.assign(items_.size(), 1.0f);
  }
  float of(uint32_t item) const {
    const auto it = std::lower_bound(items_.begin(), items_.end(), item);
    return it != items_.end() && *it == item ? factors_[size_t(it - items_.begin())] : 1.0f;
  }
  float& slot(uint32_t item) {  // a queued sample's
    return factors_[size_t(std::lower_bound(items_.begin(), items_.end(), item) - items_.begin())];
  }
  uint64_t bytes() const {
    return items_.capacity() * sizeof(uint32_t) + factors_.capacity() * sizeof(float);
  }

 private:
  std::vector<uint32_t> items_;
  std::vector<float> factors_;
};

}  // namespace proxyvis
