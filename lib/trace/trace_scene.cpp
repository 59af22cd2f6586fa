// Queries on a committed Embree scene: rtcOccluded1 / rtcIntersect1 per segment. Batches run
// rtcOccluded1 inside tbb::parallel_for over chunks: for incoherent shadow rays this measured as
// fast as rtcOccluded1M and 8/16-wide packets (bench_trace), and it keeps every answer a function
// of its segment alone, whatever the thread count.
#include <embree3/rtcore.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <string>

#include "trace/internal/embree_ray.h"
#include "trace/internal/trace_scene_impl.h"
#include "util/error.h"

namespace proxyvis {

using detail::toRtcRay;

namespace {

// Segments per parallel_for task: large enough that the counter update and the context set-up
// vanish, small enough to balance 2..64 threads on 10^4..10^7 rays.
constexpr size_t kChunk = 1024;

// An intersection context carrying what the filter needs; `base` must stay the first member so
// that Embree's context pointer can be cast back (standard-layout).
struct IgnoreContext {
  RTCIntersectContext base;
  const uint32_t* user_ids;
  uint32_t ignore;
  bool mask_first;
};

// Rejects candidate hits on geometry with the ignored user id. instID[0] is the top-level
// instance for a hit inside a prototype, RTC_INVALID_GEOMETRY_ID for a flattened mesh, whose
// geomID is then the top-level id.
void ignoreFilter(const RTCFilterFunctionNArguments* args) {
  const auto* ctx = reinterpret_cast<const IgnoreContext*>(args->context);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    unsigned top = RTCHitN_instID(args->hit, args->N, i, 0);
    if (top == RTC_INVALID_GEOMETRY_ID) top = RTCHitN_geomID(args->hit, args->N, i);
    if (ctx->user_ids[top] == ctx->ignore) args->valid[i] = 0;
  }
}

void initContext(IgnoreContext& ctx, const TraceScene::Impl& impl, uint32_t ignore) {
  rtcInitIntersectContext(&ctx.base);
  ctx.user_ids = impl.user_ids.data();
  ctx.ignore = ignore;
  ctx.mask_first = impl.ignore == IgnoreStrategy::kMaskThenFilter;
  if (ignore != kIgnoreNone && !ctx.mask_first) ctx.base.filter = ignoreFilter;
}

// NaN or inf in org/dir, NaN tnear/tfar or an infinite tnear: Embree's answer would be undefined.
// x - x is 0 for finite x and NaN otherwise, so one comparison covers all six coordinates.
bool isValid(const Segment& s) {
  float d = (s.org.x - s.org.x) + (s.org.y - s.org.y) + (s.org.z - s.org.z) + (s.dir.x - s.dir.x) +
            (s.dir.y - s.dir.y) + (s.dir.z - s.dir.z) + (s.tnear - s.tnear);
  return d == 0.0f && !std::isnan(s.tfar);
}

[[noreturn]] void throwInvalid(const Segment& s, const std::string& where) {
  throw Error("",
              "invalid segment" + where + ": org (" + std::to_string(s.org.x) + ", " +
                  std::to_string(s.org.y) + ", " + std::to_string(s.org.z) + "), dir (" +
                  std::to_string(s.dir.x) + ", " + std::to_string(s.dir.y) + ", " +
                  std::to_string(s.dir.z) + "), t in [" + std::to_string(s.tnear) + ", " +
                  std::to_string(s.tfar) + "]",
              "NaN or infinite values cannot be traced", "check the sampling that produced it");
}

// IgnoreStrategy::kMaskThenFilter (see trace_scene.h): every top-level geometry carries the mask
// bit b = maskBit(its user id). Pass 1 masks out the ignored id's bit: it never enters that
// geometry (nor the ~1/32 of the others that share b). Only if pass 1 finds nothing, pass 2
// traces the geometry with bit b alone, the context filter rejecting the ignored id's hits. The
// union of the two passes is every geometry except the ignored one's. With kFilter (or nothing to
// ignore) initContext has set the filter (or none) and one plain pass does it.
bool occludedOne(RTCScene scene, IgnoreContext& ctx, const Segment& s) {
  if (ctx.ignore == kIgnoreNone || !ctx.mask_first) {
    RTCRay ray = toRtcRay(s);
    rtcOccluded1(scene, &ctx.base, &ray);
    return ray.tfar < 0.0f;  // Embree sets tfar = -inf on a hit
  }
  const uint32_t bit = maskBit(ctx.ignore);
  RTCRay ray = toRtcRay(s, ~bit);
  rtcOccluded1(scene, &ctx.base, &ray);
  if (ray.tfar < 0.0f) return true;
  ray = toRtcRay(s, bit);
  ctx.base.filter = ignoreFilter;
  rtcOccluded1(scene, &ctx.base, &ray);
  ctx.base.filter = nullptr;
  return ray.tfar < 0.0f;
}

// Closest hit; with kMaskThenFilter, pass 1 as above, then pass 2 only up to pass 1's distance.
void intersectOne(RTCScene scene, IgnoreContext& ctx, const Segment& s, RTCRayHit& rh) {
  const bool two_pass = ctx.ignore != kIgnoreNone && ctx.mask_first;
  const uint32_t bit = two_pass ? maskBit(ctx.ignore) : 0u;
  rh.ray = toRtcRay(s, ~bit);
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene, &ctx.base, &rh);
  if (!two_pass) return;
  RTCRayHit second;
  second.ray = toRtcRay(s, bit);
  second.ray.tfar = rh.ray.tfar;  // the segment's tfar, or pass 1's hit distance
  second.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  second.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  ctx.base.filter = ignoreFilter;
  rtcIntersect1(scene, &ctx.base, &second);
  ctx.base.filter = nullptr;
  if (second.hit.geomID != RTC_INVALID_GEOMETRY_ID) rh = second;
}

