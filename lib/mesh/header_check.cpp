#include "mesh/internal/header_check.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <cstring>
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
  std::vector<bool> is_list;  // per property, in order
};

// `declared`: what the header declares, with its counts ("3485 vertices and 6966 faces").
void tooMany(const std::string& file, const std::string& declared, uint64_t need, uint64_t have) {
  throw Error(file, "header declares " + declared,
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

// OpenMesh's ASCII PLY reader can spin forever once its stream fails on a token that is not a
// number (seen in fuzzing: "1\xc81"), so the body of an ASCII file is checked token by token:
// numbers only ('#' comments allowed in OFF).
void checkAsciiNumbers(const std::string& bytes, size_t from, const std::string& file,
                       bool comments) {
  size_t i = from;
  size_t line = 1 + size_t(std::count(bytes.begin(), bytes.begin() + long(from), '\n'));
  while (i < bytes.size()) {
    const char c = bytes[i];
    if (c == '\n') ++line;
    if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
      continue;
    }
    if (comments && c == '#') {
      while (i < bytes.size() && bytes[i] != '\n') ++i;
      continue;
    }
    size_t end = i;
    while (end < bytes.size() && !std::isspace(static_cast<unsigned char>(bytes[end]))) ++end;
    const std::string token = bytes.substr(i, end - i);
    char* parsed_end = nullptr;
    std::strtod(token.c_str(), &parsed_end);
    // Plain decimals only: istream >> float (what OpenMesh uses) rejects "nan", "inf" and hex.
    const bool plain = token.find_first_not_of("0123456789+-.eE") == std::string::npos;
    if (!plain || token.size() > 64 || parsed_end != token.c_str() + token.size()) {
      std::string shown = token.substr(0, 20);
      for (char& ch : shown)
        if (static_cast<unsigned char>(ch) < 32 || static_cast<unsigned char>(ch) > 126) ch = '?';
      throw Error(file, "not a number on line " + std::to_string(line) + ": '" + shown + "'",
                  "the body of an ASCII mesh file holds numbers only", "the file is corrupt");
    }
    i = end;
  }
}

// OpenMesh's ASCII PLY reader also spins when a list count is negative or runs past the end of
// the file (fuzzing: a face line "-30 1 5"). Walks the records: every list length must be a
// non-negative integer and every declared value present. Values are already known to be numbers
// (checkAsciiNumbers).
void checkAsciiRecords(const std::string& bytes, size_t from,
                       const std::vector<PlyElement>& elements, const std::string& file);

void badHeaderLine(const std::string& file, size_t number, const std::string& line,
                   const std::string& why) {
  std::string shown = line.substr(0, 60);
  for (char& c : shown)
    if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) c = '?';
  throw Error(file, "corrupt PLY header line " + std::to_string(number) + " '" + shown + "'", why,
              "the file is corrupt; re-export it");
}

// Validates every header line before OpenMesh sees it (OpenMesh's header parser can loop forever
// on some corrupt headers) and checks the element counts against the file size.
void checkPly(const std::string& bytes, const std::string& file) {
  if (bytes.compare(0, 4, "ply\n") != 0 && bytes.compare(0, 5, "ply\r\n") != 0)
    throw Error(file, "not a PLY file", "the first line is not 'ply'",
                "check that the file is a PLY mesh");
  std::vector<PlyElement> elements;
  std::string format;
  size_t pos = 0, number = 0;
  bool ended = false;
  while (!ended) {
    const size_t eol = bytes.find('\n', pos);
    if (eol == std::string::npos || number > 10000)
      throw Error(file, "PLY header has no 'end_header' line", {},
                  "the file is truncated or not a PLY mesh");
    std::string line = bytes.substr(pos, eol - pos);
    pos = eol + 1;
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream ls(line);
    std::string key, extra;
    ls >> key;
    if (number == 1 || key == "comment" || key == "obj_info") continue;
    if (key == "end_header") {
      if (ls >> extra) badHeaderLine(file, number, line, "text after end_header");
      ended = true;
    } else if (key == "format") {
      std::string version;
      if (!(ls >> format >> version) || version != "1.0" || (ls >> extra))
        badHeaderLine(file, number, line, "expected 'format <type> 1.0'");
    } else if (key == "element") {
      PlyElement e;
      std::string count;
      if (!(ls >> e.name >> count) || (ls >> extra))
        badHeaderLine(file, number, line, "expected 'element <name> <count>'");
      e.count = parseCount(count, file, e.name + " elements");
      elements.push_back(e);
    } else if (key == "property") {
      if (elements.empty()) badHeaderLine(file, number, line, "property before any element");
      std::string type, name;
      if (!(ls >> type)) badHeaderLine(file, number, line, "property without a type");
      PlyElement& e = elements.back();
      ++e.properties;
      e.is_list.push_back(type == "list");
      if (type == "list") {
        std::string count_type, item_type;
        if (!(ls >> count_type >> item_type) || plyTypeSize(item_type) == 0)
          badHeaderLine(file, number, line, "expected 'property list <count type> <type> <name>'");
        type = count_type;
      }
      if (plyTypeSize(type) == 0) badHeaderLine(file, number, line, "unknown property type");
      if (!(ls >> name) || (ls >> extra))
        badHeaderLine(file, number, line, "expected one property name");
      e.min_binary_bytes += uint64_t(plyTypeSize(type));
    } else {
      badHeaderLine(file, number, line, "unknown keyword");
    }
  }
  const bool ascii = format == "ascii";
  if (!ascii && format != "binary_little_endian" && format != "binary_big_endian")
    throw Error(file, "unknown PLY format '" + format + "'",
                "expected ascii, binary_little_endian or binary_big_endian",
                "the header is corrupt");
  if (ascii) checkAsciiNumbers(bytes, pos, file, false);
  const uint64_t body = bytes.size() - pos;
  if (ascii) checkAsciiRecords(bytes, pos, elements, file);
  uint64_t need = 0;
  for (const PlyElement& e : elements) {
    // ASCII: every property takes at least one digit and one separator.
    const uint64_t per_record = ascii ? 2 * e.properties : e.min_binary_bytes;
    need += e.count * per_record;  // counts < 2^31 and per_record is small: no overflow
    if (need > body + 1)
      tooMany(file, std::to_string(e.count) + " " + e.name + " elements", need, body);
  }
}

