#pragma once
// The class proxy-gen writes for a proxy. A class is a promise about the INPUT mesh: an inside
// proxy is hit by no segment that misses the input, an outside proxy misses no segment that hits
// it. A proxy verified against a stand-in for the input (the input with its holes filled) keeps no
// such promise, since rays pass through the holes, and is written as class general with the
// reason (docs/proxy_classes.md).
#include <optional>
#include <string>

#include "proxies/pipeline/proxy_report.h"
#include "util/proxy_class.h"

namespace proxyvis {

// Why the mesh the proxy was verified against is not the input ("the input has 56 boundary
// edges; ..."), for --fill-holes: the proxy is verified inside the filled mesh only.
std::string filledHolesReason(uint64_t boundary_edges, uint64_t holes_filled);

// Sets the report's class: none when not verified; the kind asked for when verified against the
// input itself; general with class_reason = `stand_in` when verified only against a stand-in for
// the input.
void setWrittenClass(ProxyReport& report, ProxyClass kind, bool verified,
                     const std::optional<std::string>& stand_in);

}  // namespace proxyvis
