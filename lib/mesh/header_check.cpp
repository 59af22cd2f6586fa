#include "mesh/internal/header_check.h"

#include <cstdint>
#include <limits>
#include <sstream>
#include <vector>

#include "util/error.h"

namespace proxyvis::detail {
namespace {

// Readers index with int: anything above this cannot be loaded anyway.
constexpr uint64_t kMaxCount = uint64_t(std::numeric_limits<int32_t>::max());

int plyTypeSize(const std::string& t) {
  if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
  if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
  if (t == "int" || t == "uint" || t == "float" || t == "int32" || t == "uint32" || t == "float32")
    return 4;
  if (t == "double" || t == "float64") return 8;
  return 0;
}

struct PlyElement {
  std::string name;
  uint64_t count = 0;
  uint64_t min_binary_bytes = 0;  // per record: fixed properties + the count field of lists
  uint64_t properties = 0;
};

void tooMany(const std::string& file, const std::string& what, uint64_t count, uint64_t need,
             uint64_t have) {
  throw Error(file, "header declares " + std::to_string(count) + " " + what,
              "that needs at least " + std::to_string(need) + " bytes but the file has " +
                  std::to_string(have),
              "the file is truncated or its header is corrupt");
}

uint64_t parseCount(const std::string& token, const std::string& file, const std::string& what) {
  if (token.empty() || token.find_first_not_of("0123456789") != std::string::npos)
    throw Error(file, "bad " + what + " count '" + token + "' in the header",
                "expected a non-negative integer", "the file is corrupt");
  if (token.size() > 12 || std::stoull(token) > kMaxCount)
    throw Error(file, "header declares " + token + " " + what,
                "more than 2^31-1 elements cannot be loaded", "the file is corrupt or too large");
  return std::stoull(token);
}

void checkPly(const std::string& bytes, const std::string& file) {
  const size_t end = bytes.find("end_header");
  if (bytes.compare(0, 3, "ply") != 0 || end == std::string::npos)
    throw Error(file, "not a PLY file", "no 'ply' magic or no 'end_header' line",
                "check that the file is a PLY mesh");
  const size_t body_start = bytes.find('\n', end);
  const uint64_t body = body_start == std::string::npos ? 0 : bytes.size() - body_start - 1;

  std::istringstream header(bytes.substr(0, end));
  std::string line, format;
  std::vector<PlyElement> elements;
  while (std::getline(header, line)) {
    std::istringstream ls(line);
    std::string key;
    ls >> key;
    if (key == "format") {
      ls >> format;
    } else if (key == "element") {
      PlyElement e;
      std::string count;
      ls >> e.name >> count;
      e.count = parseCount(count, file, e.name + " elements");
      elements.push_back(e);
    } else if (key == "property") {
      if (elements.empty())
        throw Error(file, "PLY property before any element", {}, "the header is corrupt");
      std::string type;
      ls >> type;
      PlyElement& e = elements.back();
      ++e.properties;
      if (type == "list") {
        std::string count_type;
        ls >> count_type;
        type = count_type;
      }
      const int size = plyTypeSize(type);
      if (size == 0)
        throw Error(file, "unknown PLY property type '" + type + "'", {}, "the header is corrupt");
      e.min_binary_bytes += uint64_t(size);
    }
  }
  const bool ascii = format == "ascii";
  if (!ascii && format != "binary_little_endian" && format != "binary_big_endian")
    throw Error(file, "unknown PLY format '" + format + "'",
                "expected ascii, binary_little_endian or binary_big_endian",
                "the header is corrupt");
  uint64_t need = 0;
  for (const PlyElement& e : elements) {
    // ASCII: every property takes at least one digit and one separator.
    const uint64_t per_record = ascii ? 2 * e.properties : e.min_binary_bytes;
    need += e.count * per_record;  // counts < 2^31 and per_record is small: no overflow
    if (need > body + 1) tooMany(file, e.name + " elements", e.count, need, body);
  }
}

void checkOff(const std::string& bytes, const std::string& file) {
  std::istringstream in(bytes.substr(0, std::min<size_t>(bytes.size(), 4096)));
  std::string magic;
  in >> magic;
  if (magic.size() < 3 || magic.compare(magic.size() - 3, 3, "OFF") != 0)
    throw Error(file, "not an OFF file", "the first word is not OFF (or COFF, NOFF, ...)",
                "check that the file is an OFF mesh");
  if (magic.find("4") != std::string::npos || magic.find('n') != std::string::npos)
    return;  // 4D / n-dimensional variants: OpenMesh rejects them itself
  std::string tok;
  std::vector<std::string> counts;
  while (counts.size() < 2 && in >> tok) {
    if (tok[0] == '#') {
      std::getline(in, tok);
      continue;
    }
    if (tok == "BINARY") continue;
    counts.push_back(tok);
  }
  if (counts.size() < 2)
    throw Error(file, "OFF header has no vertex and face counts", {}, "the file is corrupt");
  const uint64_t nv = parseCount(counts[0], file, "vertices");
  const uint64_t nf = parseCount(counts[1], file, "faces");
  // ASCII records are at least "x y z\n" (6 bytes) and "3 a b c\n" (8 bytes); binary ones more.
  const uint64_t need = nv * 6 + nf * 8;
  if (need > bytes.size() + 1)
    tooMany(file, std::to_string(nv) + " vertices and " + std::to_string(nf) + " faces", nv + nf,
            need, bytes.size());
}

}  // namespace

void checkDeclaredCounts(const std::string& bytes, const std::string& ext,
                         const std::string& file) {
  if (ext == "ply") checkPly(bytes, file);
  if (ext == "off") checkOff(bytes, file);
}

}  // namespace proxyvis::detail
