#pragma once
// The four visibility classes of shadow segments against an original P and a proxy P'
// (docs/design.md): HH' (both block), HM' (P blocks, P' misses), MH' (P misses, P' blocks),
// MM' (both miss), what the estimators derive from their counts, and the proxy class they show.
#include <cstdint>
#include <optional>
#include <string>

#include "proxies/check/containment.h"
#include "util/proxy_class.h"
#include "util/stats.h"

namespace proxyvis {

struct ClassCounts {
  uint64_t hh = 0, hm = 0, mh = 0, mm = 0;
  uint64_t total() const { return hh + hm + mh + mm; }
  ClassCounts& operator+=(const ClassCounts& o) {
    hh += o.hh, hm += o.hm, mh += o.mh, mm += o.mm;
    return *this;
  }
  bool operator==(const ClassCounts&) const = default;
};

// A proportion k/n with its Wilson interval. n = 0 means "not estimable": value 0, [0, 1].
struct RateEstimate {
  uint64_t k = 0, n = 0;
  double value = 0;
  Interval ci{0, 1};
};

RateEstimate estimateRate(uint64_t k, uint64_t n, double z = 1.959963984540054);

// Everything derived from the counts, each with a Wilson interval at the same z (95 % default).
struct ClassStats {
  RateEstimate hh, hm, mh, mm;  // fractions of all segments
  RateEstimate v_avg;           // P(V = 1) = (MH' + MM') / N
  RateEstimate f_hit;           // HH' / (HH' + HM')   (P(V'=0 | V=0))
  RateEstimate f_miss;          // MM' / (MH' + MM')   (P(V'=1 | V=1))
  RateEstimate error_given_v0;  // P(error | V'=0) = MH' / (HH' + MH')
  RateEstimate error_given_v1;  // P(error | V'=1) = HM' / (HM' + MM')
  RateEstimate error;           // (HM' + MH') / N
  // The rates that cost a data-parallel renderer (docs/data_parallel.md) messages: an outside
  // proxy hit by a segment that misses the original sends a forward for nothing; an inside proxy
  // missed by a segment that hits the original fails to save one.
  RateEstimate wasted_forward;  // P(hit proxy | miss original) = MH' / (MH' + MM') = 1 - f_miss
  RateEstimate missed_block;    // P(miss proxy | hit original) = HM' / (HH' + HM') = 1 - f_hit
};

ClassStats deriveStats(const ClassCounts& c, double z = 1.959963984540054);

// What the segments show: outside = no HM' seen, inside = no MH' seen, general = both seen,
// equivalent = neither seen (proxy and original agree on every segment).
enum class SampledClass { kOutside, kInside, kGeneral, kEquivalent };
const char* sampledClassName(SampledClass c);
SampledClass sampledClass(const ClassCounts& c);

// The sampled class contradicts the exact verdict when the verdict rules out an error class
// that the segments show: `contains` rules out HM', `contained` rules out MH'. Such a
// contradiction means a tracing or tolerance bug (or a segment end inside the proxy, docs/design.md
// pitfall 2). Returns the explanation, or nothing when they agree.
std::optional<std::string> sampledExactMismatch(const ClassCounts& c, ContainmentVerdict exact);

// Does the evidence contradict the expected class? outside: any HM' seen, or a decidable exact
// verdict other than `contains`; inside: any MH' seen, or a decidable verdict other than
// `contained`; general: never (every proxy may be used as a general one). Returns the reason.
std::optional<std::string> contradictsExpectation(ProxyClass expected, const ClassCounts& c,
                                                  ContainmentVerdict exact);

}  // namespace proxyvis
