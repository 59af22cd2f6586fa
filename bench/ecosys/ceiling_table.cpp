#include "ceiling_table.h"

#include <algorithm>
#include <limits>
#include <numeric>

#include "estimate/roulette.h"

namespace proxyvis::ecosys {

void RegionStats::add(const RegionStats& o) {
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) n[i][j] += o.n[i][j];
    timed[i] += o.timed[i];
    ticks_p[i] += o.ticks_p[i], ticks_o[i] += o.ticks_o[i];
  }
  var_sum += o.var_sum;
}

CeilingStats::CeilingStats(int lights, int width, int height, int tile, uint64_t cap_ticks)
    : lights_(lights), width_(width), tile_(tile), cap_ticks_(cap_ticks) {
  tiles_x_ = (width + tile - 1) / tile;
  tiles_ = tiles_x_ * ((height + tile - 1) / tile);
  regions_.resize(size_t(lights) * tiles_);
  v_sum_.assign(size_t(lights) * width * height, 0.0);
  v_n_.assign(v_sum_.size(), 0);
}

void CeilingStats::add(uint32_t light, uint32_t pixel, bool proxy_visible, bool visible,
                       uint64_t ticks_proxy, uint64_t ticks_original) {
  const int tile = int((pixel / width_) / tile_) * tiles_x_ + int((pixel % width_) / tile_);
  RegionStats& r = regions_[size_t(light) * tiles_ + tile];
  r.n[proxy_visible][visible]++;
  if (ticks_proxy < cap_ticks_ && ticks_original < cap_ticks_) {
    r.timed[proxy_visible]++;
    r.ticks_p[proxy_visible] += double(ticks_proxy);
    r.ticks_o[proxy_visible] += double(ticks_original);
  } else {
    ++preempted_;
  }
  const size_t key = size_t(light) * v_n_.size() / lights_ + pixel;
  v_sum_[key] += visible;
  v_n_[key]++;
  samples_.emplace_back(light, pixel);
}

void CeilingStats::finish() {
  const size_t per_light = v_n_.size() / lights_;
  for (auto [light, pixel] : samples_) {
    const size_t key = light * per_light + pixel;
    const double n = v_n_[key], m = v_sum_[key] / n;
    const int tile = int((pixel / width_) / tile_) * tiles_x_ + int((pixel % width_) / tile_);
    regions_[size_t(light) * tiles_ + tile].var_sum += n > 1 ? n / (n - 1) * m * (1 - m) : 0;
  }
  samples_.clear();
}

namespace {

// The roulette model of a region; a class seen in fewer than 16 samples borrows the light-wide
// cost (its weight is small anyway).
RouletteModel modelOf(const RegionStats& r, const ClassCosts& fallback) {
  RouletteModel m;
  const double n = double(r.samples());
  m.p_mh = r.n[0][1] / n;
  m.p_hm = r.n[1][0] / n;
  m.p_blocked = (r.n[0][0] + r.n[0][1]) / n;
  m.var_exact = r.var_sum / n;
  for (int i = 0; i < 2; ++i) {
    const double ni = double(r.timed[i]);
    m.costs.proxy[i] = ni >= 16 ? r.ticks_p[i] / ni : fallback.proxy[i];
    m.costs.original[i] = ni >= 16 ? r.ticks_o[i] / ni : fallback.original[i];
  }
  m.costs.per_sample = fallback.per_sample;
  return m;
}

// Per-sample means over a light's regions: exact and oracle Var and Cost.
struct Totals {
  double var_exact = 0, cost_exact = 0, var_oracle = 0, cost_oracle = 0;
  double var_culling = 0, cost_culling = 0;
  int regions = 0, regions_roulette = 0;
};

// The oracle decides per region from `train` (exact or roulette, and q) and is scored on `stats`;
// train == stats scores it on the samples it decided from (optimistic: it fits their noise).
Totals oracle(const CeilingStats& stats, const CeilingStats& train, int light,
              const ClassCosts& fallback, ProxyClass cls, double q_min) {
  Totals t;
  double n_all = 0;
  for (int tile = 0; tile < stats.tiles(); ++tile) {
    const RegionStats& r = stats.region(light, tile);
    const double n = double(r.samples());
    if (n == 0) continue;
    ++t.regions;
    n_all += n;
    const RegionStats& rt = train.region(light, tile);
    bool use = false;
    RouletteQ q;
    if (rt.samples() > 0) {
      const RouletteModel mt = modelOf(rt, fallback);
      q = optimalRouletteQ(mt, cls, q_min);
      const double ve = mt.var_exact, ce = exactCost(mt);
      const double vr = rouletteVariance(mt, q), cr = rouletteCost(mt, q);
      // Where neither adds variance (every pixel fully lit or fully shadowed, no proxy error)
      // the products are both 0 and only the cost decides.
      use = vr * cr < ve * ce || (vr == 0 && ve == 0 && cr < ce);
    }
    const RouletteModel m = modelOf(r, fallback);
    const double ve = m.var_exact, ce = exactCost(m);
    const double vr = rouletteVariance(m, q), cr = rouletteCost(m, q);
    t.regions_roulette += use;
    t.var_exact += n * ve, t.cost_exact += n * ce;
    t.var_oracle += n * (use ? vr : ve), t.cost_oracle += n * (use ? cr : ce);
    const RouletteQ one{1, cls == ProxyClass::kOutside ? 0.0 : 1.0};
    t.var_culling += n * rouletteVariance(m, one), t.cost_culling += n * rouletteCost(m, one);
  }
  if (n_all > 0)
    for (double* x : {&t.var_exact, &t.cost_exact, &t.var_oracle, &t.cost_oracle, &t.var_culling,
                      &t.cost_culling})
      *x /= n_all;
  return t;
}

// Efficiency of an estimator relative to exact, 1/(Var x Cost) over exact's; with no variance on
// either side the cost ratio (as rouletteEfficiencyVsExact does).
double ratio(double var_e, double cost_e, double var, double cost) {
  if (var == 0) return var_e == 0 ? cost_e / cost : std::numeric_limits<double>::infinity();
  return (var_e * cost_e) / (var * cost);
}

}  // namespace

