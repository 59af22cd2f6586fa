#pragma once
// The --geometry-budget of the out-of-core renderer: the bytes its cache of built originals may
// hold, given as bytes ("2G", "500M", "123456") or as a share of the originals' in-core size
// ("25%"), which is known only once the scene has been scanned.
#include <cstdint>
#include <string>

namespace proxyvis {

struct GeometryBudget {
  uint64_t bytes = 0;  // when share == 0
  double share = 0;    // (0, 1]: a fraction of the originals' in-core bytes
  std::string text;    // as given, for messages and reports

  // The budget in bytes for originals whose built scenes take `in_core_bytes` together.
  uint64_t resolve(uint64_t in_core_bytes) const;
};

// Parses "2G", "1.5G", "500M", "64K", "123456" (powers of 1024; an optional trailing B or iB) or
// "25%" (0 < p <= 100). Throws Error naming --geometry-budget for anything else.
GeometryBudget parseGeometryBudget(const std::string& text);

}  // namespace proxyvis
