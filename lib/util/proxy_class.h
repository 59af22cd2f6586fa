#pragma once
#include <optional>
#include <string>

namespace proxyvis {

// Class of a proxy relative to its original (docs/design.md): outside = contains it (no HM'
// rays), inside = contained in it (no MH' rays), general = both error kinds possible.
enum class ProxyClass { kOutside, kInside, kGeneral };

inline const char* proxyClassName(ProxyClass c) {
  return c == ProxyClass::kOutside ? "outside" : c == ProxyClass::kInside ? "inside" : "general";
}
inline std::optional<ProxyClass> parseProxyClass(const std::string& s) {
  if (s == "outside") return ProxyClass::kOutside;
  if (s == "inside") return ProxyClass::kInside;
  if (s == "general") return ProxyClass::kGeneral;
  return std::nullopt;
}

}  // namespace proxyvis
