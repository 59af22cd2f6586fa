#pragma once
// Per-region statistics of (V', V) pairs with per-ray costs, and the oracle ceiling they allow,
// per light and for a light mix. A region is one (light, screen tile): what a learner could model
// separately. The oracle picks, per region, exact or roulette with its optimal q (estimate/
// roulette.h), knowing the region's statistics exactly; the ceiling is exact's Var x Cost over
// the oracle's, sample-weighted over regions. Variance is per light sample and not weighted by
// radiance (the same simplification as bench/render_compare/bench_oracle_ceiling.cpp).
#include <cstdint>
#include <string>
#include <vector>

#include "util/proxy_class.h"

namespace proxyvis::ecosys {

struct RegionStats {
  uint64_t n[2][2] = {{0, 0}, {0, 0}};  // [V'][V]
  // Ray costs summed over the timed samples of each class (V'): samples where either ray was
  // preempted (took longer than the cap) count for the probabilities but not for the costs.
  uint64_t timed[2] = {0, 0};
  double ticks_p[2] = {0, 0}, ticks_o[2] = {0, 0};
  double var_sum = 0;  // sum over the region's samples of their pixel's V_p(1-V_p)
  uint64_t samples() const { return n[0][0] + n[0][1] + n[1][0] + n[1][1]; }
  void add(const RegionStats& o);
};

class CeilingStats {
 public:
  // `cap_ticks`: a ray timed longer than this was preempted (the machine is shared), and its
  // sample's costs are left out.
  CeilingStats(int lights, int width, int height, int tile, uint64_t cap_ticks);
  // One traced segment: the proxy's and the original's answer and each ray's cost in ticks.
  void add(uint32_t light, uint32_t pixel, bool proxy_visible, bool visible, uint64_t ticks_proxy,
           uint64_t ticks_original);
  // Credits every sample with its pixel's unbiased V_p(1-V_p); call once after the last add().
  void finish();
  int lights() const { return lights_; }
  const RegionStats& region(int light, int tile) const {
    return regions_[size_t(light) * tiles_ + tile];
  }
  int tiles() const { return tiles_; }
  uint64_t preempted() const { return preempted_; }

 private:
  int lights_, width_, tile_, tiles_x_, tiles_;
  uint64_t cap_ticks_, preempted_ = 0;
  std::vector<RegionStats> regions_;
  std::vector<double> v_sum_;  // [light][pixel]
  std::vector<uint32_t> v_n_;
  std::vector<std::pair<uint32_t, uint32_t>> samples_;  // (light, pixel) of every add()
};

struct CeilingRow {
  std::string light;  // light name, or "mix" for the weighted light mix
  double weight = 1;  // share of light samples this row stands for
  uint64_t segments = 0;
  double p_blocked = 0, p_mh = 0, p_hm = 0, var_exact = 0;
  double c_p[2] = {0, 0}, c_o[2] = {0, 0};  // ns per ray given V' = 0 / 1
  double ceiling_shadow = 1;                // oracle per region, shadow rays alone (c_s = 0)
  double ceiling_render = 1;                // oracle per region with c_s added to every sample
  // Two-fold: the oracle decides on even passes and is scored on odd ones, and the reverse;
  // the mean of the two shadow-ray ceilings (filled in by the bench).
  double ceiling_heldout = 1;
  double culling_shadow = 1;  // q = 1 everywhere (culling for an outside proxy), shadow rays alone
  int regions = 0, regions_roulette = 0;
};

// Rows for each light and, when there are several, one for the mix with `light_weights` (the
// fraction of light samples each light gets; normalized here). `c_s_ns` is the per-sample cost
// outside visibility (ns), `ticks_per_ns` converts the ray timings. With `train`, the oracle
// chooses per region from those statistics (other passes of the same pixels) and is scored on
// `stats`: a held-out ceiling that does not reward choices fitted to the scored samples' noise.
std::vector<CeilingRow> ceilingRows(const CeilingStats& stats,
                                    const std::vector<std::string>& names,
                                    std::vector<double> light_weights, ProxyClass cls, double q_min,
                                    double c_s_ns, double ticks_per_ns,
                                    const CeilingStats* train = nullptr);

}  // namespace proxyvis::ecosys
