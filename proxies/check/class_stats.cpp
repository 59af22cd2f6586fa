#include "proxies/check/class_stats.h"

#include <fmt/core.h>

namespace proxyvis {

RateEstimate estimateRate(uint64_t k, uint64_t n, double z) {
  RateEstimate r;
  r.k = k;
  r.n = n;
  if (n == 0) return r;
  r.value = double(k) / double(n);
  r.ci = wilsonInterval(k, n, z);
  return r;
}

ClassStats deriveStats(const ClassCounts& c, double z) {
  const uint64_t n = c.total();
  ClassStats s;
  s.hh = estimateRate(c.hh, n, z);
  s.hm = estimateRate(c.hm, n, z);
  s.mh = estimateRate(c.mh, n, z);
  s.mm = estimateRate(c.mm, n, z);
  s.v_avg = estimateRate(c.mh + c.mm, n, z);
  s.f_hit = estimateRate(c.hh, c.hh + c.hm, z);
  s.f_miss = estimateRate(c.mm, c.mh + c.mm, z);
  s.error_given_v0 = estimateRate(c.mh, c.hh + c.mh, z);
  s.error_given_v1 = estimateRate(c.hm, c.hm + c.mm, z);
  s.error = estimateRate(c.hm + c.mh, n, z);
  s.wasted_forward = estimateRate(c.mh, c.mh + c.mm, z);
  s.missed_block = estimateRate(c.hm, c.hh + c.hm, z);
  return s;
}

const char* sampledClassName(SampledClass c) {
  switch (c) {
    case SampledClass::kOutside:
      return "outside";
    case SampledClass::kInside:
      return "inside";
    case SampledClass::kGeneral:
      return "general";
    case SampledClass::kEquivalent:
      return "equivalent";
  }
  return "general";
}

SampledClass sampledClass(const ClassCounts& c) {
  if (c.hm == 0 && c.mh == 0) return SampledClass::kEquivalent;
  if (c.hm == 0) return SampledClass::kOutside;
  if (c.mh == 0) return SampledClass::kInside;
  return SampledClass::kGeneral;
}

std::optional<std::string> sampledExactMismatch(const ClassCounts& c, ContainmentVerdict exact) {
  if (exact == ContainmentVerdict::kContains && c.hm > 0)
    return fmt::format(
        "the proxy exactly contains the original, yet {} segments hit the original and miss the "
        "proxy (HM'): a tracing or tolerance bug, or segment ends inside the proxy",
        c.hm);
  if (exact == ContainmentVerdict::kContained && c.mh > 0)
    return fmt::format(
        "the proxy lies exactly inside the original, yet {} segments miss the original and hit "
        "the proxy (MH'): a tracing or tolerance bug, or segment ends inside the original",
        c.mh);
  return std::nullopt;
}

std::optional<std::string> contradictsExpectation(ProxyClass expected, const ClassCounts& c,
                                                  ContainmentVerdict exact) {
  const bool decidable = exact != ContainmentVerdict::kUndecidable;
  switch (expected) {
    case ProxyClass::kOutside:
      if (c.hm > 0) return fmt::format("{} HM' segments (hit the original, miss the proxy)", c.hm);
      if (decidable && exact != ContainmentVerdict::kContains)
        return fmt::format("exact check: {}, not contains", containmentName(exact));
      return std::nullopt;
    case ProxyClass::kInside:
      if (c.mh > 0) return fmt::format("{} MH' segments (miss the original, hit the proxy)", c.mh);
      if (decidable && exact != ContainmentVerdict::kContained)
        return fmt::format("exact check: {}, not contained", containmentName(exact));
      return std::nullopt;
    case ProxyClass::kGeneral:
      return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace proxyvis
