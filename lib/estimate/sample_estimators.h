#pragma once
// One visibility estimate per light segment, as templates over the tracer so the renderer's
// SceneTracer and the tests' synthetic tracer inline without virtual calls. A Tracer provides
//   bool proxyVisible(const Segment&) const;     // V'
//   bool originalVisible(const Segment&) const;  // V
// Every traced ray is added to `counts`. `u` is one uniform number in [0, 1) per segment, drawn by
// the caller (the randomised estimators need exactly one).
#include "estimate/roulette.h"
#include "estimate/selection.h"
#include "estimate/visibility_estimator.h"

namespace proxyvis {

template <class Tracer>
double exactSample(const Tracer& t, const Segment& s, RayCounts& counts) {
  ++counts.original;
  return t.originalVisible(s) ? 1.0 : 0.0;
}

// Proxy culling: a pre-test that only short-cuts where the verified class guarantees the answer
// (outside: V' = 1 => V = 1; inside: V' = 0 => V = 0). A general proxy guarantees nothing, so
// culling with it is exact visibility (the proxy is not traced at all).
template <class Tracer>
double cullingSample(const Tracer& t, const Segment& s, ProxyClass cls, RayCounts& counts) {
  if (cls == ProxyClass::kGeneral) return exactSample(t, s, counts);
  ++counts.proxy;
  const bool vp = t.proxyVisible(s);
  if (cls == ProxyClass::kOutside && vp) return 1.0;
  if (cls == ProxyClass::kInside && !vp) return 0.0;
  return exactSample(t, s, counts);
}

// The paper's selection estimator (selection.h): u picks the branch.
template <class Tracer>
double selectionSample(const Tracer& t, const Segment& s, const SelectionProbabilities& p, double u,
                       RayCounts& counts) {
  ++counts.proxy;
  const bool vp = t.proxyVisible(s);
  if (u < p.p0) return vp ? 1.0 / p.p0 : 0.0;
  if (u < p.p0 + p.p_plus) {  // MH' correction: V (1 - V') / p+
    if (vp) return 0.0;
    return exactSample(t, s, counts) / p.p_plus;
  }
  if (p.p_minus <= 0) return 0.0;  // rounding put u past p0 + p+ with no p- branch
  if (!vp) return 0.0;             // HM' correction: -V' (1 - V) / p-
  return -(1.0 - exactSample(t, s, counts)) / p.p_minus;
}

// Roulette (roulette.h). Also reports what it saw, for learning: `proxy_visible` = V', and
// `traced_original` / `original_visible` when the correction was traced.
struct RouletteOutcome {
  double estimate = 0;
  bool proxy_visible = false, traced_original = false, original_visible = false;
};

template <class Tracer>
RouletteOutcome rouletteSample(const Tracer& t, const Segment& s, const RouletteQ& q, double u,
                               RayCounts& counts) {
  RouletteOutcome o;
  ++counts.proxy;
  o.proxy_visible = t.proxyVisible(s);
  const double qi = o.proxy_visible ? q.q1 : q.q0;
  o.estimate = o.proxy_visible ? 1.0 : 0.0;
  if (u < qi) {
    o.traced_original = true;
    o.original_visible = exactSample(t, s, counts) > 0;
    if (o.proxy_visible)
      o.estimate = 1.0 - (o.original_visible ? 0.0 : 1.0) / qi;
    else
      o.estimate = (o.original_visible ? 1.0 : 0.0) / qi;
  }
  return o;
}

}  // namespace proxyvis
