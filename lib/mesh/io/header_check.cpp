#include "mesh/io/internal/header_check.h"

namespace proxyvis::detail {

void checkDeclaredCounts(const std::string& bytes, const std::string& ext,
                         const std::string& file) {
  if (ext == "ply") checkPly(bytes, file);
  if (ext == "off") checkOff(bytes, file);
  if (ext == "obj") checkObj(bytes, file);
}

void blankOffComments(std::string& bytes) {
  for (size_t i = 0; i < bytes.size(); ++i) {
    if (bytes[i] != '#') continue;
    while (i < bytes.size() && bytes[i] != '\n') bytes[i++] = ' ';
  }
}

}  // namespace proxyvis::detail