// hitsAlong(): records every candidate hit's user id (nearest t kept) and rejects it, so that
// traversal goes on through the whole segment.
struct CollectContext {
  RTCIntersectContext base;
  const uint32_t* user_ids;
  std::vector<TraceScene::UserHit>* out;
  size_t first;  // out's entries from earlier queries are left alone
};

void collectFilter(const RTCFilterFunctionNArguments* args) {
  auto* ctx = reinterpret_cast<CollectContext*>(args->context);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    unsigned top = RTCHitN_instID(args->hit, args->N, i, 0);
    if (top == RTC_INVALID_GEOMETRY_ID) top = RTCHitN_geomID(args->hit, args->N, i);
    const uint32_t id = ctx->user_ids[top];
    const float t = RTCRayN_tfar(args->ray, args->N, i);
    bool found = false;
    for (size_t k = ctx->first; k < ctx->out->size(); ++k) {
      TraceScene::UserHit& h = (*ctx->out)[k];
      if (h.user_id == id) {
        h.t = std::min(h.t, t);
        found = true;
        break;
      }
    }
    if (!found) ctx->out->push_back({id, t});
    args->valid[i] = 0;
  }
}

// crossedGroups(): marks the group of every candidate hit and rejects the hit, until stop_after
// groups are found; then it accepts the hit, which ends the occlusion traversal.
struct GroupContext {
  RTCIntersectContext base;
  const uint32_t* user_ids;
  const TraceScene::Candidate* candidates;
  size_t num_candidates;
  uint8_t* found;
  size_t num_found, stop_after;
};

void groupFilter(const RTCFilterFunctionNArguments* args) {
  auto* ctx = reinterpret_cast<GroupContext*>(args->context);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    unsigned top = RTCHitN_instID(args->hit, args->N, i, 0);
    if (top == RTC_INVALID_GEOMETRY_ID) top = RTCHitN_geomID(args->hit, args->N, i);
    const uint32_t id = ctx->user_ids[top];
    for (size_t k = 0; k < ctx->num_candidates; ++k) {
      const TraceScene::Candidate& c = ctx->candidates[k];
      if (c.user_id != id || ctx->found[c.group]) continue;
      ctx->found[c.group] = 1;
      ++ctx->num_found;
    }
    if (ctx->num_found < ctx->stop_after) args->valid[i] = 0;
  }
}

}  // namespace

size_t TraceScene::crossedGroups(const Segment& s, std::span<const Candidate> candidates,
                                 std::span<uint8_t> found, size_t stop_after) const {
  if (!isValid(s)) throwInvalid(s, "");
  std::fill(found.begin(), found.end(), uint8_t(0));
  uint32_t mask = 0;
  for (const Candidate& c : candidates) {
    PV_CHECK_MSG(c.group < found.size(), "crossedGroups(): a group outside found");
    mask |= maskBit(c.user_id);
  }
  if (mask == 0 || stop_after == 0) return 0;
  impl_->counters.local().add(1);
  GroupContext ctx;
  rtcInitIntersectContext(&ctx.base);
  ctx.base.filter = groupFilter;
  ctx.user_ids = impl_->user_ids.data();
  ctx.candidates = candidates.data();
  ctx.num_candidates = candidates.size();
  ctx.found = found.data();
  ctx.num_found = 0;
  ctx.stop_after = stop_after;
  RTCRay ray = toRtcRay(s, mask);
  rtcOccluded1(impl_->scene, &ctx.base, &ray);
  return ctx.num_found;
}

