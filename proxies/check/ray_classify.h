#pragma once
// Ray-sampled classification of a proxy: N shadow-like segments, each traced (occlusion only)
// against the original and against the proxy with Embree, counted into HH', HM', MH', MM'.
// Segment i depends only on (seed, i), and counting is order-independent, so the counts are the
// same at any thread count.
#include <cstdint>
#include <functional>
#include <vector>

#include "proxies/check/class_stats.h"
#include "trace/trace_scene.h"

namespace proxyvis {

// Produces segment `index` into `out`; returns false when that index yields no segment (e.g. a
// camera ray that hits nothing), which is then skipped. Must be thread-safe and deterministic.
using SegmentGenerator = std::function<bool(uint64_t index, Segment& out)>;

// Both ends independent and uniform on the sphere (center, radius). If the sphere encloses both
// meshes, both ends lie outside both, as the outside/inside guarantees require (docs/design.md
// pitfall 2). Segment `index` uses Rng(seed, index).
Segment sphereSegment(const Vec3f& center, float radius, uint64_t seed, uint64_t index);

// The sphere around both boxes: center of their union, radius 1.05 x half its diagonal (strictly
// outside every vertex).
struct Sphere {
  Vec3f center;
  float radius = 0;
};
Sphere enclosingSphere(const Bounds3f& a, const Bounds3f& b);
SegmentGenerator sphereSegments(const Sphere& sphere, uint64_t seed);

// A segment of an error class, kept for --dump-errors.
struct ErrorSegment {
  Vec3f a, b;
  bool hm = false;  // true: HM' (original blocks, proxy misses); false: MH'
};

struct ClassifyOptions {
  // Segments to classify: indices 0, 1, ... are drawn until this many gave a segment (the
  // lowest such indices count), or until max_attempts indices were drawn.
  uint64_t segments = 1'000'000;
  uint64_t max_attempts = 0;        // 0 or less than segments: segments (every index gives one)
  uint32_t batch = 1u << 16;        // segments generated and traced per batch
  uint64_t max_error_segments = 0;  // how many error segments to keep (lowest indices first)
  bool quiet = false;               // no progress bar
};

struct Classification {
  ClassCounts counts;
  uint64_t attempts = 0;  // indices drawn (the last one counted is attempts - 1)
  uint64_t skipped = 0;   // of those, the indices for which the generator gave no segment
  double seconds = 0;     // wall time of everything, generation included
  double seconds_original = 0, seconds_proxy = 0;  // batch tracing time against each
  std::vector<ErrorSegment> errors;                // by increasing index
  // c_p / c_o: time per segment against the proxy over the original (0 if not measured).
  double costRatio() const { return seconds_original > 0 ? seconds_proxy / seconds_original : 0; }
};

Classification classifySegments(const TraceScene& original, const TraceScene& proxy,
                                const SegmentGenerator& generator, const ClassifyOptions& options);

}  // namespace proxyvis
