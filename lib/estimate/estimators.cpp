// The six runtime estimators over the per-sample templates of sample_estimators.h.
// Each draws one uniform number per segment from the caller's Rng (exact and culling draw none)
// and counts every traced ray.
#include <algorithm>
#include <string>

#include "estimate/cpu_ticks.h"
#include "estimate/region_learner.h"
#include "estimate/sample_estimators.h"
#include "estimate/visibility_estimator.h"
#include "util/error.h"

namespace proxyvis {

namespace {

constexpr EstimatorKind kAllKinds[] = {EstimatorKind::kExact,      EstimatorKind::kCulling,
                                       EstimatorKind::kPaperEqual, EstimatorKind::kPaperOptimal,
                                       EstimatorKind::kPaperCost,  EstimatorKind::kRoulette};

// Dirichlet pseudo-count per possible class for the probe-based estimates: keeps every p > 0
// where its class can occur (unbiasedness does not depend on the probes being representative).
constexpr double kProbePrior = 0.5;

class ExactEstimator final : public VisibilityEstimator {
 public:
  void estimate(const ShadingPointQuery& q, Rng&, std::span<double> out,
                RayCounts& counts) override {
    for (size_t j = 0; j < q.segments.size(); ++j)
      out[j] = exactSample(*q.tracer, q.segments[j], counts);
  }
};

class CullingEstimator final : public VisibilityEstimator {
 public:
  explicit CullingEstimator(ProxyClass cls) : cls_(cls) {}
  void estimate(const ShadingPointQuery& q, Rng&, std::span<double> out,
                RayCounts& counts) override {
    for (size_t j = 0; j < q.segments.size(); ++j)
      out[j] = cullingSample(*q.tracer, q.segments[j], cls_, counts);
  }

 private:
  ProxyClass cls_;
};

// paper-equal (fixed p), paper-optimal and paper-cost (p from this point's probe rays).
class SelectionEstimator final : public VisibilityEstimator {
 public:
  SelectionEstimator(EstimatorKind kind, ProxyClass cls, int probes)
      : kind_(kind), cls_(cls), probes_(kind == EstimatorKind::kPaperEqual ? 0 : probes) {}

  int probesPerPoint() const override { return probes_; }

  void estimate(const ShadingPointQuery& q, Rng& rng, std::span<double> out,
                RayCounts& counts) override {
    const SelectionProbabilities p = probabilities(q, counts);
    for (size_t j = 0; j < q.segments.size(); ++j)
      out[j] = selectionSample(*q.tracer, q.segments[j], p, rng.uniformDouble(), counts);
  }

 private:
  SelectionProbabilities probabilities(const ShadingPointQuery& q, RayCounts& counts) const {
    if (kind_ == EstimatorKind::kPaperEqual) return equalProbabilities(cls_);
    ClassCounts cc;
    for (const Segment& s : q.probes) {
      ++counts.probe;
      cc.add(q.tracer->originalVisible(s), q.tracer->proxyVisible(s));
    }
    const ClassProbabilities c = estimateClassProbabilities(cc, cls_, kProbePrior);
    const SelectionProbabilities opt = optimalProbabilities(c, cls_);
    if (kind_ == EstimatorKind::kPaperOptimal) return opt;
    return costHeuristicProbabilities(opt, c.error());  // smoothed: > 0 if errors are possible
  }

  EstimatorKind kind_;
  ProxyClass cls_;
  int probes_;
};

// The setup's class, floor and costs; the learner's own default margin.
RegionLearner::Options learnerOptions(const EstimatorSetup& setup) {
  RegionLearner::Options o;
  o.proxy_class = setup.proxy_class;
  o.q_min = setup.q_min;
  o.fixed_costs = setup.fixed_costs;
  return o;
}

class RouletteEstimator final : public VisibilityEstimator {
 public:
  explicit RouletteEstimator(const EstimatorSetup& setup)
      : learner_(setup.num_regions, setup.num_points, learnerOptions(setup)),
        num_regions_(setup.num_regions) {}

