#pragma once
// The "roulette" estimator: per region (tile x light), exact or proxy + roulette correction
// (roulette.h), decided each pass from earlier passes only by a RegionLearner
// (region_learner.h); no probe rays. Statistics persist across render() calls with the same
// estimator; make a new one to start fresh.
#include <tbb/cache_aligned_allocator.h>
#include <tbb/enumerable_thread_specific.h>

#include <cstdint>

#include "estimate/region_learner.h"
#include "estimate/visibility_estimator.h"

namespace proxyvis {

class RouletteEstimator final : public VisibilityEstimator {
 public:
  explicit RouletteEstimator(const EstimatorSetup& setup);

  void beginPass(int) override { learner_.beginPass(); }
  void endPass() override { learner_.endPass(); }
  LearnedSummary learnedSummary() const override { return learner_.summary(); }
  void setPerSampleCost(double cost) override { learner_.setPerSampleCost(cost); }
  void estimate(const ShadingPointQuery& q, Rng& rng, std::span<double> out,
                RayCounts& counts) override;

 private:
  // Which queries and rays this thread times (measured costs only): counters of the queries and
  // roulette segments it has seen. Never depends on random numbers, so it cannot influence an
  // estimate.
  struct TimingCounters {
    uint32_t queries = 0;
    uint32_t roulette_segments = 0;
  };

  void estimateRecorded(const ShadingPointQuery& q, Rng& rng, const RegionLearner::Plan& plan,
                        std::span<double> out, RayCounts& counts, RegionTally& t,
                        TimingCounters* timing);

  RegionLearner learner_;
  uint32_t num_regions_ = 0;
  // ets_key_per_instance: a native TLS key, looked up once per query (measured costs only).
  tbb::enumerable_thread_specific<TimingCounters, tbb::cache_aligned_allocator<TimingCounters>,
                                  tbb::ets_key_per_instance>
      timing_;
};

}  // namespace proxyvis
