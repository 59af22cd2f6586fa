#include "proxies/check/ray_classify.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <numbers>

#include "util/progress.h"
#include "util/rng.h"
#include "util/stopwatch.h"

namespace proxyvis {

namespace {

Vec3f uniformOnSphere(Rng& rng) {
  const float z = 1.0f - 2.0f * rng.uniformFloat();
  const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
  const float phi = 2.0f * std::numbers::pi_v<float> * rng.uniformFloat();
  return {r * std::cos(phi), r * std::sin(phi), z};
}

}  // namespace

Segment sphereSegment(const Vec3f& center, float radius, uint64_t seed, uint64_t index) {
  Rng rng(seed, index);
  const Vec3f a = center + radius * uniformOnSphere(rng);
  const Vec3f b = center + radius * uniformOnSphere(rng);
  return Segment::between(a, b);
}

Sphere enclosingSphere(const Bounds3f& a, const Bounds3f& b) {
  Bounds3f u = a;
  u.extend(b);
  return {u.center(), 0.5f * u.diagonal() * 1.05f};
}

SegmentGenerator sphereSegments(const Sphere& sphere, uint64_t seed) {
  return [sphere, seed](uint64_t index, Segment& out) {
    out = sphereSegment(sphere.center, sphere.radius, seed, index);
    return true;
  };
}

Classification classifySegments(const TraceScene& original, const TraceScene& proxy,
                                const SegmentGenerator& generator, const ClassifyOptions& options) {
  const Stopwatch whole;
  Classification result;
  Progress progress("Classifying segments", options.segments, options.quiet);
  const size_t batch = std::max<size_t>(1, options.batch);
  std::vector<Segment> segs(batch);
  std::vector<uint8_t> valid(batch), hit_o(batch), hit_p(batch);
  const uint64_t cap = std::max(options.max_attempts, options.segments);
  uint64_t classified = 0;
  for (uint64_t first = 0; classified < options.segments && first < cap; first += batch) {
    const size_t n = size_t(std::min<uint64_t>(batch, cap - first));
    tbb::parallel_for(size_t(0), n, [&](size_t i) {
      valid[i] = generator(first + i, segs[i]) ? 1 : 0;
      if (!valid[i]) segs[i] = Segment{{}, 0, {1, 0, 0}, -1};  // empty range: never occluded
    });
    const std::span<const Segment> in(segs.data(), n);
    Stopwatch trace;
    proxy.occluded(in, std::span<uint8_t>(hit_p.data(), n));
    result.seconds_proxy += trace.seconds();
    trace.restart();
    original.occluded(in, std::span<uint8_t>(hit_o.data(), n));
    result.seconds_original += trace.seconds();
    ClassCounts c;
    const uint64_t before = classified;
    // In index order, so the segments counted are the same at any batch size or thread count.
    for (size_t i = 0; i < n && classified < options.segments; ++i) {
      ++result.attempts;
      if (!valid[i]) {
        ++result.skipped;
        continue;
      }
      ++classified;
      const bool o = hit_o[i], p = hit_p[i];
      if (o && p)
        ++c.hh;
      else if (o)
        ++c.hm;
      else if (p)
        ++c.mh;
      else
        ++c.mm;
      if (o != p && result.errors.size() < options.max_error_segments)
        result.errors.push_back({segs[i].org + segs[i].tnear * segs[i].dir,
                                 segs[i].org + segs[i].tfar * segs[i].dir, o});
    }
    result.counts += c;
    progress.update(classified - before);
  }
  progress.done();
  result.seconds = whole.seconds();
  return result;
}

}  // namespace proxyvis
