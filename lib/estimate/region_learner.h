#pragma once
// Per-region learning for the roulette estimator (docs/design.md "Statistics without probe rays",
// §2b "decide per region"). A region is a screen tile x light (x whether the shading point's
// object has a proxy, in the renderer). Each pass, every region runs in one of two modes, frozen
// in beginPass() from the statistics of earlier passes only (so the choice is independent of the
// pass's own random numbers and every estimate stays unbiased):
//
//  exact     trace the original for every segment (no added variance). To keep learning, also
//            trace the proxy first for a fraction `explore` of the points (kWarmupExploreRate
//            until the region has kMinSamples observations, then at most kExploreRate, thinning
//            as the statistics grow and capped at kExploreBudget of exact's cost): each such
//            segment reveals its class (V, V') and the cost of both rays. The other queries take
//            the exact estimator's path (Plan::quiet), so exact mode costs explore * c_p more.
//  roulette  always trace the proxy, correct with q_i (roulette.h). P(V'=i) comes from every proxy
//            ray; P(error | V'=i) from the corrections actually traced, each weighted by 1/q_i of
//            its pass (Horvitz-Thompson), so the rate estimate is unbiased whatever q was used.
//
// The decision (decideRegion) compares the predicted efficiency 1/(Var x Cost) of the optimal
// roulette with exact and uses roulette only when it wins by `margin`, and, with measured costs,
// only if the measured times of both modes in the same passes agree (see kAltQueries); so a
// region loses to exact at most its exploration cost plus estimation error. Error rates are
// smoothed with half a pseudo-error (Jeffreys-like), so a region that never showed an error is not
// assumed perfect.
//
// The variance exact visibility leaves per pixel, mean_p V_p(1-V_p), is learned as
// E[V~] - E[V~_prev * V~], where V~_prev is the mean of the same point's estimates in earlier
// passes (independent of the current one, so the product has expectation V_p^2), kept for one
// point in four (the history is the learner's largest per-query cost), or from pairs of
// segments of one query. Every counter a pass adds is an integer (estimates in fixed point, kept
// per thread and summed at the end of the pass), so the statistics, and with fixed costs the
// output, do not depend on the thread count or the order queries arrive in.
#include <tbb/enumerable_thread_specific.h>

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "estimate/roulette.h"
#include "estimate/visibility_estimator.h"
#include "util/rng.h"

namespace proxyvis {

struct RegionDecision {
  bool roulette = false;
  RouletteQ q;                      // used when roulette
  double predicted_efficiency = 0;  // optimal roulette vs exact (rouletteEfficiencyVsExact)
};

// The choice for one region given its model: roulette with optimalRouletteQ if it is predicted
// to be at least (1 + margin) times as efficient as exact, else exact.
RegionDecision decideRegion(const RouletteModel& m, ProxyClass cls, double q_min, double margin);

// What a thread observed in one region during the current pass (integers only).
struct RegionTally {
  uint64_t n[2] = {0, 0};             // proxy rays with V' = i
  uint64_t traced[2] = {0, 0};        // originals traced after V' = i
  uint64_t err[2] = {0, 0};           // of those, V != V' (any mode)
  uint64_t err_roulette[2] = {0, 0};  // of err, found by roulette corrections (traced with q_i)
  uint64_t cost_n_p[2] = {0, 0}, cost_n_o[2] = {0, 0};  // timed rays by class of V'
  uint64_t ticks_p[2] = {0, 0}, ticks_o[2] = {0, 0};
  uint64_t mode_n[2] = {0, 0}, mode_ticks[2] = {0, 0};  // timed queries by mode: segments, ticks
  int64_t v_sum = 0, v_cross = 0;                       // fixed point (kFixedOne)
  uint64_t v_n = 0;
  uint64_t samples = 0;  // every segment estimated, whatever the mode
  void add(const RegionTally& o);
};

class RegionLearner {
 public:
  static constexpr int kMinSamples = 64;  // observations before leaving exact
  // Warm-up (fewer than kMinSamples observations, or with measured costs fewer than 2 passes):
  // one point in eight explores, which gives a 16 x 16 tile its kMinSamples observations in the
  // two passes measured costs need anyway. Every point exploring made the warm-up passes cost two
  // rays per segment, a loss of several percent at a few dozen samples per pixel.
  static constexpr double kWarmupExploreRate = 1.0 / 8;
  // After the warm-up, an exact region explores at most kExploreRate of its points, thinning as
  // kExploreRate * sqrt(kExploreSamples / samples) and capped so that the extra proxy rays cost
  // at most kExploreBudget of exact; one whose roulette is predicted below kSettledEfficiency of
  // exact (the proxy does not pay: points on an object with a proxy, which trace their own
  // original either way) explores at kSettledExploreRate only.
  static constexpr double kExploreRate = 1.0 / 32;
  static constexpr double kExploreSamples = 4096;
  static constexpr double kSettledEfficiency = 1.0;
  static constexpr double kSettledExploreRate = 1.0 / 1024;
  static constexpr double kExploreBudget = 0.005;
  // Points explore in the same set for kExploreEpochPasses passes (exploresPoint's salt changes
  // per epoch of that many passes): an explored point then has estimates of earlier passes, which
  // the variance of exact visibility needs (see addEstimates).
  static constexpr uint32_t kExploreEpochPasses = 8;
  static constexpr uint32_t kWeylMultiplier = 0x9e3779b9u;  // 2^32 / golden ratio, odd
  // Samples are counted in one pass in kSampleCountPasses (see countsSamples()); a region's pixels
  // are the same every pass, so this loses nothing but the counter's cost.
  static constexpr uint32_t kSampleCountPasses = 8;
  static constexpr int64_t kFixedOne = int64_t(1) << 20;
  // In roulette and trial regions the variance history is kept for one point in kVarianceStride
  // (the history update is the learner's largest per-query cost); quiet exact regions keep it for
  // their explored points only.
  static constexpr uint32_t kVarianceStride = 4;
  // Measured mode costs (measured-cost mode only). The per-ray costs predict what roulette would
  // cost, but a ray timed alone among rays of the other scene runs on caches that scene warmed,
  // and the machine's load changes: the decision that counts compares the time per segment of
  // whole queries in each mode, in the same region and the same passes. A region the model calls
  // a candidate (or that uses roulette) runs one query in kAltQueries in the other mode
  // (Plan::trial), interleaved with its own, and both are timed; the comparison needs
  // kMinModeSegments timed segments of each, weights decaying by kModeDecay per pass.
  static constexpr double kMinModeSegments = 256;
  static constexpr double kModeDecay = 0.98;
  static constexpr uint32_t kAltQueries = 16;

