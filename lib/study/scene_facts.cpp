#include "study/scene_facts.h"

#include <nlohmann/json.hpp>

#include "render/render_scene.h"
#include "util/json_field.h"

namespace proxyvis {

SceneFacts sceneFacts(const RenderScene& scene) {
  SceneFacts f;
  f.proxy_class = scene.proxyClass();
  f.uses_proxies = scene.usesProxies();
  f.instances_flattened = scene.instancesFlattened();
  f.build = scene.buildChoice().name();
  f.build_reason = scene.buildChoice().reason;
  f.build_description = scene.buildChoice().description();
  f.original_triangles = scene.originalTriangles();
  f.proxy_triangles = scene.proxyTriangles();
  f.warnings = scene.warnings();
  return f;
}

void to_json(nlohmann::json& j, const ProxyClassRecord& r) {
  j = {{"mesh", r.mesh},
       {"proxy", r.proxy},
       {"claimed", r.claimed},
       {"class", r.proxy_class},
       {"class_status", r.class_status},
       {"reason", r.reason}};
}

void from_json(const nlohmann::json& j, ProxyClassRecord& r) {
  const JsonField f(j);
  r.mesh = f["mesh"].asString();
  r.proxy = f["proxy"].asString();
  r.claimed = f["claimed"].asString();
  r.proxy_class = f["class"].asString();
  r.class_status = f["class_status"].asString();
  r.reason = f["reason"].asString();
}

void to_json(nlohmann::json& j, const SceneFacts& f) {
  j = {{"proxy_class", f.proxy_class},
       {"uses_proxies", f.uses_proxies},
       {"instances_flattened", f.instances_flattened},
       {"build", f.build},
       {"build_reason", f.build_reason},
       {"build_description", f.build_description},
       {"original_triangles", f.original_triangles},
       {"proxy_triangles", f.proxy_triangles},
       {"warnings", f.warnings},
       {"proxy_classes", f.proxy_classes},
       {"trust_notes", f.trust_notes}};
}

void from_json(const nlohmann::json& j, SceneFacts& f) {
  const JsonField in(j);
  f.proxy_class = in["proxy_class"].get<ProxyClass>();
  f.uses_proxies = in["uses_proxies"].asBool();
  f.instances_flattened = in["instances_flattened"].asBool();
  f.build = in["build"].asString();
  f.build_reason = in["build_reason"].asString();
  f.build_description = in["build_description"].asString();
  f.original_triangles = in["original_triangles"].asUint64();
  f.proxy_triangles = in["proxy_triangles"].asUint64();
  f.warnings = in["warnings"].asStrings();
  f.proxy_classes = in["proxy_classes"].getList<ProxyClassRecord>();
  f.trust_notes = in["trust_notes"].asStrings();
}

}  // namespace proxyvis
