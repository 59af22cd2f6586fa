#pragma once
// Random numbers keyed on (seed, index) so that every pixel, ray or sample has its own stream and
// results do not depend on the thread count (pbrt samplers.h: SetSequence(Hash(p, seed))).
// PCG32 by M.E. O'Neill, "PCG: A Family of Simple Fast Space-Efficient Statistically Good
// Algorithms for Random Number Generation" (2014).
#include <cstdint>

namespace proxyvis {

// SplitMix64 finaliser: a strong 64-bit mix, used to turn (seed, index...) into stream keys.
constexpr uint64_t mixBits(uint64_t v) {
  v ^= v >> 31;
  v *= 0x7fb5d329728ea185ULL;
  v ^= v >> 27;
  v *= 0x81dadef4bc2dd44dULL;
  v ^= v >> 33;
  return v;
}

constexpr uint64_t hashKeys(uint64_t a, uint64_t b) {
  return mixBits(a * 0x9e3779b97f4a7c15ULL ^ mixBits(b + 0x632be59bd9b4e019ULL));
}
constexpr uint64_t hashKeys(uint64_t a, uint64_t b, uint64_t c) {
  return hashKeys(hashKeys(a, b), c);
}

class Rng {
 public:
  Rng() { setSequence(0, 0); }
  // Stream `index` of generator `seed`; distinct (seed, index) pairs give independent streams.
  Rng(uint64_t seed, uint64_t index) { setSequence(seed, index); }
  // The stream Rng(seed, hashKeys(a, b, c)), set up on the first draw: a caller that may draw
  // nothing (the renderer hands every query a stream; exact visibility never draws) pays no
  // hashing.
  static Rng deferred(uint64_t seed, uint64_t a, uint64_t b, uint64_t c) {
    Rng r(Pending{});
    r.state_ = seed;
    r.key_[0] = a, r.key_[1] = b, r.key_[2] = c;
    return r;
  }

  void setSequence(uint64_t seed, uint64_t index) {
    // Both the increment and the start state depend on the seed and the index: with the
    // increment keyed on the index alone, stream i of two seeds differed only by a state offset
    // and their outputs were measurably correlated.
    pending_ = false;
    state_ = 0u;
    inc_ = (hashKeys(index, seed ^ 0xda3e39cb94b95bdbULL) << 1u) | 1u;
    nextU32();
    state_ += hashKeys(seed + 0x853c49e6748fea9bULL, index);
    nextU32();
  }

  uint32_t nextU32() {
    if (pending_) [[unlikely]] {
      pending_ = false;
      setSequence(state_, hashKeys(key_[0], key_[1], key_[2]));
    }
    uint64_t old = state_;
    state_ = old * 0x5851f42d4c957f2dULL + inc_;
    uint32_t xorshifted = uint32_t(((old >> 18u) ^ old) >> 27u);
    uint32_t rot = uint32_t(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((~rot + 1u) & 31));
  }

  // Uniform in [0, 1): 24 random bits, never rounds up to 1.
  float uniformFloat() { return float(nextU32() >> 8) * 0x1p-24f; }
  // Uniform in [0, 1) with 53 random bits.
  double uniformDouble() {
    uint64_t hi = nextU32(), lo = nextU32();
    return double(((hi << 32) | lo) >> 11) * 0x1p-53;
  }

 private:
  struct Pending {};
  explicit Rng(Pending) : pending_(true) {}
  uint64_t state_ = 0, inc_ = 1;
  uint64_t key_[3] = {0, 0, 0};  // deferred: hashKeys arguments (state_ holds the seed)
  bool pending_ = false;
};

}  // namespace proxyvis
