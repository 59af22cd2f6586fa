#include "outofcore/geometry_budget.h"

#include <cmath>
#include <string_view>

#include "util/error.h"

namespace proxyvis {

namespace {

[[noreturn]] void refuse(const std::string& text, const std::string& why) {
  throw Error("", "--geometry-budget " + text + ": " + why, {},
              "give bytes (2G, 500M, 64K, 123456) or a share of the originals' in-core size "
              "(25%)");
}

}  // namespace

uint64_t GeometryBudget::resolve(uint64_t in_core_bytes) const {
  if (share <= 0) return bytes;
  return uint64_t(std::ceil(share * double(in_core_bytes)));
}

GeometryBudget parseGeometryBudget(const std::string& text) {
  GeometryBudget b;
  b.text = text;
  std::string_view s = text;
  if (s.empty()) refuse(text, "empty");
  const bool percent = s.back() == '%';
  if (percent) s.remove_suffix(1);
  double scale = 1;
  if (!percent) {
    if (s.size() >= 2 && (s.ends_with("iB") || s.ends_with("ib")))
      s.remove_suffix(2);
    else if (!s.empty() && (s.back() == 'B' || s.back() == 'b'))
      s.remove_suffix(1);
    if (!s.empty()) {
      switch (s.back()) {
        case 'K':
        case 'k':
          scale = 1024.0;
          break;
        case 'M':
        case 'm':
          scale = 1024.0 * 1024;
          break;
        case 'G':
        case 'g':
          scale = 1024.0 * 1024 * 1024;
          break;
        case 'T':
        case 't':
          scale = 1024.0 * 1024 * 1024 * 1024;
          break;
        default:
          break;
      }
      if (scale > 1) s.remove_suffix(1);
    }
  }
  if (s.empty() || s.find_first_not_of("0123456789.") != std::string_view::npos)
    refuse(text, "not a number of bytes or a percentage");
  double value = 0;
  try {
    size_t used = 0;
    value = std::stod(std::string(s), &used);
    if (used != s.size()) refuse(text, "not a number");
  } catch (const Error&) {
    throw;
  } catch (...) {
    refuse(text, "not a number");
  }
  if (percent) {
    if (!(value > 0 && value <= 100)) refuse(text, "a share must be in (0, 100] %");
    b.share = value / 100;
    return b;
  }
  const double bytes = value * scale;
  if (!(bytes >= 1)) refuse(text, "must be at least one byte");
  if (!(bytes < 1.8e19)) refuse(text, "too large");
  b.bytes = uint64_t(bytes);
  return b;
}

}  // namespace proxyvis
