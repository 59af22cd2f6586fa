// PLY: the header line by line before OpenMesh sees it (its header parser can loop forever on some
// corrupt headers), the element counts against the file size, then one walk over the records.
#include <algorithm>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "mesh/io/internal/header_check.h"
#include "mesh/io/internal/printable.h"
#include "mesh/io/internal/text_check.h"
#include "util/error.h"

namespace proxyvis::detail {
namespace {

int plyTypeSize(const std::string& t) {
  if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
  if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
  if (t == "int" || t == "uint" || t == "float" || t == "int32" || t == "uint32" || t == "float32")
    return 4;
  if (t == "double" || t == "float64") return 8;
  return 0;
}

// Range of a PLY integer type; false for float types.
bool plyIntegerRange(const std::string& t, int64_t& lo, int64_t& hi) {
  const int size = plyTypeSize(t);
  if (size == 0 || t == "float" || t == "float32" || t == "double" || t == "float64") return false;
  const bool is_unsigned = t[0] == 'u';
  const int bits = 8 * size;
  lo = is_unsigned ? 0 : -(int64_t(1) << (bits - 1));
  hi = is_unsigned ? (int64_t(1) << bits) - 1 : (int64_t(1) << (bits - 1)) - 1;
  return true;
}

struct PlyProperty {
  std::string name;
  std::string type;        // scalar type, or the item type of a list
  std::string count_type;  // lists only
  bool list = false;
};

struct PlyElement {
  std::string name;
  uint64_t count = 0;
  uint64_t min_binary_bytes = 0;   // per record: fixed properties + the count field of lists
  std::vector<PlyProperty> props;  // in order
};

struct PlyHeader {
  std::string format;
  std::vector<PlyElement> elements;
  size_t body = 0;  // offset of the first byte after end_header
};

[[noreturn]] void badHeaderLine(const std::string& file, size_t number, const std::string& line,
                                const std::string& why) {
  throw Error(
      file,
      "corrupt PLY header line " + std::to_string(number) + " '" + printableExcerpt(line, 60) + "'",
      why, "the file is corrupt; re-export it");
}

// One header line that declares a property of the last element.
PlyProperty parseProperty(std::istringstream& words, const std::string& file, size_t number,
                          const std::string& line) {
  std::string type, name, extra;
  if (!(words >> type)) badHeaderLine(file, number, line, "property without a type");
  PlyProperty p;
  p.list = type == "list";
  if (p.list) {
    if (!(words >> p.count_type >> p.type) || plyTypeSize(p.type) == 0)
      badHeaderLine(file, number, line, "expected 'property list <count type> <type> <name>'");
    type = p.count_type;
  } else {
    p.type = type;
  }
  if (plyTypeSize(type) == 0) badHeaderLine(file, number, line, "unknown property type");
  if (!(words >> name) || (words >> extra))
    badHeaderLine(file, number, line, "expected one property name");
  p.name = name;
  return p;
}

PlyHeader parseHeader(const std::string& bytes, const std::string& file) {
  if (bytes.compare(0, 4, "ply\n") != 0 && bytes.compare(0, 5, "ply\r\n") != 0)
    throw Error(file, "not a PLY file", "the first line is not 'ply'",
                "check that the file is a PLY mesh");
  PlyHeader h;
  size_t pos = 0, number = 0;
  for (bool ended = false; !ended;) {
    const size_t eol = bytes.find('\n', pos);
    if (eol == std::string::npos || number > 10000)
      throw Error(file, "PLY header has no 'end_header' line", {},
                  "the file is truncated or not a PLY mesh");
    std::string line = bytes.substr(pos, eol - pos);
    pos = eol + 1;
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream words(line);
    std::string key, extra;
    words >> key;
    if (number == 1 || key == "comment" || key == "obj_info") continue;
    if (key == "end_header") {
      if (words >> extra) badHeaderLine(file, number, line, "text after end_header");
      ended = true;
    } else if (key == "format") {
      std::string version;
      if (!(words >> h.format >> version) || version != "1.0" || (words >> extra))
        badHeaderLine(file, number, line, "expected 'format <type> 1.0'");
    } else if (key == "element") {
      PlyElement e;
      std::string count;
      if (!(words >> e.name >> count) || (words >> extra))
        badHeaderLine(file, number, line, "expected 'element <name> <count>'");
      e.count = parseCount(count, file, e.name + " elements");
      h.elements.push_back(e);
    } else if (key == "property") {
      if (h.elements.empty()) badHeaderLine(file, number, line, "property before any element");
      PlyElement& e = h.elements.back();
      e.props.push_back(parseProperty(words, file, number, line));
      const PlyProperty& p = e.props.back();
      e.min_binary_bytes += uint64_t(plyTypeSize(p.list ? p.count_type : p.type));
    } else {
      badHeaderLine(file, number, line, "unknown keyword");
    }
  }
  if (h.format != "ascii" && h.format != "binary_little_endian" && h.format != "binary_big_endian")
    throw Error(file, "unknown PLY format '" + printableExcerpt(h.format, 30) + "'",
                "expected ascii, binary_little_endian or binary_big_endian",
                "the header is corrupt");
  h.body = pos;
  return h;
}

// The declared counts against the bytes after the header, before any record is read.
void checkCountsFit(const PlyHeader& h, uint64_t body_bytes, const std::string& file) {
  const bool ascii = h.format == "ascii";
  uint64_t need = 0;
  for (const PlyElement& e : h.elements) {
    // Records of no bytes: the file size cannot bound their number, and OpenMesh would reserve
    // all of them (2^31 vertices: 12 GB for positions nobody declared).
    if (e.count > 0 && e.props.empty())
      throw Error(file,
                  "header declares " + std::to_string(e.count) + " '" +
                      printableExcerpt(e.name, 30) + "' elements with no properties",
                  "an element without properties holds no data",
                  "the header is corrupt; re-export the file");
    // ASCII: every property takes at least one digit and one separator.
    const uint64_t per_record = ascii ? 2 * e.props.size() : e.min_binary_bytes;
    need += e.count * per_record;  // counts < 2^31 and per_record is small: no overflow
    if (need > body_bytes + 1)
      tooMany(file, std::to_string(e.count) + " " + printableExcerpt(e.name, 30) + " elements",
              need, body_bytes);
  }
}

// The ASCII body in one walk. OpenMesh's ASCII reader spins forever once its stream fails on a
// token that is not a number (fuzzing: "1\xc81"), and when a list length is negative or runs past
// the end of the file (a face line "-30 1 5"): every token must be a number, every list length a
// non-negative integer, integer properties integers of their type, every declared value present.
void checkAsciiBody(const std::string& bytes, const PlyHeader& h, const std::string& file) {
  TextTokens tokens(bytes, h.body, false);
  auto next = [&](const PlyElement& e, uint64_t record) -> const std::string& {
    if (!tokens.next())
      throw Error(file,
                  "file ends inside " + printableExcerpt(e.name, 30) + " " + std::to_string(record),
                  "fewer values than the header declares", "the file is truncated");
    checkNumberToken(tokens.token(), file, tokens.line(), "body");
    return tokens.token();
  };
  auto notInteger = [&](const PlyElement& e, const PlyProperty& p, const std::string& type) {
    return Error(file,
                 "'" + printableExcerpt(tokens.token(), 20) + "' on line " +
                     std::to_string(tokens.line()) + " is not a valid " + type + " (" +
                     printableExcerpt(p.name, 30) + " of " + printableExcerpt(e.name, 30) + ")",
                 "the header declares that property as an integer type", "the file is corrupt");
  };
  for (const PlyElement& e : h.elements) {
    for (uint64_t r = 0; r < e.count; ++r) {
      for (const PlyProperty& p : e.props) {
        int64_t lo = 0, hi = 0;
        int64_t items = 1;
        if (p.list) {
          plyIntegerRange(p.count_type, lo, hi);
          const std::string& length = next(e, r);
          if (!isIntegerIn(length, std::max<int64_t>(lo, 0), std::min<int64_t>(hi, 1 << 20)))
            throw notInteger(e, p, "list length");
          items = std::stoll(length);
        }
        const bool integer = plyIntegerRange(p.type, lo, hi);
        for (int64_t k = 0; k < items; ++k)
          if (!isIntegerIn(next(e, r), lo, hi) && integer)
            throw notInteger(e, p, p.type + " value");
      }
    }
  }
  // What follows the records is not read, but a stream that fails on it still spins.
  while (tokens.next()) checkNumberToken(tokens.token(), file, tokens.line(), "body");
}

// A binary list length is read from the file and OpenMesh reads that many items: 2e9 in a
// 100-byte file kept it reading past the end for minutes. Walks the records (elements without
// lists in one step): every list length must be a non-negative integer whose items fit in the
// bytes left.
void checkBinaryBody(const std::string& bytes, const PlyHeader& h, const std::string& file) {
  const bool big_endian = h.format == "binary_big_endian";
  uint64_t pos = h.body;
  const uint64_t size = bytes.size();
  auto readCount = [&](const std::string& type) -> int64_t {
    const int n = plyTypeSize(type);
    unsigned char b[8] = {};
    for (int k = 0; k < n; ++k)
      b[big_endian ? n - 1 - k : k] = static_cast<unsigned char>(bytes[size_t(pos) + size_t(k)]);
    pos += uint64_t(n);
    uint64_t raw = 0;
    for (int k = n - 1; k >= 0; --k) raw = (raw << 8) | b[k];
    if (type[0] == 'u') return int64_t(raw);
    const int shift = 64 - 8 * n;  // sign-extend
    return int64_t(raw << shift) >> shift;
  };
  for (const PlyElement& e : h.elements) {
    const bool has_list =
        std::any_of(e.props.begin(), e.props.end(), [](const PlyProperty& p) { return p.list; });
    if (!has_list) {
      pos += e.count * e.min_binary_bytes;  // checked against the size before
      continue;
    }
    for (uint64_t r = 0; r < e.count; ++r) {
      for (const PlyProperty& p : e.props) {
        const uint64_t field = uint64_t(plyTypeSize(p.list ? p.count_type : p.type));
        const std::string where = printableExcerpt(e.name, 30) + " " + std::to_string(r);
        if (pos + field > size)
          throw Error(file, "file ends inside " + where, "fewer bytes than the header declares",
                      "the file is truncated");
        if (!p.list) {
          pos += field;
          continue;
        }
        const int64_t items = readCount(p.count_type);
        const uint64_t item_size = uint64_t(plyTypeSize(p.type));
        int64_t lo = 0, hi = 0;
        if (!plyIntegerRange(p.count_type, lo, hi) || items < 0)
          throw Error(file, "list length " + std::to_string(items) + " in " + where,
                      "a list length is a non-negative integer", "the file is corrupt");
        if (uint64_t(items) > (size - pos) / item_size)
          throw Error(file, "file ends inside " + where,
                      "its list of " + std::to_string(items) + " items needs " +
                          std::to_string(uint64_t(items) * item_size) + " bytes, " +
                          std::to_string(size - pos) + " are left",
                      "the file is truncated or its list length is corrupt");
        pos += uint64_t(items) * item_size;
      }
    }
  }
}

}  // namespace

void checkPly(const std::string& bytes, const std::string& file) {
  const PlyHeader h = parseHeader(bytes, file);
  checkCountsFit(h, bytes.size() - h.body, file);
  if (h.format == "ascii")
    checkAsciiBody(bytes, h, file);
  else
    checkBinaryBody(bytes, h, file);
}

}  // namespace proxyvis::detail
