#pragma once
#include <cstdint>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>

namespace proxyvis {

// Class of a proxy relative to its original (docs/design.md): outside = contains it (no HM'
// rays), inside = contained in it (no MH' rays), general = both error kinds possible.
enum class ProxyClass { kOutside, kInside, kGeneral };

// The largest face budget a proxy may be given: proxy-gen's --max-faces and --min-faces, and a
// scene mesh's "proxy_max_faces".
inline constexpr uint64_t kMaxFacesLimit = 1'000'000'000;

inline const char* proxyClassName(ProxyClass c) {
  return c == ProxyClass::kOutside ? "outside" : c == ProxyClass::kInside ? "inside" : "general";
}
inline std::optional<ProxyClass> parseProxyClass(const std::string& s) {
  if (s == "outside") return ProxyClass::kOutside;
  if (s == "inside") return ProxyClass::kInside;
  if (s == "general") return ProxyClass::kGeneral;
  return std::nullopt;
}

// The class as its name; from_json refuses any other text (util/json_field.h's error).
void to_json(nlohmann::json& j, ProxyClass c);
void from_json(const nlohmann::json& j, ProxyClass& c);

}  // namespace proxyvis
