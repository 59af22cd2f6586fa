// OBJ: 'v' and 'f' lines before OpenMesh's reader sees them.
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>

#include "mesh/io/internal/header_check.h"
#include "mesh/io/internal/printable.h"
#include "mesh/io/internal/text_check.h"
#include "util/error.h"

namespace proxyvis::detail {
namespace {

// One OBJ face corner: v, v/t, v//n or v/t/n with non-zero (possibly negative) integers.
bool isObjCorner(const std::string& t) {
  // Up to three '/'-separated fields; the first is required, the others may be empty.
  size_t field = 0, pos = 0;
  while (true) {
    const size_t slash = t.find('/', pos);
    const std::string f =
        t.substr(pos, slash == std::string::npos ? std::string::npos : slash - pos);
    const size_t digits = f.size() - (!f.empty() && f[0] == '-');
    const bool empty_ok = field > 0 && f.empty();
    // Within int: OpenMesh reads indices with operator>> and dropped a face whose index
    // overflowed (9999999999), silently.
    const bool integer =
        digits >= 1 && digits <= 10 && f.back() != '-' &&
        f.find_first_not_of("0123456789", f[0] == '-') == std::string::npos &&
        f[f[0] == '-'] != '0' &&
        isIntegerIn(f, std::numeric_limits<int32_t>::min(), std::numeric_limits<int32_t>::max());
    if (!integer && !empty_ok) return false;
    if (slash == std::string::npos) return true;
    if (++field > 2) return false;
    pos = slash + 1;
  }
}

}  // namespace

// OpenMesh's OBJ reader asserts (aborts the process) on some malformed face lines, e.g.
// "f /0 11 15" (found by fuzzing), so 'v' and 'f' lines are checked before it sees them.
void checkObj(const std::string& bytes, const std::string& file) {
  std::istringstream in(bytes);
  std::string line;
  size_t number = 0;
  while (std::getline(in, line)) {
    ++number;
    std::istringstream ls(line);
    std::string key, token;
    ls >> key;
    if (key != "v" && key != "f") continue;
    size_t count = 0;
    while (ls >> token) {
      if (key == "v") {
        checkNumberToken(token, file, number, "coordinates");
      } else if (!isObjCorner(token)) {
        throw Error(file,
                    "bad face index '" + printableExcerpt(token, 20) + "' on line " +
                        std::to_string(number),
                    "expected v, v/t, v//n or v/t/n (1-based)", "the file is corrupt");
      }
      ++count;
    }
    if ((key == "v" && (count < 3 || count > 7)) || (key == "f" && count < 3))
      throw Error(file, "malformed '" + key + "' line " + std::to_string(number),
                  key == "v" ? "expected 3 coordinates (and optional w or colour)"
                             : "a face needs at least 3 corners",
                  "the file is corrupt");
  }
}

}  // namespace proxyvis::detail
