// RenderResult's numbers as JSON (renderer.h), read back through util/json_field.h.
#include <nlohmann/json.hpp>

#include "render/renderer.h"
#include "util/json_field.h"

namespace proxyvis {

void to_json(nlohmann::json& j, const RenderResult& r) {
  j = {{"spp", r.spp},
       {"passes", r.passes},
       {"seconds", r.seconds},
       {"cpu_seconds", r.cpu_seconds},
       {"shading_seconds", r.shading_seconds},
       {"primary_seconds", r.primary_seconds},
       {"visibility_seconds", r.visibility_seconds},
       {"rays", {r.rays.proxy, r.rays.original, r.rays.probe}},
       {"primary_rays", r.primary_rays},
       {"shadow_segments", r.shadow_segments},
       {"proxy_class", r.proxy_class},
       {"learned", r.learned}};
}

void from_json(const nlohmann::json& j, RenderResult& r) {
  const JsonField f(j);
  r.spp = f["spp"].asInt();
  r.passes = f["passes"].asInt();
  r.seconds = f["seconds"].asDouble();
  r.cpu_seconds = f["cpu_seconds"].asDouble();
  r.shading_seconds = f["shading_seconds"].asDouble();
  r.primary_seconds = f["primary_seconds"].asDouble();
  r.visibility_seconds = f["visibility_seconds"].asDouble();
  const JsonField rays = f["rays"];
  if (rays.arraySize() != 3) rays.fail("expected 3 counts: proxy, original, probe");
  r.rays.proxy = rays[size_t(0)].asUint64();
  r.rays.original = rays[1].asUint64();
  r.rays.probe = rays[2].asUint64();
  r.primary_rays = f["primary_rays"].asUint64();
  r.shadow_segments = f["shadow_segments"].asUint64();
  r.proxy_class = f["proxy_class"].get<ProxyClass>();
  r.learned = f["learned"].get<LearnedSummary>();
}

}  // namespace proxyvis
