#pragma once
// The boundary between the renderer (lib/render) and the visibility estimators (lib/estimate).
// The renderer owns cameras, lights, shading and the Embree scenes; an estimator only decides
// which rays to trace for the light samples of one shading point and how to weight them.
// lib/estimate owns this file; keep the renderer's calls (estimate(), beginPass(), endPass(),
// probesPerPoint(), makeEstimator()) working.
//
// The renderer's side, per render:
//   auto e = makeEstimator(setup);         // setup: kind, verified proxy_class, num_regions,
//                                          // num_points, probes_per_point, q_min, fixed_costs
//   for each pass k: e->beginPass(k); parallel: e->estimate(query, rng, out, counts); e->endPass();
//   e->learnedSummary() for the report.
// The estimators (docs/design.md; math in class_probabilities.h, selection.h, roulette.h):
//   exact          original only.
//   culling        proxy pre-test where the verified class guarantees the answer; a general
//                  proxy guarantees nothing, so culling is exact there (proxy not traced).
//   paper-equal    selection, p = 1/3 each (1/2 when a verified class drops a branch).
//   paper-optimal  selection, p_i ~ sqrt(a_i) from the query's probe segments (each traced
//                  against both; RayCounts::probe), class probabilities with a Dirichlet(1/2)
//                  prior so no needed branch gets p = 0.
//   paper-cost     paper-optimal with the paper's error^(1/4) heuristic.
//   roulette       per region (tile x light): exact or proxy + roulette, decided each pass from
//                  earlier passes only (region_learner.h); no probe rays. Statistics persist
//                  across render() calls with the same estimator; make a new one to start fresh.
// Every estimate is unbiased for any statistics; every traced ray is counted.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "estimate/learned_summary.h"
#include "estimate/roulette.h"
#include "util/proxy_class.h"
#include "util/rng.h"
#include "util/segment.h"

namespace proxyvis {

enum class EstimatorKind { kExact, kCulling, kPaperEqual, kPaperOptimal, kPaperCost, kRoulette };

// "exact", "culling", "paper-equal", "paper-optimal", "paper-cost", "roulette".
const char* estimatorName(EstimatorKind kind);
// Throws proxyvis::Error for an unknown name (message lists the valid ones).
EstimatorKind parseEstimatorName(const std::string& name);
std::vector<EstimatorKind> allEstimators();
// The names of allEstimators() in that order, joined by `separator` ("," makes the default of an
// option list; ", " a sentence).
std::string allEstimatorNames(const char* separator = ",");

// Rays traced, by kind. Summed per pixel into the cost AOVs and per run into the tables.
struct RayCounts {
  uint64_t proxy = 0;     // segments traced against proxies
  uint64_t original = 0;  // segments traced against the original geometry
  uint64_t probe = 0;     // probe segments (each traced against both; counted here only)
  RayCounts& operator+=(const RayCounts& o) {
    proxy += o.proxy;
    original += o.original;
    probe += o.probe;
    return *this;
  }
  bool operator==(const RayCounts&) const = default;
};

// Traces one shadow segment. Implemented by the renderer, which applies the self-shadowing rule
// (rays leaving object A use A's original, the proxies of everything else).
class SegmentTracer {
 public:
  virtual ~SegmentTracer() = default;
  virtual bool proxyVisible(const Segment& s) const = 0;     // V'
  virtual bool originalVisible(const Segment& s) const = 0;  // V
};

// The light samples of one shading point.
struct ShadingPointQuery {
  std::span<const Segment> segments;  // one per light sample; estimate one visibility per segment
  const SegmentTracer* tracer = nullptr;
  uint32_t region = 0;  // learning region (screen tile x light), < EstimatorSetup::num_regions
  // Extra light-sample segments for the probe-based estimators (paper-optimal, paper-cost);
  // drawn independently of `segments` from the same distribution.
  std::span<const Segment> probes;
  // Optional: index of this (shading point, light) pair, < EstimatorSetup::num_points, e.g.
  // pixel * num_lights + light; each point at most once per pass. Roulette keeps a running mean
  // per point across passes to learn the variance exact visibility leaves per pixel,
  // mean_p V_p(1 - V_p), which its exact-vs-proxy decision needs. Without it, roulette uses pairs
  // of segments of one query (needs >= 2 segments per query), else the pooled V(1 - V) of the
  // region (an overestimate that favours the proxy).
  uint32_t point = kNoPoint;
  static constexpr uint32_t kNoPoint = ~0u;
};

struct EstimatorSetup {
  EstimatorKind kind = EstimatorKind::kExact;
  // Verified class of the scene's proxies; only a verified class lets an estimator drop a
  // correction branch (docs/design.md, pitfall 4).
  ProxyClass proxy_class = ProxyClass::kGeneral;
  uint32_t num_regions = 1;
  int probes_per_point = 16;  // paper-optimal / paper-cost
  double q_min = 0.05;        // roulette floor where an error class is possible
  uint32_t num_points = 0;    // roulette: size of the ShadingPointQuery::point range (0 = none)
  // Roulette cost model. Unset: ray costs per class of V' are measured per region with the CPU
  // tick counter on 1 ray in 8 (reported in ns, calibrated against steady_clock per pass), which
  // makes roulette's choices (never its expectation) depend on timing, so output is unbiased but
  // not bit-reproducible. Set (any unit, e.g. ns from a bench): deterministic output at any thread
  // count.
  std::optional<ClassCosts> fixed_costs;
};

class VisibilityEstimator {
 public:
  virtual ~VisibilityEstimator() = default;
  // Single-threaded, before pass `pass` (one pass = every pixel's light samples once). Roulette
  // freezes the statistics learned in passes < pass here, which keeps it unbiased.
  virtual void beginPass(int pass) { (void)pass; }
  // Thread-safe. Writes one unbiased visibility estimate per segment into out (same size).
  virtual void estimate(const ShadingPointQuery& query, Rng& rng, std::span<double> out,
                        RayCounts& counts) = 0;
  // Single-threaded, after the pass: merge per-thread statistics.
  virtual void endPass() {}
  // How many probe segments estimate() wants per shading point (0 for most).
  virtual int probesPerPoint() const { return 0; }
  // Statistics learned so far (roulette); call between passes.
  virtual LearnedSummary learnedSummary() const { return {}; }
  // Between passes (optional): what every light sample costs outside visibility (light sampling,
  // shading, the primary ray's share), in ns, or in fixed_costs' unit when those are set. Roulette
  // weighs its added variance against the whole sample's cost (ClassCosts::per_sample); without
  // it, it optimises shadow-ray time alone and overrates the proxy when shading is costly.
  virtual void setPerSampleCost(double cost) { (void)cost; }
};

std::unique_ptr<VisibilityEstimator> makeEstimator(const EstimatorSetup& setup);

}  // namespace proxyvis