  struct Options {
    ProxyClass proxy_class = ProxyClass::kGeneral;
    double q_min = 0.05;
    double margin = 0.25;  // measured costs are noisy: a small predicted gain is often none
    std::optional<ClassCosts> fixed_costs;
  };
  RegionLearner(uint32_t num_regions, uint32_t num_points, const Options& options);

  struct Plan {
    bool roulette = false;
    RouletteQ q;  // roulette mode
    // Exact mode: fraction of points whose queries also trace the proxy (< 1), and the same as a
    // threshold of exploresPoint's 32-bit sequence (explore * 2^32).
    double explore = kWarmupExploreRate;
    uint32_t explore_below = uint32_t(kWarmupExploreRate * 0x1p32);
    // Exact mode without a trial: only explored queries record their segments and estimates;
    // every other query traces the original as the exact estimator does (in one pass in
    // kSampleCountPasses after adding to the region's sample counter).
    bool quiet = true;
    // Measured costs only: one query in kAltQueries runs the other mode (roulette with q, or
    // exact), for a same-pass comparison of the two modes' times.
    bool trial = false;
  };
  // Whether a query runs the plan's other mode (see Plan::trial). Depends only on the point, the
  // pass and the region, never on random numbers.
  bool alternate(const Plan& plan, uint32_t point) const {
    return plan.trial && (point + passes_) % kAltQueries == 0;
  }
  // Whether an exact-mode query of `point` explores this pass, for a fraction plan.explore of the
  // points. Exploring never changes an exact estimate, so the choice need not be random or
  // independent of the estimates: a Weyl sequence, point * 2^32 / golden ratio mod 2^32 shifted
  // by a salt drawn per epoch, falls below explore * 2^32 for that fraction of the points, evenly
  // spread. One multiply and a compare, where a full hash was a measurable part of an exact
  // query's cost.
  bool exploresPoint(const Plan& plan, uint32_t point) const {
    return point * kWeylMultiplier + explore_salt_ < plan.explore_below;
  }
  // Whether this pass counts samples (one pass in kSampleCountPasses, each query then counting
  // kSampleCountPasses times its segments): the counter is an exact query's only other cost.
  bool countsSamples() const { return counts_samples_; }
  // Whether a trial region times this query of its own mode (one in kAltQueries, never the
  // alternated one). Depends only on the point and the pass.
  bool timesOwnMode(const Plan& plan, uint32_t point) const {
    return plan.trial && (point + passes_) % kAltQueries == kAltQueries / 2;
  }
  const Plan& plan(uint32_t region) const { return plans_[region]; }
  bool measuresCosts() const { return !options_.fixed_costs; }
  // Largest tick count one timed ray may add (frozen in beginPass): a thread preempted in the
  // middle of a ray would otherwise add milliseconds to a mean of tens of nanoseconds.
  uint64_t tickCap() const { return tick_cap_; }
  // Times of whole queries by mode (ns per segment, shading cost included), once both modes have
  // enough timed segments in `region`; nullopt before.
  struct ModeTimes {
    double exact = 0, roulette = 0;
  };
  std::optional<ModeTimes> modeTimes(uint32_t region) const;

  // The calling thread's tally of `region` for this pass: the record*() calls add to it without
  // atomics; endPass() sums every thread's tallies (integer sums: the order does not matter).
  // A thread-local cache of (learner, tallies) makes it a compare and a load, cheap enough for
  // every query of an exact region to count its samples.
  RegionTally& local(uint32_t region) {
    LocalCache& c = localCache();
    if (c.learner != id_) {
      c.tallies = &threadTallies();
      c.learner = id_;
    }
    return (*c.tallies)[region];
  }