// Walks the records of an ASCII OFF body from `pos` (just after the face count) and bounds every
// value among the faces: OpenMesh reads a face's vertex count as unsigned, so a "-34" made it
// loop 4 billion times pushing vertex handles (fuzz_off, twice: after the first fix only counts
// at the start of a line were checked). Vertices are 3 values (+3 with N, +2 with ST), or a line
// when colours (C) make their length vary.
void checkOffFaceValues(const std::string& bytes, size_t pos, const std::string& magic, uint64_t nv,
                        const std::string& file) {
  auto skipSpace = [&] {
    while (pos < bytes.size()) {
      if (bytes[pos] == '#') {
        while (pos < bytes.size() && bytes[pos] != '\n') ++pos;
      } else if (std::isspace(static_cast<unsigned char>(bytes[pos]))) {
        ++pos;
      } else {
        return true;
      }
    }
    return false;
  };
  auto nextToken = [&]() -> std::string {
    if (!skipSpace()) return {};
    const size_t start = pos;
    while (pos < bytes.size() && !std::isspace(static_cast<unsigned char>(bytes[pos]))) ++pos;
    return bytes.substr(start, pos - start);
  };
  auto skipLine = [&] {
    while (pos < bytes.size() && bytes[pos] != '\n') ++pos;
  };
  const bool colours = magic.find('C') != std::string::npos;
  const uint64_t per_vertex =
      3 + (magic.find('N') != std::string::npos ? 3 : 0) + (magic.compare(0, 2, "ST") == 0 ? 2 : 0);
  if (nextToken().empty()) return;  // the edge count
  // Where the faces start, by values (3 per vertex, +3 with N, +2 with ST) and by lines (one
  // vertex per line, which colours need): the earlier of the two, so that a vertex line with
  // more or fewer values than expected cannot hide a face value from the check below.
  const size_t vertices_start = pos;
  for (uint64_t v = 0; v < nv && !colours; ++v)
    for (uint64_t k = 0; k < per_vertex; ++k)
      if (nextToken().empty()) return;  // truncated: OpenMesh's own checks report it
  const size_t by_values = colours ? bytes.size() : pos;
  pos = vertices_start;
  for (uint64_t v = 0; v < nv; ++v) {
    if (!skipSpace()) return;
    skipLine();
  }
  pos = std::min(pos, by_values);
  // Faces: which token OpenMesh takes as a vertex count depends on how it reads colours, so
  // every value from here on is bounded. Indices are below nv, colours at most 255, and a count
  // at most the values that follow; nothing in this part is negative.
  for (std::string value = nextToken(); !value.empty(); value = nextToken()) {
    const uint64_t left = (bytes.size() - pos) / 2 + 1;  // values that can still follow
    // The digits OpenMesh's unsigned read would take: "40.51" is a count of 40.
    const std::string digits = value.substr(0, value.find_first_not_of("0123456789"));
    if (value[0] == '-' ||
        (!digits.empty() &&
         (digits.size() > 12 || std::stoull(digits) > std::max({nv, left, uint64_t(255)})))) {
      std::string shown = value.substr(0, 20);
      for (char& ch : shown)
        if (static_cast<unsigned char>(ch) < 32 || static_cast<unsigned char>(ch) > 126) ch = '?';
      throw Error(file, "value '" + shown + "' among the faces",
                  "face values are vertex counts, vertex indices below " + std::to_string(nv) +
                      " or colours, none negative",
                  "the file is corrupt");
    }
  }
}

