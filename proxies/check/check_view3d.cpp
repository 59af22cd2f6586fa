#include "proxies/check/check_view3d.h"

#include <fmt/core.h>

#include <nlohmann/json.hpp>

#include "proxies/check/check_report.h"
#include "view3d/view3d_html.h"

namespace proxyvis {

std::optional<ProxyClass> claimedClass(const PairCheckReport& r) {
  if (r.expected) return r.expected;
  const ProxyClass proven = provenClass(r);
  if (proven != ProxyClass::kGeneral) return proven;
  if (r.sampled_class == SampledClass::kOutside) return ProxyClass::kOutside;
  if (r.sampled_class == SampledClass::kInside) return ProxyClass::kInside;
  return std::nullopt;
}

namespace {

View3dCheck::ClassRate classRate(uint64_t count, const RateEstimate& e) {
  return {count, e.n == 0 ? 0.0 : e.value, rateLower(e), rateUpper(e)};
}

View3dCheck::Mesh meshOf(const MeshSummary& m) {
  return {m.source, m.closed};
}

// What the page's tables show of the report.
View3dCheck viewOf(const PairCheckReport& r) {
  const ClassCounts& c = r.sampled.counts;
  View3dCheck v;
  v.classes = {classRate(c.hh, r.stats.hh), classRate(c.hm, r.stats.hm),
               classRate(c.mh, r.stats.mh), classRate(c.mm, r.stats.mm)};
  v.proven_class = proxyClassName(provenClass(r));
  v.proven_class_note =
      "the class the exact check proves: outside when the proxy contains the original, inside "
      "when it is contained in it, otherwise general";
  v.sampled_class = sampledClassName(r.sampled_class);
  if (const std::optional<MissedClassBound> b = missedClassBound(r))
    v.missed_class_bound = std::pair<std::string, double>(b->name, b->upper);
  v.exact = containmentName(r.exact.verdict);
  v.exact_detail = r.exact.detail;
  if (r.expected) {
    v.expect = proxyClassName(*r.expected);
    v.contradiction = r.contradiction;
  }
  v.mismatch = r.mismatch;
  v.ok = !r.failed();
  v.original = meshOf(r.original);
  v.proxy = meshOf(r.proxy);
  return v;
}

}  // namespace

std::string checkReportHtml(const TriMesh& original, const TriMesh& proxy,
                            const PairCheckReport& r) {
  const std::optional<ProxyClass> claim = claimedClass(r);
  View3dPage page;
  page.title = fmt::format("proxy-check: {} against {}", proxy.source, original.source);
  page.original = &original;
  page.proxy = &proxy;
  page.claim = claim ? proxyClassName(*claim) : "";
  View3dSegmentLayer hm{.id = "hm",
                        .label = "HM' segments",
                        .meaning = "original blocks, proxy misses",
                        .color = "#d62728",
                        .counted = r.sampled.counts.hm,
                        .breaks_claim = claim == ProxyClass::kOutside,
                        .visible = claim != ProxyClass::kInside,
                        .segments = {}};
  View3dSegmentLayer mh{.id = "mh",
                        .label = "MH' segments",
                        .meaning = "original misses, proxy blocks",
                        .color = "#1f77b4",
                        .counted = r.sampled.counts.mh,
                        .breaks_claim = claim == ProxyClass::kInside,
                        .visible = claim != ProxyClass::kOutside,
                        .segments = {}};
  for (const ErrorSegment& e : r.sampled.errors) (e.hm ? hm : mh).segments.emplace_back(e.a, e.b);
  page.layers = {std::move(hm), std::move(mh)};
  page.check = viewOf(r);
  page.json = toJson(r);
  page.json["class"] = page.check.proven_class;
  page.json["class_note"] = page.check.proven_class_note;
  return view3dHtml(page);
}

}  // namespace proxyvis