std::vector<CeilingRow> ceilingRows(const CeilingStats& stats,
                                    const std::vector<std::string>& names,
                                    std::vector<double> light_weights, ProxyClass cls, double q_min,
                                    double c_s_ns, double ticks_per_ns, const CeilingStats* train) {
  const int lights = stats.lights();
  const double wsum = std::accumulate(light_weights.begin(), light_weights.end(), 0.0);
  for (double& w : light_weights) w /= wsum;
  std::vector<CeilingRow> rows;
  CeilingRow mix;
  mix.light = "mix";
  Totals mix_shadow, mix_render;
  double mix_class[2] = {0, 0};
  for (int l = 0; l < lights; ++l) {
    RegionStats all;
    for (int tile = 0; tile < stats.tiles(); ++tile) all.add(stats.region(l, tile));
    const double n = double(all.samples());
    if (n == 0) continue;
    ClassCosts fallback;
    for (int i = 0; i < 2; ++i) {
      const double ni = std::max<double>(1, double(all.timed[i]));
      fallback.proxy[i] = all.ticks_p[i] / ni;
      fallback.original[i] = all.ticks_o[i] / ni;
    }
    CeilingRow row;
    row.light = names[l];
    row.weight = light_weights[l];
    row.segments = all.samples();
    row.p_blocked = (all.n[0][0] + all.n[0][1]) / n;
    row.p_mh = all.n[0][1] / n;
    row.p_hm = all.n[1][0] / n;
    row.var_exact = all.var_sum / n;
    for (int i = 0; i < 2; ++i) {
      row.c_p[i] = fallback.proxy[i] / ticks_per_ns;
      row.c_o[i] = fallback.original[i] / ticks_per_ns;
    }
    const CeilingStats& tr = train ? *train : stats;
    const Totals shadow = oracle(stats, tr, l, fallback, cls, q_min);
    fallback.per_sample = c_s_ns * ticks_per_ns;
    const Totals whole = oracle(stats, tr, l, fallback, cls, q_min);
    row.ceiling_shadow =
        ratio(shadow.var_exact, shadow.cost_exact, shadow.var_oracle, shadow.cost_oracle);
    row.ceiling_render =
        ratio(whole.var_exact, whole.cost_exact, whole.var_oracle, whole.cost_oracle);
    row.culling_shadow =
        ratio(shadow.var_exact, shadow.cost_exact, shadow.var_culling, shadow.cost_culling);
    row.regions = shadow.regions;
    row.regions_roulette = shadow.regions_roulette;
    rows.push_back(row);
    // The mix: each sample picks light l with probability w_l, so per-sample Var and Cost are
    // the weighted means of the lights' (the spread between lights is left out for all alike).
    const double w = light_weights[l];
    auto accumulate = [w](Totals& into, const Totals& t) {
      into.var_exact += w * t.var_exact, into.cost_exact += w * t.cost_exact;
      into.var_oracle += w * t.var_oracle, into.cost_oracle += w * t.cost_oracle;
      into.var_culling += w * t.var_culling, into.cost_culling += w * t.cost_culling;
      into.regions += t.regions, into.regions_roulette += t.regions_roulette;
    };
    accumulate(mix_shadow, shadow);
    accumulate(mix_render, whole);
    mix.segments += row.segments;
    mix.p_blocked += w * row.p_blocked, mix.p_mh += w * row.p_mh, mix.p_hm += w * row.p_hm;
    mix.var_exact += w * row.var_exact;
    // Class costs of the mix: weighted by each light's share of that class, not by w alone.
    const double pc[2] = {row.p_blocked, 1 - row.p_blocked};
    for (int i = 0; i < 2; ++i) {
      mix_class[i] += w * pc[i];
      mix.c_p[i] += w * pc[i] * row.c_p[i], mix.c_o[i] += w * pc[i] * row.c_o[i];
    }
  }
  for (int i = 0; i < 2; ++i)
    if (mix_class[i] > 0) mix.c_p[i] /= mix_class[i], mix.c_o[i] /= mix_class[i];
  if (rows.size() > 1) {
    mix.ceiling_shadow = ratio(mix_shadow.var_exact, mix_shadow.cost_exact, mix_shadow.var_oracle,
                               mix_shadow.cost_oracle);
    mix.ceiling_render = ratio(mix_render.var_exact, mix_render.cost_exact, mix_render.var_oracle,
                               mix_render.cost_oracle);
    mix.culling_shadow = ratio(mix_shadow.var_exact, mix_shadow.cost_exact, mix_shadow.var_culling,
                               mix_shadow.cost_culling);
    mix.regions = mix_shadow.regions;
    mix.regions_roulette = mix_shadow.regions_roulette;
    rows.push_back(mix);
  }
  return rows;
}

}  // namespace proxyvis::ecosys
