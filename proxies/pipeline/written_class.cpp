#include "proxies/pipeline/written_class.h"

#include <fmt/core.h>

namespace proxyvis {

std::string filledHolesReason(uint64_t boundary_edges, uint64_t holes_filled) {
  return fmt::format(
      "the input has {} boundary edges: the proxy was verified inside the input with its holes "
      "filled ({} {}), but a ray through a hole can hit the proxy and miss the input",
      boundary_edges, holes_filled, holes_filled == 1 ? "hole" : "holes");
}

void setWrittenClass(ProxyReport& report, ProxyClass kind, bool verified,
                     const std::optional<std::string>& stand_in) {
  report.class_reason.reset();
  report.written_class.reset();
  if (!verified) return;
  if (stand_in && kind != ProxyClass::kGeneral) {
    report.written_class = ProxyClass::kGeneral;
    report.class_reason = *stand_in;
  } else {
    report.written_class = kind;
  }
}

}  // namespace proxyvis
