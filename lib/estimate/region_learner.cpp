#include "estimate/region_learner.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>

#include "estimate/cpu_ticks.h"

#include "util/error.h"

namespace proxyvis {

namespace {

// The constants of model(), which estimates a region from its tallies.
// Pseudo-counts for the error-rate estimate: (errors + 1/2) / (samples + 1).
constexpr double kErrorPriorErrors = 0.5, kErrorPriorSamples = 1.0;
// Timed rays a region needs before its own cost outweighs the global mean of the class.
constexpr double kCostShrinkage = 32.0;
// Variance pairs a region needs before its own V(1-V) estimate replaces the pooled one.
constexpr double kMinVariancePairs = 16.0;

uint64_t nextLearnerId() {
  static std::atomic<uint64_t> next{1};
  return next.fetch_add(1, std::memory_order_relaxed);
}

int64_t toFixed(double x) {
  return int64_t(x * double(RegionLearner::kFixedOne));
}

template <class T>
uint64_t take(std::atomic<T>& a) {
  return uint64_t(a.exchange(0, std::memory_order_relaxed));
}

}  // namespace

void RegionTally::add(const RegionTally& o) {
  for (int i = 0; i < 2; ++i) {
    n[i] += o.n[i];
    traced[i] += o.traced[i];
    err[i] += o.err[i];
    err_roulette[i] += o.err_roulette[i];
    cost_n_p[i] += o.cost_n_p[i];
    cost_n_o[i] += o.cost_n_o[i];
    ticks_p[i] += o.ticks_p[i];
    ticks_o[i] += o.ticks_o[i];
  }
  for (int i = 0; i < 2; ++i) {
    mode_n[i] += o.mode_n[i];
    mode_ticks[i] += o.mode_ticks[i];
  }
  v_sum += o.v_sum;
  v_cross += o.v_cross;
  v_n += o.v_n;
  samples += o.samples;
}

RegionDecision decideRegion(const RouletteModel& m, ProxyClass cls, double q_min, double margin) {
  RegionDecision d;
  d.q = optimalRouletteQ(m, cls, q_min);
  d.predicted_efficiency = rouletteEfficiencyVsExact(m, d.q);
  d.roulette = d.predicted_efficiency >= 1 + margin;
  return d;
}

RegionLearner::RegionLearner(uint32_t num_regions, uint32_t num_points, const Options& options)
    : id_(nextLearnerId()),
      options_(options),
      plans_(num_regions),
      learned_(num_regions),
      points_(num_points) {
  PV_CHECK(num_regions > 0);
  PV_CHECK(options.q_min > 0 && options.q_min <= 1);
  if (options_.fixed_costs) {
    global_costs_ = *options_.fixed_costs;
    per_sample_ = options_.fixed_costs->per_sample;
  }
}

void RegionLearner::recordSegment(RegionTally& t, const SegmentObservation& o) const {
  const int vp = o.proxy_visible ? 1 : 0;
  ++t.n[vp];
  if (o.traced_original) {
    ++t.traced[vp];
    if (o.original_visible != o.proxy_visible) {
      ++t.err[vp];
      if (o.by_roulette) ++t.err_roulette[vp];
    }
  }
  if (o.proxy_ticks) {
    ++t.cost_n_p[vp];
    t.ticks_p[vp] += std::min(*o.proxy_ticks, tick_cap_);
  }
  if (o.original_ticks) {
    ++t.cost_n_o[vp];
    t.ticks_o[vp] += std::min(*o.original_ticks, tick_cap_);
  }
}

void RegionLearner::recordQueryTime(RegionTally& t, bool roulette, uint64_t segments,
                                    uint64_t ticks) const {
  const int mode = roulette ? 1 : 0;
  t.mode_n[mode] += segments;
  t.mode_ticks[mode] += std::min(ticks, tick_cap_ * segments);
}

std::vector<RegionTally>& RegionLearner::threadTallies() {
  // Sized once per thread and never reallocated (endPass refills it), so the cached pointer in
  // local() stays valid for the learner's life.
  std::vector<RegionTally>& v = locals_.local();
  if (v.empty()) v.resize(plans_.size());
  return v;
}

void RegionLearner::addEstimates(uint32_t point, std::span<const double> estimates, RegionTally& t,
                                 bool every_point) {
  if (estimates.empty()) return;
  if (point != ShadingPointQuery::kNoPoint && point < points_.size()) {
    // One point in RegionLearner::kVarianceStride is enough for a region's mean V(1-V), and the
    // history update is the learner's largest per-query cost.
    if (!every_point && point % RegionLearner::kVarianceStride != 0) return;
    PointHistory& h = points_[point];
    if (h.count > 0) {
      const double prev = double(h.sum) / (double(h.count) * double(kFixedOne));
      for (double x : estimates) {
        t.v_sum += toFixed(x);
        t.v_cross += toFixed(prev * x);
        ++t.v_n;
      }
    }
    for (double x : estimates) h.sum += toFixed(x);
    h.count += uint32_t(estimates.size());
    return;
  }
  if (estimates.size() < 2) return;
  double s = 0, q = 0;
  for (double x : estimates) {
    s += x;
    q += x * x;
  }
  const double n = double(estimates.size());
  t.v_sum += toFixed(s / n);
  t.v_cross += toFixed((s * s - q) / (n * (n - 1)));  // mean of x_j x_l over pairs j != l
  ++t.v_n;
}

uint64_t RegionLearner::observations(uint32_t region) const {
  const Learned& l = learned_[region];
  return uint64_t(l.n[0] + l.n[1]);
}

RouletteModel RegionLearner::model(uint32_t region) const {
  const Learned& l = learned_[region];
  RouletteModel m;
  const double total = l.n[0] + l.n[1];
  m.p_blocked = total > 0 ? l.n[0] / total : 0.5;
  const bool possible[2] = {options_.proxy_class != ProxyClass::kInside,
                            options_.proxy_class != ProxyClass::kOutside};
  double err[2];
  for (int i = 0; i < 2; ++i)
    err[i] =
        possible[i] ? (l.err_weighted[i] + kErrorPriorErrors) / (l.n[i] + kErrorPriorSamples) : 0.0;
  err[0] = std::min(err[0], 1.0);
  err[1] = std::min(err[1], 1.0);
  m.p_mh = m.p_blocked * err[0];
  m.p_hm = (1 - m.p_blocked) * err[1];
  if (l.v_n >= kMinVariancePairs) {
    m.var_exact = std::max(0.0, (l.v_sum - l.v_cross) / l.v_n);
  } else {
    const double v = m.p_blocked * err[0] + (1 - m.p_blocked) * (1 - err[1]);
    m.var_exact = v * (1 - v);
  }
  if (options_.fixed_costs) {
    m.costs = *options_.fixed_costs;
  } else {
    const double ns = nsPerTick();
    for (int i = 0; i < 2; ++i) {
      m.costs.proxy[i] = (l.ticks_p[i] * ns + kCostShrinkage * global_costs_.proxy[i]) /
                         (l.cost_n_p[i] + kCostShrinkage);
      m.costs.original[i] = (l.ticks_o[i] * ns + kCostShrinkage * global_costs_.original[i]) /
                            (l.cost_n_o[i] + kCostShrinkage);
    }
  }
  m.costs.per_sample = per_sample_;
  return m;
}

namespace {

// The constants of beginPass, which sets each pass's tick cap and each region's mode.
// The tick cap of one timed ray: kTickCapOverWorstMean times the costliest class mean (a ray
// rarely costs more; a preempted one does), never below kMinTickCap ticks (before costs are
// known, and so that a cheap scene's slowest honest rays are not cut).
constexpr double kTickCapOverWorstMean = 64;
constexpr uint64_t kMinTickCap = 1000;
// Measured efficiency when roulette adds no variance but exact has some: roulette wins outright
// (the ratio would be infinite); any large finite value passes every threshold.
constexpr double kNoAddedVarianceEfficiency = 1e9;
// Hysteresis: a region already on roulette stays there while its measured efficiency is at least
// this (switching needs 1 + margin), so timing noise does not flip it every pass.
constexpr double kStayOnRouletteEfficiency = 1.05;

int64_t steadyNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

}  // namespace

void RegionLearner::beginPass() {
  if (measuresCosts()) {
    pass_start_ns_ = steadyNs();
    pass_start_ticks_ = cpuTicks();
    // Once there is a costliest class mean (see kTickCapOverWorstMean).
    double worst_ns = 0;
    for (int i = 0; i < 2; ++i)
      worst_ns = std::max({worst_ns, global_costs_.proxy[i], global_costs_.original[i]});
    if (calib_ticks_ > 0 && worst_ns > 1)
      tick_cap_ =
          std::max<uint64_t>(kMinTickCap, uint64_t(kTickCapOverWorstMean * worst_ns / nsPerTick()));
  }
  explore_salt_ = uint32_t(mixBits(passes_ / kExploreEpochPasses));
  counts_samples_ = passes_ % kSampleCountPasses == 0;
  for (uint32_t r = 0; r < plans_.size(); ++r) {
    Plan& p = plans_[r];
    if (observations(r) < uint64_t(kMinSamples) || (measuresCosts() && passes_ < 2)) {
      p = Plan{};  // warm-up: exact, exploring kWarmupExploreRate
      continue;
    }
    const RouletteModel m = model(r);
    const RegionDecision d = decideRegion(m, options_.proxy_class, options_.q_min, options_.margin);
    bool roulette = d.roulette;
    double efficiency = d.predicted_efficiency;
    if (const std::optional<ModeTimes> t = modeTimes(r)) {
      // Both modes timed here: their measured times replace the per-ray cost model.
      const double var = rouletteVariance(m, d.q);
      efficiency = var > 0
                       ? m.var_exact * t->exact / (var * t->roulette)
                       : (m.var_exact > 0 ? kNoAddedVarianceEfficiency : t->exact / t->roulette);
      // Both must agree: the model (per-ray costs) and the measured times (with hysteresis).
      roulette = d.roulette &&
                 efficiency >= (p.roulette ? kStayOnRouletteEfficiency : 1.0 + options_.margin);
    } else if (measuresCosts()) {
      // Until both modes are timed, the model alone only starts a trial: single rays timed on a
      // loaded machine can be off by a factor of ten (a preempted ray), and a region switched to
      // roulette on such a cost loses to exact until the trial catches it.
      roulette = false;
    }
    const bool trial = measuresCosts() && (roulette || d.roulette);
    const double explore = exploreRate(m, efficiency, learned_[r].samples);
    p = Plan{roulette, d.q, explore, uint32_t(explore * 0x1p32), !roulette && !trial, trial};
  }
}

double RegionLearner::exploreRate(const RouletteModel& m, double efficiency, double samples) {
  if (efficiency < kSettledEfficiency) return kSettledExploreRate;
  // The statistics' error falls as 1/sqrt(samples), so does the rate needed to keep them current.
  const double thinning = kExploreRate * std::sqrt(kExploreSamples / std::max(1.0, samples));
  // An explored segment costs one proxy ray more; where that ray is dear (a point on an object
  // with a proxy traces its own original in V' too) the rate is cut so that exploring costs at
  // most kExploreBudget of exact.
  const double proxy_ray = m.p_blocked * m.costs.proxy[0] + (1 - m.p_blocked) * m.costs.proxy[1];
  const double affordable = proxy_ray > 0 ? kExploreBudget * exactCost(m) / proxy_ray : 1.0;
  return std::clamp(std::min(affordable, thinning), kSettledExploreRate, kExploreRate);
}

void RegionLearner::endPass() {
  if (measuresCosts() && pass_start_ns_ != 0) {
    calib_ns_ += double(steadyNs() - pass_start_ns_);
    calib_ticks_ += double(cpuTicks() - pass_start_ticks_);
  }
  std::vector<RegionTally> pass(plans_.size());
  for (std::vector<RegionTally>& v : locals_) {
    for (size_t r = 0; r < v.size(); ++r) pass[r].add(v[r]);
    std::fill(v.begin(), v.end(), RegionTally{});
  }
  // The first pass runs on cold caches and pages (every BVH node touched for the first time):
  // its ray times overstate whichever scene it traced most, so they are dropped.
  if (measuresCosts() && passes_ == 0)
    for (RegionTally& p : pass)
      for (int i = 0; i < 2; ++i) {
        p.cost_n_p[i] = p.cost_n_o[i] = p.ticks_p[i] = p.ticks_o[i] = 0;
        p.mode_n[i] = p.mode_ticks[i] = 0;
      }
  ++passes_;
  double sum_p[2] = {0, 0}, n_p[2] = {0, 0}, sum_o[2] = {0, 0}, n_o[2] = {0, 0};
  for (uint32_t r = 0; r < plans_.size(); ++r) {
    const RegionTally& p = pass[r];
    Learned& l = learned_[r];
    const Plan& plan = plans_[r];
    const double q[2] = {plan.q.q0, plan.q.q1};
    for (int i = 0; i < 2; ++i) {
      l.n[i] += double(p.n[i]);
      // Errors found by exact tracing count once, those of roulette corrections 1/q_i times
      // (traced => q_i > 0): Horvitz-Thompson, whatever mix of modes the pass ran.
      l.err_weighted[i] += double(p.err[i] - p.err_roulette[i]);
      if (p.err_roulette[i]) l.err_weighted[i] += double(p.err_roulette[i]) / q[i];
      l.cost_n_p[i] += double(p.cost_n_p[i]);
      l.ticks_p[i] += double(p.ticks_p[i]);
      l.cost_n_o[i] += double(p.cost_n_o[i]);
      l.ticks_o[i] += double(p.ticks_o[i]);
      l.mode_n[i] = kModeDecay * l.mode_n[i] + double(p.mode_n[i]);
      l.mode_ticks[i] = kModeDecay * l.mode_ticks[i] + double(p.mode_ticks[i]);
      sum_p[i] += l.ticks_p[i];
      n_p[i] += l.cost_n_p[i];
      sum_o[i] += l.ticks_o[i];
      n_o[i] += l.cost_n_o[i];
    }
    l.v_n += double(p.v_n);
    l.samples += double(p.samples);
    l.v_sum += double(p.v_sum) / double(kFixedOne);
    l.v_cross += double(p.v_cross) / double(kFixedOne);
  }
  if (options_.fixed_costs) return;
  // Global mean per class in ns; a class never timed borrows the other class's mean.
  const double ns = nsPerTick();
  auto mean = [&](double s, double n) { return n > 0 ? s * ns / n : 0.0; };
  double cp[2] = {mean(sum_p[0], n_p[0]), mean(sum_p[1], n_p[1])};
  double co[2] = {mean(sum_o[0], n_o[0]), mean(sum_o[1], n_o[1])};
  for (int i = 0; i < 2; ++i) {
    if (cp[i] <= 0) cp[i] = cp[1 - i] > 0 ? cp[1 - i] : 1.0;
    if (co[i] <= 0) co[i] = co[1 - i] > 0 ? co[1 - i] : cp[i];
  }
  for (int i = 0; i < 2; ++i) {
    global_costs_.proxy[i] = cp[i];
    global_costs_.original[i] = co[i];
  }
}

std::optional<RegionLearner::ModeTimes> RegionLearner::modeTimes(uint32_t region) const {
  const Learned& l = learned_[region];
  if (!measuresCosts() || l.mode_n[0] < kMinModeSegments || l.mode_n[1] < kMinModeSegments)
    return std::nullopt;
  const double ns = nsPerTick();
  return ModeTimes{per_sample_ + ns * l.mode_ticks[0] / l.mode_n[0],
                   per_sample_ + ns * l.mode_ticks[1] / l.mode_n[1]};
}

LearnedSummary RegionLearner::summary() const {
  LearnedSummary s;
  double n[2] = {0, 0}, err[2] = {0, 0}, v_n = 0, v_diff = 0;
  // Predicted efficiency of the current plans: sample-weighted sums of variance and cost.
  double var_e = 0, cost_e = 0, var_plan = 0, cost_plan = 0;
  for (uint32_t r = 0; r < plans_.size(); ++r) {
    const Learned& l = learned_[r];
    if (l.n[0] + l.n[1] <= 0) continue;
    ++s.regions;
    if (plans_[r].roulette) ++s.regions_roulette;
    const RouletteModel m = model(r);
    const double w = l.samples;
    var_e += w * m.var_exact;
    cost_e += w * exactCost(m);
    var_plan += w * (plans_[r].roulette ? rouletteVariance(m, plans_[r].q) : m.var_exact);
    cost_plan += w * (plans_[r].roulette ? rouletteCost(m, plans_[r].q) : exactCost(m));
    for (int i = 0; i < 2; ++i) {
      n[i] += l.n[i];
      err[i] += l.err_weighted[i];
    }
    v_n += l.v_n;
    v_diff += l.v_sum - l.v_cross;
  }
  const double total = n[0] + n[1];
  s.p_proxy_blocked = total > 0 ? n[0] / total : 0;
  s.error_given_blocked = n[0] > 0 ? err[0] / n[0] : 0;
  s.error_given_visible = n[1] > 0 ? err[1] / n[1] : 0;
  s.var_exact = v_n > 0 ? v_diff / v_n : 0;
  s.costs = global_costs_;
  s.costs.per_sample = per_sample_;
  if (var_plan > 0 && cost_plan > 0)
    s.predicted_efficiency = var_e * cost_e / (var_plan * cost_plan);
  return s;
}

}  // namespace proxyvis
