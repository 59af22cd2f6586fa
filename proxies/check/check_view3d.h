#pragma once
// proxy-check's HTML page (--html): the classification and an interactive 3D view of original,
// proxy and the error segments (lib/view3d, docs/report_3d.md).
#include <optional>
#include <string>

#include "mesh/tri_mesh.h"
#include "proxies/check/pair_check.h"
#include "util/proxy_class.h"

namespace proxyvis {

// The class the page is about: the --expect class when given, else the class the exact check
// proves (outside, inside), else the sampled class when it is outside or inside; nullopt when
// none is claimed (general, equivalent).
std::optional<ProxyClass> claimedClass(const PairCheckReport& report);

// The page for one checked pair. Its layers: HM' segments (red; they break an outside claim) and
// MH' segments (blue; they break an inside claim), each with the count the check made and the
// kept segments of report.sampled.errors; the layer that breaks the claim is on, the other off.
// The tables show the report's verdicts, classes and meshes (View3dCheck); below the view,
// toJson(report) plus "class" (provenClass) and "class_note".
std::string checkReportHtml(const TriMesh& original, const TriMesh& proxy,
                            const PairCheckReport& report);

}  // namespace proxyvis
