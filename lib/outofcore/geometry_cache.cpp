#include "outofcore/geometry_cache.h"

#include <algorithm>

namespace proxyvis {

GeometryCache::GeometryCache(std::vector<uint64_t> expected_bytes, uint64_t budget_bytes,
                             Loader loader, std::vector<uint64_t> load_peak_bytes)
    : expected_(std::move(expected_bytes)),
      load_peak_(load_peak_bytes.empty() ? expected_ : std::move(load_peak_bytes)),
      budget_(budget_bytes),
      loader_(std::move(loader)),
      entries_(expected_.size()) {}

void GeometryCache::evictOne() {
  const uint32_t victim = lru_.back();
  lru_.pop_back();
  Entry& e = entries_[victim];
  stats_.resident_bytes -= e.bytes;
  e.scene.reset();
  e.bytes = 0;
  ++stats_.evictions;
}

const TraceScene& GeometryCache::acquire(uint32_t mesh) {
  Entry& e = entries_[mesh];
  if (e.scene) {
    ++stats_.hits;
    lru_.splice(lru_.begin(), lru_, e.lru);
    return *e.scene;
  }
  const uint64_t peak = std::max(load_peak_[mesh], expected_[mesh]);
  while (!lru_.empty() && stats_.resident_bytes + peak > budget_) evictOne();
  stats_.peak_loading_bytes = std::max(stats_.peak_loading_bytes, stats_.resident_bytes + peak);
  GeometryLoad load = loader_(mesh);
  ++stats_.loads;
  stats_.bytes_read += load.file_bytes;
  stats_.read_seconds += load.read_seconds;
  stats_.build_seconds += load.build_seconds;
  // Accounted at the scan's figure: a rebuild of the same mesh can report a little more
  // (Embree's allocator), and evicting another mesh for that would make a budget of the whole
  // in-core size thrash. The peak RSS in the report is the check on the real memory.
  load.bytes = expected_[mesh];
  e.scene = std::move(load.scene);
  e.bytes = load.bytes;
  lru_.push_front(mesh);
  e.lru = lru_.begin();
  stats_.resident_bytes += e.bytes;
  stats_.peak_resident_bytes = std::max(stats_.peak_resident_bytes, stats_.resident_bytes);
  return *e.scene;
}

}  // namespace proxyvis