  // What the estimator saw of one segment it classed (V' traced).
  struct SegmentObservation {
    bool proxy_visible = false;     // V'
    bool traced_original = false;   // V was traced (a correction, or exact mode's answer)
    bool original_visible = false;  // V, when traced
    bool by_roulette = false;       // traced as a roulette correction (weighted 1/q later)
    // CPU ticks of the rays that were timed (an original may be timed without being traced
    // for the estimate: traced_original false, original_ticks set).
    std::optional<uint64_t> proxy_ticks, original_ticks;
  };
  // Records one classed segment: its class, its error if V is known, its ray times (capped at
  // tickCap()).
  void recordSegment(RegionTally& t, const SegmentObservation& o) const;
  // Records `count` segments estimated in the region, whatever the mode (the region's weight).
  static void recordSamples(RegionTally& t, uint64_t count) { t.samples += count; }
  // Records one whole query timed in exact (roulette = false) or roulette mode: `segments`
  // segments in `ticks` (capped at tickCap() per segment).
  void recordQueryTime(RegionTally& t, bool roulette, uint64_t segments, uint64_t ticks) const;
  // Variance learning for one query's estimates. `point` may be kNoPoint. Each point must be
  // passed at most once per pass (its history must come from earlier passes). Only one point in
  // kVarianceStride is kept unless `every_point` (explored queries, already a sparse choice).
  void addEstimates(uint32_t point, std::span<const double> estimates, RegionTally& t,
                    bool every_point = false);

  // Single-threaded. beginPass freezes the plans from everything folded in so far; endPass folds
  // the pass's counters into the statistics. In measured mode they also calibrate CPU ticks
  // against steady_clock over the passes, so that learned costs are reported in ns.
  void beginPass();
  void endPass();
  // Cost every light sample pays outside visibility (ClassCosts::per_sample): ns in measured
  // mode, the fixed costs' unit otherwise. Takes effect at the next beginPass.
  void setPerSampleCost(double cost) { per_sample_ = cost; }

  // The model a region's decision uses (costs shrunk towards the global mean per class).
  RouletteModel model(uint32_t region) const;
  uint64_t observations(uint32_t region) const;
  LearnedSummary summary() const;

 private:
  struct Pending {  // this pass, integer atomics
    std::atomic<uint64_t> n[2], traced[2], err[2], cost_n_p[2], cost_n_o[2], ticks_p[2], ticks_o[2],
        v_n;
    std::atomic<int64_t> v_sum, v_cross;
  };
  struct Learned {  // passes so far
    double n[2] = {0, 0};
    double err_weighted[2] = {0, 0};  // sum of errors / q of their pass
    double cost_n_p[2] = {0, 0}, cost_n_o[2] = {0, 0}, ticks_p[2] = {0, 0}, ticks_o[2] = {0, 0};
    double mode_n[2] = {0, 0}, mode_ticks[2] = {0, 0};  // decayed by kModeDecay per pass
    double v_sum = 0, v_cross = 0, v_n = 0;
    double samples = 0;
  };
  struct PointHistory {
    int64_t sum = 0;  // fixed point
    uint32_t count = 0;
  };

  struct LocalCache {
    uint64_t learner = 0;  // id_ of the learner whose tallies follow (0: none)
    std::vector<RegionTally>* tallies = nullptr;
  };
  // initial-exec: one load from the thread pointer (the library is linked statically).
  static LocalCache& localCache() {
    static thread_local LocalCache cache __attribute__((tls_model("initial-exec")));
    return cache;
  }
  std::vector<RegionTally>& threadTallies();

  // Unique per learner for the life of the process (an address could be reused by a later one).
  uint64_t id_ = 0;
  Options options_;
  std::vector<Plan> plans_;
  // ets_key_per_instance: a native TLS key, the fastest lookup TBB offers (once per query).
  tbb::enumerable_thread_specific<std::vector<RegionTally>,
                                  tbb::cache_aligned_allocator<std::vector<RegionTally>>,
                                  tbb::ets_key_per_instance>
      locals_;
  std::vector<Learned> learned_;
  std::vector<PointHistory> points_;
  ClassCosts global_costs_;  // ns when measured (once calibrated)
  double per_sample_ = 0;
  uint64_t tick_cap_ = uint64_t(1) << 22;
  uint32_t passes_ = 0;         // passes folded in so far
  uint32_t explore_salt_ = 0;   // exploresPoint's shift for this pass's epoch
  bool counts_samples_ = true;  // see countsSamples()
  // Tick calibration: the pass being timed, and totals over passes.
  int64_t pass_start_ns_ = 0;
  uint64_t pass_start_ticks_ = 0;
  double calib_ns_ = 0, calib_ticks_ = 0;
  double nsPerTick() const { return calib_ticks_ > 0 ? calib_ns_ / calib_ticks_ : 1.0; }
  // An exact-mode region's exploration rate given its model, the efficiency of roulette against
  // exact and the samples seen.
  static double exploreRate(const RouletteModel& m, double efficiency, double samples);
};

}  // namespace proxyvis
