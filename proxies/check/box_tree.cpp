#include "proxies/check/box_tree.h"

#include <algorithm>
#include <numeric>

namespace proxyvis {

namespace {
constexpr uint32_t kLeafSize = 4;
}  // namespace

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

BoxTree::BoxTree(std::vector<Bounds3f> boxes) : boxes_(std::move(boxes)) {
  order_.resize(boxes_.size());
  std::iota(order_.begin(), order_.end(), 0u);
  if (!boxes_.empty()) build(0, uint32_t(boxes_.size()));
}

uint32_t BoxTree::build(uint32_t first, uint32_t count) {
  const uint32_t index = uint32_t(nodes_.size());
  nodes_.emplace_back();
  Bounds3f box = boxes_[order_[first]];
  Bounds3f centers;
  for (uint32_t i = first; i < first + count; ++i) {
    box.extend(boxes_[order_[i]]);
    centers.extend(boxes_[order_[i]].center());
  }
  nodes_[index].box = box;
  if (count <= kLeafSize) {
    nodes_[index].first = first;
    nodes_[index].count = count;
    return index;
  }
  const Vec3f extent = centers.hi - centers.lo;
  const int axis = extent[0] >= extent[1] && extent[0] >= extent[2] ? 0
                   : extent[1] >= extent[2]                         ? 1
                                                                    : 2;
  const uint32_t half = count / 2;
  std::nth_element(
      order_.begin() + first, order_.begin() + first + half, order_.begin() + first + count,
      [&](uint32_t a, uint32_t b) { return boxes_[a].center()[axis] < boxes_[b].center()[axis]; });
  const uint32_t left = build(first, half);
  const uint32_t right = build(first + half, count - half);
  nodes_[index].left = left;
  nodes_[index].right = right;
  return index;
}

void BoxTree::crossed(const Segment& s, std::vector<uint32_t>& out) const {
  if (nodes_.empty()) return;
  const size_t start = out.size();
  uint32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& n = nodes_[stack[--top]];
    if (!segmentCrossesBox(s, n.box)) continue;
    if (n.count > 0) {
      for (uint32_t i = n.first; i < n.first + n.count; ++i)
        if (segmentCrossesBox(s, boxes_[order_[i]])) out.push_back(order_[i]);
    } else {
      stack[top++] = n.left;
      stack[top++] = n.right;
    }
  }
  std::sort(out.begin() + std::ptrdiff_t(start), out.end());
}

}  // namespace proxyvis
