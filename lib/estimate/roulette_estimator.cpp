#include "estimate/roulette_estimator.h"

#include "estimate/cpu_ticks.h"
#include "estimate/sample_estimators.h"
#include "util/error.h"

namespace proxyvis {

namespace {

// With measured costs, one roulette segment in kTimedSegmentStride has its rays timed: enough
// samples of the per-class costs at an eighth of the clock reads.
constexpr uint32_t kTimedSegmentStride = 8;
// Of the timed roulette segments that trace no correction, one in kTimingOnlyOriginalStride also
// traces the original just to time it: where q is 0 or tiny, c_o | V' would otherwise go stale.
// 64: at most 1 segment in 512 pays an extra original ray (1 in 64 was measurably slower).
constexpr uint32_t kTimingOnlyOriginalStride = 64;

// The setup's class, floor and costs; the learner's own default margin.
RegionLearner::Options learnerOptions(const EstimatorSetup& setup) {
  RegionLearner::Options o;
  o.proxy_class = setup.proxy_class;
  o.q_min = setup.q_min;
  o.fixed_costs = setup.fixed_costs;
  return o;
}

}  // namespace

RouletteEstimator::RouletteEstimator(const EstimatorSetup& setup)
    : learner_(setup.num_regions, setup.num_points, learnerOptions(setup)),
      num_regions_(setup.num_regions) {}

void RouletteEstimator::estimate(const ShadingPointQuery& q, Rng& rng, std::span<double> out,
                                 RayCounts& counts) {
  PV_CHECK_MSG(q.region < num_regions_, "query region out of range of EstimatorSetup::num_regions");
  const RegionLearner::Plan& region_plan = learner_.plan(q.region);
  // Exploring never changes an exact estimate, so it need not be independent of it: the point's
  // place in RegionLearner::exploresPoint's sequence decides, cheaper than a random number.
  auto explores = [&](const RegionLearner::Plan& plan) {
    return q.point == ShadingPointQuery::kNoPoint ? rng.uniformFloat() < plan.explore
                                                  : learner_.exploresPoint(plan, q.point);
  };
  // In one pass in kSampleCountPasses, every query counts its segments in the region's tally
  // (a thread-local compare and load).
  if (learner_.countsSamples())
    RegionLearner::recordSamples(learner_.local(q.region),
                                 q.segments.size() * RegionLearner::kSampleCountPasses);
  if (region_plan.quiet) {
    // An exact region without a trial: the exact estimator's path; only explored queries
    // record more.
    if (!explores(region_plan)) {
      for (size_t j = 0; j < q.segments.size(); ++j)
        out[j] = exactSample(*q.tracer, q.segments[j], counts);
      return;
    }
    RegionTally& t = learner_.local(q.region);
    estimateRecorded(q, rng, region_plan, out, counts, t, nullptr);
    learner_.addEstimates(q.point, out.first(q.segments.size()), t, true);
    return;
  }
  // Roulette, or an exact region on trial: a trial region runs one query in
  // RegionLearner::kAltQueries in its other mode.
  const bool alt = learner_.alternate(region_plan, q.point);
  RegionLearner::Plan alt_plan = region_plan;
  if (alt) alt_plan.roulette = !region_plan.roulette;
  const RegionLearner::Plan& plan = alt ? alt_plan : region_plan;
  RegionTally& t = learner_.local(q.region);
  TimingCounters* timing = learner_.measuresCosts() ? &timing_.local() : nullptr;
  // One query in kAltQueries of a trial region is timed whole in each mode, for the cost of
  // its region's mode (region_learner.h).
  const bool time_query = timing && region_plan.trial &&
                          (alt || (q.point == ShadingPointQuery::kNoPoint
                                       ? timing->queries++ % RegionLearner::kAltQueries == 0
                                       : learner_.timesOwnMode(region_plan, q.point)));
  const uint64_t query_start = time_query ? cpuTicks() : 0;
  if (!plan.roulette && !explores(plan)) {
    for (size_t j = 0; j < q.segments.size(); ++j)
      out[j] = exactSample(*q.tracer, q.segments[j], counts);
  } else {
    estimateRecorded(q, rng, plan, out, counts, t, timing);
  }
  learner_.addEstimates(q.point, out.first(q.segments.size()), t);
  if (time_query)
    learner_.recordQueryTime(t, plan.roulette, q.segments.size(), cpuTicks() - query_start);
}

// Roulette or exploring exact: every segment is classed (V') and recorded in `t`. Timed rays:
// every explored segment (they are few and are the only samples of c_o by class in an exact
// region) and one roulette segment in kTimedSegmentStride per thread.
void RouletteEstimator::estimateRecorded(const ShadingPointQuery& q, Rng& rng,
                                         const RegionLearner::Plan& plan, std::span<double> out,
                                         RayCounts& counts, RegionTally& t,
                                         TimingCounters* timing) {
  for (size_t j = 0; j < q.segments.size(); ++j) {
    const double u = plan.roulette ? double(rng.uniformFloat()) : 1.0;
    uint32_t timed_index = 0;  // which timed roulette segment this is
    bool timed = learner_.measuresCosts();
    if (timed && plan.roulette && timing) {
      const uint32_t k = timing->roulette_segments++;
      timed = k % kTimedSegmentStride == 0;
      timed_index = k / kTimedSegmentStride;
    }
    TimedTracer<SegmentTracer> tt{*q.tracer, timed};
    RegionLearner::SegmentObservation o;
    if (plan.roulette) {
      const RouletteOutcome r = rouletteSample(tt, q.segments[j], plan.q, u, counts);
      out[j] = r.estimate;
      o.proxy_visible = r.proxy_visible;
      o.traced_original = r.traced_original;
      o.original_visible = r.original_visible;
      o.by_roulette = true;
      if (timed && !r.traced_original && timed_index % kTimingOnlyOriginalStride == 0) {
        // An original ray traced only to be timed: its answer is not used, so the estimate is
        // unchanged; its cost is counted like any other ray.
        ++counts.original;
        (void)tt.originalVisible(q.segments[j]);
        o.original_ticks = tt.original_ticks;
      }
    } else {  // exploring: both rays, the exact answer
      ++counts.proxy;
      o.proxy_visible = tt.proxyVisible(q.segments[j]);
      out[j] = exactSample(tt, q.segments[j], counts);
      o.traced_original = true;
      o.original_visible = out[j] > 0;
    }
    if (timed) {
      o.proxy_ticks = tt.proxy_ticks;
      if (o.traced_original) o.original_ticks = tt.original_ticks;
    }
    learner_.recordSegment(t, o);
  }
}

}  // namespace proxyvis
