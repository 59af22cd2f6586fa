#pragma once
// The paper's selection estimator (Billen et al. 2014, §4) and its probabilities, with the
// variance corrected as in docs/design.md. Per light sample, pick one term:
//   with p0:  V' / p0                     (proxy term; traces the proxy)
//   with p+:  V (1 - V') / p+             (MH' correction; proxy first, original only if V' = 0)
//   with p-: -V' (1 - V) / p-             (HM' correction; proxy first, original only if V' = 1)
// E = V' + P(MH') - P(HM') = V for any p with p+ > 0 where MH' is possible and p- > 0 where HM'
// is possible.
#include "estimate/class_probabilities.h"

namespace proxyvis {

struct SelectionProbabilities {
  double p0 = 1, p_plus = 0, p_minus = 0;  // sum to 1
};

// Var = [(1-V)(1-f_hit) + V f_miss]/p0 + V(1-f_miss)/p+ + (1-V)(1-f_hit)/p- - V^2, V = V_avg;
// i.e. (P(HM')+P(MM'))/p0 + P(MH')/p+ + P(HM')/p- - V^2. A term whose numerator is 0 contributes
// 0 even when its p is 0; a positive numerator over p = 0 gives +infinity (the estimator is
// biased then, not merely noisy).
double selectionVariance(const ClassProbabilities& c, const SelectionProbabilities& p);

// DOCUMENTATION ONLY, WRONG: the talk slides print the HM' term over p+ instead of p-:
//   [(1-V)(1-f_hit) + V f_miss]/p0 + V(1-f_miss)/p+ + (1-V)(1-f_hit)/p+ - V^2.
// Kept so a test can show Monte Carlo rejects it (tests/estimate/selection_test.cpp).
double selectionVarianceSlideMisprint(const ClassProbabilities& c, const SelectionProbabilities& p);

// Expected rays per sample: proxy rays (always 1) and original rays (p+ P(V'=0) + p- P(V'=1)).
struct SelectionRays {
  double proxy = 1, original = 0;
};
SelectionRays selectionRays(const ClassProbabilities& c, const SelectionProbabilities& p);

// paper-equal: 1/3 each; a branch that a verified class makes useless (p- for outside, p+ for
// inside) is dropped and the others renormalised to 1/2.
SelectionProbabilities equalProbabilities(ProxyClass c);

// paper-optimal: minimises selectionVariance: p_i proportional to sqrt(a_i), a0 = P(HM')+P(MM'),
// a+ = P(MH'), a- = P(HM') (Lagrange: d/dp_i (a_i/p_i) = -lambda). Branches the verified class
// excludes get 0. If every a_i is 0, returns p0 = 1.
SelectionProbabilities optimalProbabilities(const ClassProbabilities& c, ProxyClass cls);

// paper-cost: the paper's heuristic p'+- = error^(1/4) p+-, p'0 = 1 - p'+ - p'-, where error is
// the fraction of probe rays with V != V' (the caller smooths it: error = 0 would drop the
// correction branches and bias the estimate).
SelectionProbabilities costHeuristicProbabilities(const SelectionProbabilities& optimal,
                                                  double error);

}  // namespace proxyvis