  void beginPass(int) override { learner_.beginPass(); }
  void endPass() override { learner_.endPass(); }
  LearnedSummary learnedSummary() const override { return learner_.summary(); }
  void setPerSampleCost(double cost) override { learner_.setPerSampleCost(cost); }

  void estimate(const ShadingPointQuery& q, Rng& rng, std::span<double> out,
                RayCounts& counts) override {
    PV_CHECK_MSG(q.region < regions(), "query region out of range of EstimatorSetup::num_regions");
    const RegionLearner::Plan& region_plan = learner_.plan(q.region);
    // A trial region runs one query in RegionLearner::kAltQueries in its other mode.
    const bool alt = learner_.alternate(region_plan, q.point);
    RegionLearner::Plan alt_plan = region_plan;
    if (alt) alt_plan.roulette = !region_plan.roulette;
    const RegionLearner::Plan& plan = alt ? alt_plan : region_plan;
    // The region's tally is fetched (a thread-local lookup) only when something is recorded: a
    // settled exact region records its rare explored segments and timed queries only, so its
    // queries cost what the exact estimator's do.
    RegionTally* tally = nullptr;
    auto local = [&]() -> RegionTally& {
      if (!tally) tally = &learner_.local(q.region);
      return *tally;
    };
    const bool sampled_point =
        q.point == ShadingPointQuery::kNoPoint || q.point % RegionLearner::kVarianceStride == 0;
    const bool quiet = (!plan.roulette && plan.settled) || !sampled_point;
    if (sampled_point)
      local().samples +=
          q.segments.size() *
          (q.point == ShadingPointQuery::kNoPoint ? 1 : RegionLearner::kVarianceStride);
    // Which rays get timed (estimateRecorded): every explored segment (they are few and are the
    // only samples of c_o by class in an exact region) and every 8th roulette segment per
    // thread. Never depends on the random numbers, so it cannot influence an estimate.
    thread_local uint32_t query_counter = 0;
    // One query in 16 is timed whole, for the cost of its region's mode (region_learner.h); not
    // while a region still explores every segment (that is not what exact mode costs later).
    const bool time_query =
        learner_.measuresCosts() && (plan.roulette || plan.explore < 1) &&
        (alt || (region_plan.trial && (query_counter++ & (RegionLearner::kAltQueries - 1)) == 0));
    const uint64_t query_start = time_query ? cpuTicks() : 0;
    // Exact mode explores whole queries: one random number per query, and most queries of an
    // exact region take the exact estimator's path (exploring never changes the estimate).
    auto explores = [&] {
      return q.point == ShadingPointQuery::kNoPoint ? rng.uniformFloat() < plan.explore
                                                    : learner_.exploresPoint(plan, q.point);
    };
    if (!plan.roulette && plan.explore < 1 && !explores()) {
      for (size_t j = 0; j < q.segments.size(); ++j)
        out[j] = exactSample(*q.tracer, q.segments[j], counts);
    } else {
      estimateRecorded(q, rng, plan, out, counts, local());
    }
    if (!quiet) learner_.addEstimates(q.point, out.first(q.segments.size()), local());
    if (time_query) {
      const int mode = plan.roulette ? 1 : 0;
      const uint64_t n = q.segments.size();
      RegionTally& t = local();
      t.mode_n[mode] += n;
      t.mode_ticks[mode] += std::min(cpuTicks() - query_start, learner_.tickCap() * n);
    }
  }

