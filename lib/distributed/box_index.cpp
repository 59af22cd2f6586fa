#include "distributed/box_index.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>

#include "util/error.h"

namespace proxyvis {

namespace {

struct BoxContext {
  RTCIntersectContext base;  // first member: Embree's context pointer is cast back
  const LabelledBox* boxes;
  std::vector<LabelEntry>* out;              // labelsAlong(): one entry per label
  std::vector<BoxIndex::BoxEntry>* per_box;  // boxesAlong(): one entry per box (out unused)
  size_t first;
};

void boxBounds(const RTCBoundsFunctionArguments* args) {
  const auto* boxes = static_cast<const LabelledBox*>(args->geometryUserPtr);
  const Bounds3f& b = boxes[args->primID].box;
  args->bounds_o->lower_x = b.lo.x;
  args->bounds_o->lower_y = b.lo.y;
  args->bounds_o->lower_z = b.lo.z;
  args->bounds_o->upper_x = b.hi.x;
  args->bounds_o->upper_y = b.hi.y;
  args->bounds_o->upper_z = b.hi.z;
}

// Slab test of the segment against the box; records the entry t and never reports a hit, so
// that traversal visits every box the segment meets.
void boxOccluded(const RTCOccludedFunctionNArguments* args) {
  if (args->N != 1 || !args->valid[0]) return;
  auto* ctx = reinterpret_cast<BoxContext*>(args->context);
  const LabelledBox& lb = ctx->boxes[args->primID];
  RTCRay* ray = reinterpret_cast<RTCRay*>(args->ray);
  const float org[3] = {ray->org_x, ray->org_y, ray->org_z};
  const float dir[3] = {ray->dir_x, ray->dir_y, ray->dir_z};
  float t0 = ray->tnear, t1 = ray->tfar;
  for (int a = 0; a < 3; ++a) {
    const float lo = lb.box.lo[a], hi = lb.box.hi[a];
    if (dir[a] == 0.0f) {
      if (org[a] < lo || org[a] > hi) return;
      continue;
    }
    const float inv = 1.0f / dir[a];
    float ta = (lo - org[a]) * inv, tb = (hi - org[a]) * inv;
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return;
  }
  if (ctx->per_box) {
    ctx->per_box->push_back({lb.id, lb.label, t0});
    return;
  }
  std::vector<LabelEntry>& out = *ctx->out;
  for (size_t k = ctx->first; k < out.size(); ++k)
    if (out[k].label == lb.label) {
      out[k].t = std::min(out[k].t, t0);
      return;
    }
  out.push_back({lb.label, t0});
}

void boxIntersect(const RTCIntersectFunctionNArguments*) {}

// Every box the segment meets gets the callback; none reports a hit.
void traceBoxes(RTCScene scene, const Segment& s, RTCIntersectContext& ctx) {
  RTCRay ray;
  ray.org_x = s.org.x, ray.org_y = s.org.y, ray.org_z = s.org.z;
  ray.dir_x = s.dir.x, ray.dir_y = s.dir.y, ray.dir_z = s.dir.z;
  ray.tnear = s.tnear, ray.tfar = s.tfar;
  ray.time = 0, ray.mask = ~0u, ray.id = 0, ray.flags = 0;
  rtcOccluded1(scene, &ctx, &ray);
}

}  // namespace

BoxIndex::BoxIndex(TraceDevice& device, std::vector<LabelledBox> boxes, float pad)
    : boxes_(std::move(boxes)) {
  for (LabelledBox& b : boxes_) {
    b.box.lo = b.box.lo - Vec3f(pad, pad, pad);
    b.box.hi = b.box.hi + Vec3f(pad, pad, pad);
  }
  scene_ = rtcNewScene(device.handle());
  if (!boxes_.empty()) {
    RTCGeometry geom = rtcNewGeometry(device.handle(), RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geom, unsigned(boxes_.size()));
    rtcSetGeometryUserData(geom, boxes_.data());
    rtcSetGeometryBoundsFunction(geom, boxBounds, boxes_.data());
    rtcSetGeometryIntersectFunction(geom, boxIntersect);
    rtcSetGeometryOccludedFunction(geom, boxOccluded);
    rtcCommitGeometry(geom);
    rtcAttachGeometry(scene_, geom);
    rtcReleaseGeometry(geom);
  }
  rtcCommitScene(scene_);
  device.throwIfError("box index");
}

BoxIndex::~BoxIndex() {
  if (scene_) rtcReleaseScene(scene_);
}

void BoxIndex::labelsAlong(const Segment& s, std::vector<LabelEntry>& out) const {
  BoxContext ctx;
  rtcInitIntersectContext(&ctx.base);
  ctx.boxes = boxes_.data();
  ctx.out = &out;
  ctx.per_box = nullptr;
  ctx.first = out.size();
  traceBoxes(scene_, s, ctx.base);
}

void BoxIndex::boxesAlong(const Segment& s, std::vector<BoxEntry>& out) const {
  BoxContext ctx;
  rtcInitIntersectContext(&ctx.base);
  ctx.boxes = boxes_.data();
  ctx.out = nullptr;
  ctx.per_box = &out;
  ctx.first = 0;
  traceBoxes(scene_, s, ctx.base);
}

}  // namespace proxyvis
