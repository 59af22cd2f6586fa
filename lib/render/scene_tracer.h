#pragma once
// The renderer's SegmentTracer: V and V' for shadow segments leaving one object, with the
// self-shadowing rule of docs/design.md, pitfall 1. A shading point on object A lies on (or inside)
// A's outside proxy, so its segments would always "hit" it. Instead V' for A's segments is
//     V' = [segment misses every other object's proxy]  and  [segment misses A's original],
// traced as proxies() ignoring A's user id, then A's original in object space. V stays the
// segment against all originals. The classes keep their guarantees: with outside proxies, V' = 1
// still implies V = 1; with inside proxies, V' = 0 still implies V = 0.
#include "estimate/visibility_estimator.h"
#include "render/render_scene.h"
#include "scene/transform.h"

namespace proxyvis {

class SceneTracer final : public SegmentTracer {
 public:
  // `object`: the object the shading point lies on (Hit::user_id of the primary hit).
  SceneTracer(const RenderScene& scene, uint32_t object)
      : originals_(scene.originals()), proxies_(scene.proxies()) {
    const RenderObject& o = scene.objects()[object];
    self_ = o.proxy >= 0 ? scene.selfScene(o.mesh) : nullptr;
    ignore_ = self_ ? object : kIgnoreNone;
    to_object_ = o.to_object;
  }

  bool proxyVisible(const Segment& s) const override {
    if (proxies_.occluded(s, ignore_)) return false;
    if (!self_) return true;
    Segment local = s;
    local.org = to_object_.apply(s.org);
    local.dir = applyLinear(to_object_, s.dir);  // same t range: the map is affine
    return !self_->occluded(local);
  }
  bool originalVisible(const Segment& s) const override { return !originals_.occluded(s); }

 private:
  const TraceScene& originals_;
  const TraceScene& proxies_;
  const TraceScene* self_ = nullptr;
  uint32_t ignore_ = kIgnoreNone;
  Affine3f to_object_;
};

}  // namespace proxyvis
