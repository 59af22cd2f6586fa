#pragma once
// What the report says about the loaded scene. Every unit result records it, so the merge needs
// no scene loading (only the scene description, for image metadata).
#include <cstdint>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "util/proxy_class.h"

namespace proxyvis {

class RenderScene;

// One proxy's class status (proxies/check/class_trust.h), as the report's meta.proxy_classes
// lists it.
struct ProxyClassRecord {
  std::string mesh;          // the mesh's name
  std::string proxy;         // the proxy file's name
  std::string claimed;       // the class its file claims, or "none"
  std::string proxy_class;   // JSON "class": the class the renderer relies on
  std::string class_status;  // classStatusName()
  std::string reason;

  bool operator==(const ProxyClassRecord&) const = default;
};

struct SceneFacts {
  ProxyClass proxy_class = ProxyClass::kGeneral;
  bool uses_proxies = false;
  bool instances_flattened = false;
  // The BVH build every render used (RenderScene::buildChoice()): name, reason, description.
  std::string build, build_reason, build_description;
  uint64_t original_triangles = 0, proxy_triangles = 0;
  std::vector<std::string> warnings;
  std::vector<ProxyClassRecord> proxy_classes;  // report.meta.proxy_classes
  std::vector<std::string> trust_notes;  // one per proxy whose claimed class was not taken as is

  bool operator==(const SceneFacts&) const = default;
};

// The facts of the loaded scene; the proxies' class records and notes are the caller's (they
// come from proxies/check's trust decisions).
SceneFacts sceneFacts(const RenderScene& scene);

// {"mesh", "proxy", "claimed", "class", "class_status", "reason"}.
void to_json(nlohmann::json& j, const ProxyClassRecord& r);
void from_json(const nlohmann::json& j, ProxyClassRecord& r);
// {"proxy_class" (its name), "uses_proxies", "instances_flattened", "build", "build_reason",
// "build_description", "original_triangles", "proxy_triangles", "warnings", "proxy_classes",
// "trust_notes"}.
void to_json(nlohmann::json& j, const SceneFacts& f);
void from_json(const nlohmann::json& j, SceneFacts& f);

}  // namespace proxyvis