void TraceScene::hitsAlong(const Segment& s, std::vector<UserHit>& out) const {
  if (!isValid(s)) throwInvalid(s, "");
  impl_->counters.local().add(1);
  CollectContext ctx;
  rtcInitIntersectContext(&ctx.base);
  ctx.base.filter = collectFilter;
  ctx.user_ids = impl_->user_ids.data();
  ctx.out = &out;
  ctx.first = out.size();
  RTCRay ray = toRtcRay(s);
  rtcOccluded1(impl_->scene, &ctx.base, &ray);
}

TraceScene::TraceScene(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
TraceScene::~TraceScene() = default;

bool TraceScene::occluded(const Segment& s, uint32_t ignore_user_id) const {
  if (!isValid(s)) throwInvalid(s, "");
  impl_->counters.local().add(1);
  IgnoreContext ctx;
  initContext(ctx, *impl_, ignore_user_id);
  return occludedOne(impl_->scene, ctx, s);
}

void TraceScene::occluded(std::span<const Segment> segs, std::span<uint8_t> out,
                          uint32_t ignore_user_id) const {
  PV_CHECK_MSG(segs.size() == out.size(), "occluded(): segs and out differ in size");
  // The smallest invalid index, so the error names the same segment at any thread count.
  std::atomic<size_t> first_invalid{segs.size()};
  tbb::parallel_for(tbb::blocked_range<size_t>(0, segs.size(), kChunk),
                    [&](const tbb::blocked_range<size_t>& range) {
                      IgnoreContext ctx;
                      initContext(ctx, *impl_, ignore_user_id);
                      for (size_t i = range.begin(); i != range.end(); ++i) {
                        if (!isValid(segs[i])) [[unlikely]] {
                          size_t cur = first_invalid.load();
                          while (i < cur && !first_invalid.compare_exchange_weak(cur, i)) {
                          }
                          out[i] = 0;
                          continue;
                        }
                        out[i] = occludedOne(impl_->scene, ctx, segs[i]);
                      }
                      impl_->counters.local().add(range.size());
                    });
  size_t bad = first_invalid.load();
  if (bad != segs.size()) throwInvalid(segs[bad], " " + std::to_string(bad) + " of the batch");
}

Hit TraceScene::intersect(const Segment& s, uint32_t ignore_user_id) const {
  if (!isValid(s)) throwInvalid(s, "");
  impl_->counters.local().add(1);
  IgnoreContext ctx;
  initContext(ctx, *impl_, ignore_user_id);
  RTCRayHit rh;
  intersectOne(impl_->scene, ctx, s, rh);
  Hit hit;
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return hit;
  hit.hit = true;
  hit.t = rh.ray.tfar;
  hit.u = rh.hit.u;
  hit.v = rh.hit.v;
  hit.prim_id = rh.hit.primID;
  Vec3f ng(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z);
  const uint32_t inst = rh.hit.instID[0];
  if (inst == RTC_INVALID_GEOMETRY_ID) {
    const TopGeometry& top = impl_->geometries[rh.hit.geomID];
    hit.geom_id = rh.hit.geomID;
    hit.user_id = top.user_id;
    hit.ng = ng;
  } else {
    // Embree 3 reports Ng of an instanced hit in the prototype's object space.
    const TopGeometry& top = impl_->geometries[inst];
    const auto& n = top.normal_xf;
    hit.geom_id = top.prototype;
    hit.instance_id = inst;
    hit.user_id = top.user_id;
    hit.ng = {n[0][0] * ng.x + n[0][1] * ng.y + n[0][2] * ng.z,
              n[1][0] * ng.x + n[1][1] * ng.y + n[1][2] * ng.z,
              n[2][0] * ng.x + n[2][1] * ng.y + n[2][2] * ng.z};
  }
  return hit;
}

Bounds3f TraceScene::bounds() const {
  return impl_->bounds;
}
uint64_t TraceScene::triangleCount() const {
  return impl_->triangles;
}
uint32_t TraceScene::geometryCount() const {
  return uint32_t(impl_->geometries.size());
}

IgnoreStrategy TraceScene::ignoreStrategy() const {
  return impl_->ignore;
}

uint64_t TraceScene::raysTraced() const {
  uint64_t total = 0;
  for (const RayCounter& c : impl_->counters) total += c.rays.load(std::memory_order_relaxed);
  return total;
}

void TraceScene::resetCounters() {
  for (RayCounter& c : impl_->counters) c.rays.store(0, std::memory_order_relaxed);
}

RTCSceneTy* TraceScene::handle() const {
  return impl_->scene;
}

}  // namespace proxyvis
