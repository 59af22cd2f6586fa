#pragma once
// A SegmentTracer without geometry: the segment's org encodes (mix, index) and its classes
// (V, V') are drawn from mixes[mix] with a stream keyed on (seed, mix, index), so a segment's
// answer is fixed and independent of call order. Lets the tests set the class probabilities
// exactly and compare estimators with closed forms.
#include <cstdint>
#include <vector>

#include "estimate/class_probabilities.h"
#include "estimate/visibility_estimator.h"
#include "util/rng.h"

namespace proxyvis::test {

class SyntheticTracer final : public SegmentTracer {
 public:
  SyntheticTracer(std::vector<ClassProbabilities> mixes, uint64_t seed)
      : mixes_(std::move(mixes)), seed_(seed) {}

  // index < 2^48 (two exactly representable 24-bit floats).
  static Segment segment(uint32_t mix, uint64_t index) {
    Segment s;
    s.org = Vec3f(float(index & 0xffffff), float(mix), float(index >> 24));
    s.dir = Vec3f(0, 0, 1);
    return s;
  }

  struct Classes {
    bool v, vp;
  };
  Classes classes(const Segment& s) const {
    const uint32_t mix = uint32_t(s.org.y);
    const uint64_t index = uint64_t(s.org.x) | (uint64_t(s.org.z) << 24);
    const ClassProbabilities& p = mixes_.at(mix);
    // Keyed on an index no estimator stream uses: util/rng.h streams that share an index but
    // differ in seed are correlated (same PCG increment, states a constant apart).
    const double u = Rng(seed_, hashKeys(0x7ace5eed, mix, index)).uniformDouble();
    if (u < p.hh) return {false, false};
    if (u < p.hh + p.hm) return {false, true};
    if (u < p.hh + p.hm + p.mh) return {true, false};
    return {true, true};
  }
  bool proxyVisible(const Segment& s) const override { return classes(s).vp; }
  bool originalVisible(const Segment& s) const override { return classes(s).v; }

 private:
  std::vector<ClassProbabilities> mixes_;
  uint64_t seed_;
};

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
