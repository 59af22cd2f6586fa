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
  page.summary = toJson(r);
  page.summary["class"] = proxyClassName(provenClass(r));
  page.summary["class_note"] =
      "the class the exact check proves: outside when the proxy contains the original, inside "
      "when it is contained in it, otherwise general";
  return view3dHtml(page);
}

}  // namespace proxyvis
