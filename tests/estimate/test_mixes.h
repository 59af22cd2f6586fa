#pragma once
// Class mixes and seeds shared by the estimate tests.
#include "estimate/synthetic_tracer.h"

namespace proxyvis::test {

// The tracer's own seed, apart from every estimator stream of a test keyed on `seed`.
inline uint64_t tracerSeed(uint64_t seed, uint64_t k) {
  return hashKeys(seed, 0x7ace5eed, k);
}

// Class mixes used throughout, one per proxy class (outside: no HM'; inside: no MH').
inline ClassProbabilities outsideMix() {
  return {0.30, 0.00, 0.15, 0.55};
}
inline ClassProbabilities insideMix() {
  return {0.35, 0.12, 0.00, 0.53};
}
inline ClassProbabilities generalMix() {
  return {0.30, 0.08, 0.10, 0.52};
}
inline ClassProbabilities mixFor(ProxyClass c) {
  return c == ProxyClass::kOutside  ? outsideMix()
         : c == ProxyClass::kInside ? insideMix()
                                    : generalMix();
}

}  // namespace proxyvis::test
