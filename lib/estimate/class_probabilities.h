#pragma once
// The four ray classes of docs/design.md and the quantities the paper derives from them.
// Billen, Lagae, Dutre, "Probabilistic Visibility Estimation using Geometry Proxies", CGF 33(4)
// (EGSR 2014). V = visibility against the original, V' = against the proxy (1 = unoccluded):
//   HH' (V=0,V'=0), HM' (V=0,V'=1), MH' (V=1,V'=0), MM' (V=1,V'=1).
#include <cstdint>

#include "util/proxy_class.h"

namespace proxyvis {

struct ClassProbabilities {
  double hh = 0, hm = 0, mh = 0, mm = 0;  // sum to 1

  double vAvg() const { return mh + mm; }          // P(V = 1)
  double proxyVisible() const { return hm + mm; }  // P(V' = 1)
  double proxyBlocked() const { return hh + mh; }  // P(V' = 0)
  double error() const { return hm + mh; }         // P(V != V')
  // f_hit = P(HH') / (P(HH') + P(HM')); 1 when the original is never hit (nothing to miss).
  double fHit() const;
  // f_miss = P(MM') / (P(MH') + P(MM')); 1 when the original is never missed.
  double fMiss() const;
  // P(V != V' | V' = i); 0 where P(V' = i) = 0.
  double errorGivenProxyBlocked() const;
  double errorGivenProxyVisible() const;
};

// Classes a proxy of class `c` can produce: outside proxies never give HM', inside ones never MH'.
bool classPossible(ProxyClass c, bool original_visible, bool proxy_visible);

struct ClassCounts {
  uint64_t hh = 0, hm = 0, mh = 0, mm = 0;
  uint64_t total() const { return hh + hm + mh + mm; }
  void add(bool original_visible, bool proxy_visible);
};

// Posterior mean under a symmetric Dirichlet prior of `prior` pseudo-counts on every class the
// proxy class allows (0 on the impossible ones), so no probability of a possible class is 0 even
// when it was never observed. prior must be > 0.
ClassProbabilities estimateClassProbabilities(const ClassCounts& counts, ProxyClass c,
                                              double prior);

}  // namespace proxyvis
