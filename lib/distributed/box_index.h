#pragma once
// Labelled axis-aligned boxes in an Embree BVH (user geometry: the slab test runs in the
// callback, so a segment that starts or ends inside a box counts as entering it). Answers "which
// labels' boxes does this segment enter, and where first": the forwarding baselines of the
// data-parallel renderer (one box per rank's domain, or one per object).
#include <memory>
#include <vector>

#include "trace/trace_scene.h"
#include "util/segment.h"

namespace proxyvis {

struct LabelledBox {
  Bounds3f box;
  uint32_t label = 0;
  uint32_t id = 0;  // the caller's name for the box (an object id), reported by boxesAlong()
};

// A label with the smallest t at which the segment is inside one of its boxes.
struct LabelEntry {
  uint32_t label = 0;
  float t = 0;
};

class BoxIndex {
 public:
  // Every box is grown by `pad` (world units) on each side, so that a triangle lying on a face
  // of its box is inside it despite float rounding.
  BoxIndex(TraceDevice& device, std::vector<LabelledBox> boxes, float pad);
  ~BoxIndex();
  BoxIndex(const BoxIndex&) = delete;
  BoxIndex& operator=(const BoxIndex&) = delete;

  // Appends one entry per label whose boxes the segment meets in [tnear, tfar] (entries appended
  // before the call are left alone). Thread-safe.
  void labelsAlong(const Segment& s, std::vector<LabelEntry>& out) const;
  // Appends one entry per box the segment meets in [tnear, tfar], with the t at which it is
  // first inside it, in no particular order. Thread-safe.
  struct BoxEntry {
    uint32_t id = 0, label = 0;
    float t = 0;
  };
  void boxesAlong(const Segment& s, std::vector<BoxEntry>& out) const;
  size_t size() const { return boxes_.size(); }

 private:
  std::vector<LabelledBox> boxes_;
  RTCSceneTy* scene_ = nullptr;
};

}  // namespace proxyvis
