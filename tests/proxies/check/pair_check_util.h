#pragma once
// The pair check as the proxy-check tests run it: enough rays for stable sampled classes on the
// tiny and bundled meshes, fewer distance samples than the app's default, no progress output.
#include <cstdint>

#include "proxies/check/pair_check.h"

namespace proxyvis::test {

inline PairCheckOptions testCheckOptions(uint64_t seed) {
  PairCheckOptions o;
  o.rays = 200'000;
  o.seed = seed;
  o.quiet = true;
  o.distance_samples = 2000;
  return o;
}

inline PairCheckReport testCheckPair(const TriMesh& original, const TriMesh& proxy, uint64_t seed) {
  return checkPair(original, proxy, testCheckOptions(seed));
}

}  // namespace proxyvis::test