 private:
  // Roulette or exploring exact: every segment is classed (V') and recorded in `t`.
  void estimateRecorded(const ShadingPointQuery& q, Rng& rng, const RegionLearner::Plan& plan,
                        std::span<double> out, RayCounts& counts, RegionTally& t) {
    thread_local uint32_t timing_counter = 0;
    for (size_t j = 0; j < q.segments.size(); ++j) {
      const double u = plan.roulette ? double(rng.uniformFloat()) : 1.0;
      TimedTracer<SegmentTracer> tt{
          *q.tracer, learner_.measuresCosts() && (!plan.roulette || (timing_counter++ & 7) == 0)};
      bool vp = false, traced = false, v = false;
      if (plan.roulette) {
        const RouletteOutcome o = rouletteSample(tt, q.segments[j], plan.q, u, counts);
        out[j] = o.estimate;
        vp = o.proxy_visible;
        traced = o.traced_original;
        v = o.original_visible;
        if (tt.timed && !traced && (timing_counter & 63) == 0) {
          // Keeps c_o | V' current in a roulette region, where q may be 0 or tiny: an original
          // ray traced only to be timed (its answer is not used, so the estimate is unchanged;
          // its cost is counted like any other ray).
          ++counts.original;
          (void)tt.originalVisible(q.segments[j]);
          ++t.cost_n_o[vp];
          t.ticks_o[vp] += std::min(tt.original_ticks, learner_.tickCap());
        }
      } else {  // exploring: both rays, the exact answer
        ++counts.proxy;
        vp = tt.proxyVisible(q.segments[j]);
        out[j] = exactSample(tt, q.segments[j], counts);
        traced = true;
        v = out[j] > 0;
      }
      ++t.n[vp];
      if (traced) {
        ++t.traced[vp];
        if (v != vp) {
          ++t.err[vp];
          if (plan.roulette) ++t.err_roulette[vp];
        }
      }
      if (tt.timed) {
        const uint64_t cap = learner_.tickCap();
        ++t.cost_n_p[vp];
        t.ticks_p[vp] += std::min(tt.proxy_ticks, cap);
        if (traced) {
          ++t.cost_n_o[vp];
          t.ticks_o[vp] += std::min(tt.original_ticks, cap);
        }
      }
    }
  }

  uint32_t regions() const { return num_regions_; }
  RegionLearner learner_;
  uint32_t num_regions_ = 0;
};

}  // namespace

const char* estimatorName(EstimatorKind kind) {
  switch (kind) {
    case EstimatorKind::kExact:
      return "exact";
    case EstimatorKind::kCulling:
      return "culling";
    case EstimatorKind::kPaperEqual:
      return "paper-equal";
    case EstimatorKind::kPaperOptimal:
      return "paper-optimal";
    case EstimatorKind::kPaperCost:
      return "paper-cost";
    case EstimatorKind::kRoulette:
      return "roulette";
  }
  return "?";
}

EstimatorKind parseEstimatorName(const std::string& name) {
  std::string valid;
  for (EstimatorKind k : kAllKinds) {
    if (name == estimatorName(k)) return k;
    valid += (valid.empty() ? "" : ", ") + std::string(estimatorName(k));
  }
  throw Error("", "unknown estimator '" + name + "'", "valid estimators: " + valid);
}

std::vector<EstimatorKind> allEstimators() {
  return std::vector<EstimatorKind>(std::begin(kAllKinds), std::end(kAllKinds));
}

std::unique_ptr<VisibilityEstimator> makeEstimator(const EstimatorSetup& setup) {
  if (setup.num_regions == 0) throw Error("", "estimator needs at least one learning region");
  if (!(setup.q_min > 0 && setup.q_min <= 1))
    throw Error("", "q_min must be in (0, 1]", "got " + std::to_string(setup.q_min),
                "a floor of 0 would make roulette biased where an error class is possible");
  if (setup.probes_per_point < 0) throw Error("", "probes per point must be >= 0");
  switch (setup.kind) {
    case EstimatorKind::kExact:
      return std::make_unique<ExactEstimator>();
    case EstimatorKind::kCulling:
      return std::make_unique<CullingEstimator>(setup.proxy_class);
    case EstimatorKind::kPaperEqual:
    case EstimatorKind::kPaperOptimal:
    case EstimatorKind::kPaperCost:
      return std::make_unique<SelectionEstimator>(setup.kind, setup.proxy_class,
                                                  setup.probes_per_point);
    case EstimatorKind::kRoulette:
      return std::make_unique<RouletteEstimator>(setup);
  }
  throw Error("", "unknown estimator kind");
}

}  // namespace proxyvis
