#pragma once
// Text made safe for HTML and SVG: the report pages and the 3D viewer write file names, mesh
// names and claims that a user chose into element text and attribute values.
#include <string>

namespace proxyvis {

// `text` with &, <, >, " and ' as character references.
inline std::string escapeHtml(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    const char* entity = c == '&'    ? "&amp;"
                         : c == '<'  ? "&lt;"
                         : c == '>'  ? "&gt;"
                         : c == '"'  ? "&quot;"
                         : c == '\'' ? "&#39;"
                                     : nullptr;
    if (entity)
      out += entity;
    else
      out += c;
  }
  return out;
}

}  // namespace proxyvis
