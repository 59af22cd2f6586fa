#include "proxies/pipeline/written_class.h"

#include <fmt/core.h>

namespace proxyvis {

std::string filledHolesReason(uint64_t boundary_edges, uint64_t holes_filled) {
  return fmt::format(
      "the input has {} boundary edges: the proxy was verified inside the input with its holes "
      "filled ({} {}), but a ray through a hole can hit the proxy and miss the input",
      boundary_edges, holes_filled, holes_filled == 1 ? "hole" : "holes");
}

void setWrittenClass(nlohmann::json& report, ProxyClass kind, bool verified,
                     const std::optional<std::string>& stand_in) {
  report.erase("class_reason");
  if (!verified) {
    report["class"] = nullptr;
  } else if (stand_in && kind != ProxyClass::kGeneral) {
    report["class"] = proxyClassName(ProxyClass::kGeneral);
    report["class_reason"] = *stand_in;
  } else {
    report["class"] = proxyClassName(kind);
  }
}

std::optional<ProxyClass> writtenClass(const nlohmann::json& report) {
  const auto it = report.find("class");
  if (it == report.end() || !it->is_string()) return std::nullopt;
  return parseProxyClass(it->get<std::string>());
}

}  // namespace proxyvis