void checkOff(const std::string& bytes, const std::string& file) {
  std::istringstream in(bytes.substr(0, std::min<size_t>(bytes.size(), 4096)));
  std::string magic;
  in >> magic;
  // The keyword is [ST][C][N][4][n]OFF, nothing else: a first word that only ended in "4OFF"
  // after binary bytes made OpenMesh read 84 million empty faces from 490 bytes (fuzz_off).
  size_t k = 0;
  for (const char* prefix : {"ST", "C", "N"})
    if (magic.compare(k, std::strlen(prefix), prefix) == 0) k += std::strlen(prefix);
  const bool higher_dimension = k < magic.size() && (magic[k] == '4' || magic[k] == 'n');
  if (magic.compare(k + (higher_dimension ? 1 : 0), std::string::npos, "OFF") != 0)
    throw Error(file, "not an OFF file", "the first word is not OFF (or COFF, NOFF, STOFF, ...)",
                "check that the file is an OFF mesh");
  if (higher_dimension)
    throw Error(file, "4D or n-dimensional OFF ('" + magic + "')",
                "only 3D positions can be loaded", "convert the mesh to plain OFF");
  // OpenMesh takes the counts from after the keyword's line and ignores the rest of that line:
  // counts there were checked here while OpenMesh read 12147483648 from the next line and added
  // vertices for minutes (fuzz_off). Only BINARY or a comment may follow the keyword.
  std::string rest;
  std::getline(in, rest);
  std::istringstream rest_words(rest);
  for (std::string word; rest_words >> word && word[0] != '#';)
    if (word != "BINARY")
      throw Error(file, "text after the OFF keyword on its line",
                  "the vertex and face counts are read from the next line",
                  "put the counts on a line of their own");
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
    tooMany(file, std::to_string(nv) + " vertices and " + std::to_string(nf) + " faces", need,
            bytes.size());
  if (bytes.substr(0, bytes.find('\n')).find("BINARY") == std::string::npos) {
    checkAsciiNumbers(bytes, bytes.find(magic) + magic.size(), file, true);
    if (const std::streamoff after = in.tellg(); after > 0)
      checkOffFaceValues(bytes, size_t(after), magic, nv, file);
  }
}

void checkAsciiRecords(const std::string& bytes, size_t from,
                       const std::vector<PlyElement>& elements, const std::string& file) {
  std::istringstream in(bytes.substr(from));
  std::string token;
  auto next = [&](const std::string& element, uint64_t record) {
    if (!(in >> token))
      throw Error(file, "file ends inside " + element + " " + std::to_string(record),
                  "fewer values than the header declares", "the file is truncated");
    return token;
  };
  for (const PlyElement& e : elements) {
    for (uint64_t r = 0; r < e.count; ++r) {
      for (bool list : e.is_list) {
        const std::string t = next(e.name, r);
        if (!list) continue;
        if (t.find_first_not_of("0123456789") != std::string::npos || t.size() > 9)
          throw Error(file, "bad list length '" + t + "' in " + e.name + " " + std::to_string(r),
                      "expected a non-negative integer", "the file is corrupt");
        for (long k = std::stol(t); k > 0; --k) next(e.name, r);
      }
    }
  }
}

bool isPlainNumber(const std::string& t) {
  if (t.empty() || t.size() > 64 || t.find_first_not_of("0123456789+-.eE") != std::string::npos)
    return false;
  char* end = nullptr;
  std::strtod(t.c_str(), &end);
  return end == t.c_str() + t.size();
}

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
    const bool integer = digits >= 1 && digits <= 10 && f.back() != '-' &&
                         f.find_first_not_of("0123456789", f[0] == '-') == std::string::npos &&
                         f[f[0] == '-'] != '0';
    if (!integer && !empty_ok) return false;
    if (slash == std::string::npos) return true;
    if (++field > 2) return false;
    pos = slash + 1;
  }
}

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
      const bool ok = key == "v" ? isPlainNumber(token) : isObjCorner(token);
      if (!ok) {
        std::string shown = token.substr(0, 20);
        for (char& ch : shown)
          if (static_cast<unsigned char>(ch) < 32 || static_cast<unsigned char>(ch) > 126) ch = '?';
        throw Error(
            file,
            "bad " + std::string(key == "v" ? "coordinate" : "face index") + " '" + shown +
                "' on line " + std::to_string(number),
            key == "v" ? "expected a decimal number" : "expected v, v/t, v//n or v/t/n (1-based)",
            "the file is corrupt");
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

}  // namespace

void checkDeclaredCounts(const std::string& bytes, const std::string& ext,
                         const std::string& file) {
  if (ext == "ply") checkPly(bytes, file);
  if (ext == "off") checkOff(bytes, file);
  if (ext == "obj") checkObj(bytes, file);
}

}  // namespace proxyvis::detail
