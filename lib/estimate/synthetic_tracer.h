#pragma once
// A SegmentTracer without geometry, for tests and bench_estimators: the segment's org encodes
// (mix, index) and its classes (V, V') are drawn from mixes[mix] with a stream keyed on
// (seed, mix, index), so a segment's answer is fixed and independent of call order. Lets tests
// set the class probabilities exactly and compare estimators with closed forms. Optionally
// charges every ray its class cost (ClassCosts by V') to a counter, for cost measurements in
// model units; that counter is not thread-safe, so only a single-threaded caller may set costs.
#include <cstdint>
#include <optional>
#include <vector>

#include "estimate/class_probabilities.h"
#include "estimate/roulette.h"
#include "estimate/visibility_estimator.h"
#include "util/rng.h"

namespace proxyvis {

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
  bool proxyVisible(const Segment& s) const override {
    const Classes c = classes(s);
    if (costs_) spent_ += costs_->proxy[c.vp];
    return c.vp;
  }
  bool originalVisible(const Segment& s) const override {
    const Classes c = classes(s);
    if (costs_) spent_ += costs_->original[c.vp];
    return c.v;
  }

  // Charge rays from now on (single-threaded use only); spent() is the sum so far.
  void chargeCosts(const ClassCosts& costs) { costs_ = costs; }
  double spent() const { return spent_; }

 private:
  std::vector<ClassProbabilities> mixes_;
  uint64_t seed_;
  std::optional<ClassCosts> costs_;
  mutable double spent_ = 0;
};

}  // namespace proxyvis
