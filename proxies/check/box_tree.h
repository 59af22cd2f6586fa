#pragma once
// Which of many boxes a segment crosses, without testing them all: a bounding volume hierarchy
// over the boxes (median splits, small leaves). proxy-check's scene distribution asks it for the
// instances of a mesh that a shadow segment passes (ecosys: up to 300 instances per prototype).
#include <cstdint>
#include <vector>

#include "trace/trace_scene.h"
#include "util/vec3.h"

namespace proxyvis {

// True if the segment (its [tnear, tfar] range) crosses the closed box.
bool segmentCrossesBox(const Segment& s, const Bounds3f& b);

class BoxTree {
 public:
  explicit BoxTree(std::vector<Bounds3f> boxes);

  // Appends to `out` the index of every box the segment crosses, in increasing order.
  void crossed(const Segment& s, std::vector<uint32_t>& out) const;

  size_t size() const { return boxes_.size(); }

 private:
  struct Node {
    Bounds3f box;
    uint32_t first = 0, count = 0;  // leaf: order_[first, first + count)
    uint32_t left = 0, right = 0;   // inner (count == 0): children
  };
  uint32_t build(uint32_t first, uint32_t count);

  std::vector<Bounds3f> boxes_;
  std::vector<uint32_t> order_;
  std::vector<Node> nodes_;
};

}  // namespace proxyvis
