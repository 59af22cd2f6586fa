#pragma once
// Quoting text from an input file (a scene, an instance list, a JSON key) in an error message: at
// most kMaxQuoted bytes, so a 1 MB token cannot become a 1 MB error line (util/error.h escapes
// unprintable bytes).
#include <string>
#include <string_view>

namespace proxyvis {

inline constexpr size_t kMaxQuoted = 60;

// text, or the first kMaxQuoted bytes of it followed by "...".
inline std::string clipped(std::string_view text) {
  std::string out(text.substr(0, kMaxQuoted));
  if (text.size() > kMaxQuoted) out.append("...");
  return out;
}

// 'text' (clipped). Not named quoted(): ADL would find std::quoted for a std::string. (append,
// not "'" + ...: GCC 12 warns -Wrestrict on that pattern.)
inline std::string quoteInput(std::string_view text) {
  std::string out = "'";
  out.append(clipped(text)).append("'");
  return out;
}

}  // namespace proxyvis
