#include "estimate/class_probabilities.h"

#include "util/error.h"

namespace proxyvis {

double ClassProbabilities::fHit() const {
  const double hit = hh + hm;
  return hit > 0 ? hh / hit : 1.0;
}

double ClassProbabilities::fMiss() const {
  const double miss = mh + mm;
  return miss > 0 ? mm / miss : 1.0;
}

double ClassProbabilities::errorGivenProxyBlocked() const {
  const double b = proxyBlocked();
  return b > 0 ? mh / b : 0.0;
}

double ClassProbabilities::errorGivenProxyVisible() const {
  const double v = proxyVisible();
  return v > 0 ? hm / v : 0.0;
}

bool classPossible(ProxyClass c, bool original_visible, bool proxy_visible) {
  if (c == ProxyClass::kOutside && !original_visible && proxy_visible) return false;  // HM'
  if (c == ProxyClass::kInside && original_visible && !proxy_visible) return false;   // MH'
  return true;
}

void ClassCounts::add(bool original_visible, bool proxy_visible) {
  if (original_visible)
    ++(proxy_visible ? mm : mh);
  else
    ++(proxy_visible ? hm : hh);
}

ClassProbabilities estimateClassProbabilities(const ClassCounts& counts, ProxyClass c,
                                              double prior) {
  PV_CHECK(prior > 0);
  auto weight = [&](uint64_t n, bool v, bool vp) {
    return classPossible(c, v, vp) ? double(n) + prior : 0.0;
  };
  ClassProbabilities p{weight(counts.hh, false, false), weight(counts.hm, false, true),
                       weight(counts.mh, true, false), weight(counts.mm, true, true)};
  const double sum = p.hh + p.hm + p.mh + p.mm;
  p.hh /= sum;
  p.hm /= sum;
  p.mh /= sum;
  p.mm /= sum;
  return p;
}

}  // namespace proxyvis
