#include "mesh/io/internal/header_check.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <sstream>
#include <vector>

#include "mesh/io/internal/printable.h"
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

struct PlyProperty {
  std::string name;
  std::string type;        // scalar type, or the item type of a list
  std::string count_type;  // lists only
  bool list = false;
};

struct PlyElement {
  std::string name;
  uint64_t count = 0;
  uint64_t min_binary_bytes = 0;  // per record: fixed properties + the count field of lists
  uint64_t properties = 0;
  std::vector<PlyProperty> props;  // in order
};

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

// An integer token within [lo, hi]: OpenMesh reads integers with operator>>, which takes "1.5"
// or "1e5" as 1 and leaves the rest for the next field (shifting every value after it), and
// fails the stream on values beyond the type (after which it uses uninitialised values).
bool isIntegerIn(const std::string& t, int64_t lo, int64_t hi) {
  const size_t sign = (!t.empty() && (t[0] == '-' || t[0] == '+')) ? 1 : 0;
  if (t.size() <= sign || t.size() - sign > 12 ||
      t.find_first_not_of("0123456789", sign) != std::string::npos)
    return false;
  const int64_t v = std::stoll(t);
  return v >= lo && v <= hi;
}

// Whitespace-separated tokens of `bytes` from `from` on, with their line numbers.
class Tokens {
 public:
  Tokens(const std::string& bytes, size_t from)
      : bytes_(bytes),
        pos_(from),
        line_(1 + size_t(std::count(bytes.begin(), bytes.begin() + long(from), '\n'))) {}
  // The next token, or false at the end.
  bool next(std::string& token) {
    while (pos_ < bytes_.size() && std::isspace(static_cast<unsigned char>(bytes_[pos_])))
      line_ += bytes_[pos_++] == '\n';
    if (pos_ >= bytes_.size()) return false;
    const size_t begin = pos_;
    while (pos_ < bytes_.size() && !std::isspace(static_cast<unsigned char>(bytes_[pos_]))) ++pos_;
    token.assign(bytes_, begin, pos_ - begin);
    return true;
  }
  size_t line() const { return line_; }

 private:
  const std::string& bytes_;
  size_t pos_;
  size_t line_;
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
    throw Error(file,
                "bad " + printableExcerpt(what, 40) + " count '" + printableExcerpt(token, 20) +
                    "' in the header",
                "expected a non-negative integer", "the file is corrupt");
  if (token.size() > 12 || std::stoull(token) > kMaxCount)
    throw Error(file, "header declares " + token + " " + printableExcerpt(what, 40),
                "more than 2^31-1 elements cannot be loaded", "the file is corrupt or too large");
  return std::stoull(token);
}

// A number token of an ASCII mesh: a plain decimal (istream >> float, what OpenMesh uses, rejects
// "nan", "inf" and hex) within float range. OpenMesh reads values beyond float range (1e39) as a
// failed stream: its OFF and PLY readers then use uninitialised values and its OBJ reader drops
// the vertex, shifting every later index. Throws Error naming the file and the line.
void checkNumberToken(const std::string& token, const std::string& file, size_t line,
                      const std::string& what) {
  char* parsed_end = nullptr;
  const double value = std::strtod(token.c_str(), &parsed_end);
  const bool plain = !token.empty() && token.size() <= 64 &&
                     token.find_first_not_of("0123456789+-.eE") == std::string::npos &&
                     parsed_end == token.c_str() + token.size();
  if (!plain)
    throw Error(
        file,
        "not a number on line " + std::to_string(line) + ": '" + printableExcerpt(token, 20) + "'",
        "the " + what + " of an ASCII mesh file holds decimal numbers only", "the file is corrupt");
  if (!std::isfinite(value) || std::fabs(value) > double(std::numeric_limits<float>::max()))
    throw Error(file,
                "number beyond float range on line " + std::to_string(line) + ": '" +
                    printableExcerpt(token, 20) + "'",
                "positions are 32-bit floats (at most 3.4e38 in magnitude)",
                "the file is corrupt or was written with wrong units; fix or re-export it");
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
    checkNumberToken(bytes.substr(i, end - i), file, line, "body");
    i = end;
  }
}

// OpenMesh's ASCII PLY reader also spins when a list count is negative or runs past the end of
// the file (fuzzing: a face line "-30 1 5"). Walks the records: every list length must be a
// non-negative integer and every declared value present. Values are already known to be numbers
// (checkAsciiNumbers).
void checkAsciiRecords(const std::string& bytes, size_t from,
                       const std::vector<PlyElement>& elements, const std::string& file);
void checkOffRecordLines(const std::string& bytes, size_t from, uint64_t vertices, uint64_t faces,
                         size_t min_vertex_values, const std::string& file);

// A binary list length is read from the file and OpenMesh reads that many items: 2e9 in a
// 100-byte file kept it reading past the end for minutes. Walks the records (elements without
// lists in one step): every list length must be a non-negative integer whose items fit in the
// bytes left.
void checkBinaryRecords(const std::string& bytes, size_t from,
                        const std::vector<PlyElement>& elements, bool big_endian,
                        const std::string& file) {
  uint64_t pos = from;
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
  for (const PlyElement& e : elements) {
    const bool has_list =
        std::any_of(e.props.begin(), e.props.end(), [](const PlyProperty& p) { return p.list; });
    if (!has_list) {
      pos += e.count * e.min_binary_bytes;  // checked against the size above
      continue;
    }
    for (uint64_t r = 0; r < e.count; ++r) {
      for (const PlyProperty& p : e.props) {
        const uint64_t field = uint64_t(plyTypeSize(p.list ? p.count_type : p.type));
        if (pos + field > size)
          throw Error(file,
                      "file ends inside " + printableExcerpt(e.name, 30) + " " + std::to_string(r),
                      "fewer bytes than the header declares", "the file is truncated");
        if (!p.list) {
          pos += field;
          continue;
        }
        int64_t lo = 0, hi = 0;
        const int64_t items = readCount(p.count_type);
        const uint64_t item_size = uint64_t(plyTypeSize(p.type));
        const std::string where = printableExcerpt(e.name, 30) + " " + std::to_string(r);
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

void badHeaderLine(const std::string& file, size_t number, const std::string& line,
                   const std::string& why) {
  throw Error(
      file,
      "corrupt PLY header line " + std::to_string(number) + " '" + printableExcerpt(line, 60) + "'",
      why, "the file is corrupt; re-export it");
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
      PlyProperty p;
      p.list = type == "list";
      if (p.list) {
        std::string item_type;
        if (!(ls >> p.count_type >> item_type) || plyTypeSize(item_type) == 0)
          badHeaderLine(file, number, line, "expected 'property list <count type> <type> <name>'");
        p.type = item_type;
        type = p.count_type;
      } else {
        p.type = type;
      }
      if (plyTypeSize(type) == 0) badHeaderLine(file, number, line, "unknown property type");
      if (!(ls >> name) || (ls >> extra))
        badHeaderLine(file, number, line, "expected one property name");
      p.name = name;
      e.props.push_back(p);
      e.min_binary_bytes += uint64_t(plyTypeSize(type));
    } else {
      badHeaderLine(file, number, line, "unknown keyword");
    }
  }
  const bool ascii = format == "ascii";
  if (!ascii && format != "binary_little_endian" && format != "binary_big_endian")
    throw Error(file, "unknown PLY format '" + printableExcerpt(format, 30) + "'",
                "expected ascii, binary_little_endian or binary_big_endian",
                "the header is corrupt");
  const uint64_t body = bytes.size() - pos;
  uint64_t need = 0;
  for (const PlyElement& e : elements) {
    // Records of no bytes: the file size cannot bound their number, and OpenMesh would reserve
    // all of them (2^31 vertices: 12 GB for positions nobody declared).
    if (e.count > 0 && e.properties == 0)
      throw Error(file,
                  "header declares " + std::to_string(e.count) + " '" +
                      printableExcerpt(e.name, 30) + "' elements with no properties",
                  "an element without properties holds no data",
                  "the header is corrupt; re-export the file");
    // ASCII: every property takes at least one digit and one separator.
    const uint64_t per_record = ascii ? 2 * e.properties : e.min_binary_bytes;
    need += e.count * per_record;  // counts < 2^31 and per_record is small: no overflow
    if (need > body + 1)
      tooMany(file, std::to_string(e.count) + " " + printableExcerpt(e.name, 30) + " elements",
              need, body);
  }
  // The counts fit; now every record, list lengths included.
  if (ascii) {
    checkAsciiNumbers(bytes, pos, file, false);
    checkAsciiRecords(bytes, pos, elements, file);
  } else {
    checkBinaryRecords(bytes, pos, elements, format == "binary_big_endian", file);
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
  // OpenMesh reads a binary OFF (BINARY anywhere on the first line, even in a comment) with
  // binary counts that no check here could bound: a 100-byte file allocated for seconds
  // (fuzz_off). No bundled or test file is binary OFF; PLY is the binary format we read.
  if (bytes.substr(0, bytes.find('\n')).find("BINARY") != std::string::npos)
    throw Error(file, "binary OFF is not supported",
                "its counts cannot be validated before OpenMesh allocates for them",
                "convert it to ASCII OFF or to binary PLY");
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
    // Vertex records start on the line after the counts (the third count, edges, ends it).
    const std::streamoff counts_end = in.tellg();
    const size_t eol = counts_end < 0 ? std::string::npos : bytes.find('\n', size_t(counts_end));
    // Positions, then normals (N), then texture coordinates (ST) come first on a vertex line.
    const size_t prefix_end = magic.size() - 3;
    const size_t min_values = 3 +
                              (magic.substr(0, prefix_end).find('N') != std::string::npos ? 3 : 0) +
                              (magic.substr(0, prefix_end).find("ST") != std::string::npos ? 2 : 0);
    if (eol != std::string::npos) checkOffRecordLines(bytes, eol + 1, nv, nf, min_values, file);
    if (const std::streamoff after = in.tellg(); after > 0)
      checkOffFaceValues(bytes, size_t(after), magic, nv, file);
  }
}

void checkAsciiRecords(const std::string& bytes, size_t from,
                       const std::vector<PlyElement>& elements, const std::string& file) {
  Tokens tokens(bytes, from);
  std::string token;
  auto next = [&](const PlyElement& e, uint64_t record) {
    if (!tokens.next(token))
      throw Error(file,
                  "file ends inside " + printableExcerpt(e.name, 30) + " " + std::to_string(record),
                  "fewer values than the header declares", "the file is truncated");
    return token;
  };
  auto notInteger = [&](const PlyElement& e, const PlyProperty& p, const std::string& type) {
    return Error(file,
                 "'" + printableExcerpt(token, 20) + "' on line " + std::to_string(tokens.line()) +
                     " is not a valid " + type + " (" + printableExcerpt(p.name, 30) + " of " +
                     printableExcerpt(e.name, 30) + ")",
                 "the header declares that property as an integer type", "the file is corrupt");
  };
  for (const PlyElement& e : elements) {
    for (uint64_t r = 0; r < e.count; ++r) {
      for (const PlyProperty& p : e.props) {
        int64_t lo = 0, hi = 0;
        if (p.list) {
          plyIntegerRange(p.count_type, lo, hi);
          if (!isIntegerIn(next(e, r), std::max<int64_t>(lo, 0), std::min<int64_t>(hi, 1 << 20)))
            throw notInteger(e, p, "list length");
        }
        const int64_t items = p.list ? std::stoll(token) : 1;
        const bool integer = plyIntegerRange(p.type, lo, hi);
        for (int64_t k = 0; k < items; ++k)
          if (!isIntegerIn(next(e, r), lo, hi) && integer)
            throw notInteger(e, p, p.type + " value");
      }
    }
  }
}

// OpenMesh reads an ASCII OFF record by record, one line each: a vertex line with fewer values
// than it expects leaves the rest uninitialised, and face records ("k i1 .. ik [colour]") are
// read with operator>> into int like PLY integers (see isIntegerIn). So every vertex line must
// hold `min_vertex_values` numbers and every face line a count and that many integer indices;
// failures name the line. `from` is the start of the first vertex line.
void checkOffRecordLines(const std::string& bytes, size_t from, uint64_t vertices, uint64_t faces,
                         size_t min_vertex_values, const std::string& file) {
  size_t line = 1 + size_t(std::count(bytes.begin(), bytes.begin() + long(from), '\n'));
  uint64_t records = 0;
  for (size_t pos = from; pos < bytes.size() && records < vertices + faces; ++line) {
    size_t eol = bytes.find('\n', pos);
    if (eol == std::string::npos) eol = bytes.size();
    std::istringstream ls(bytes.substr(pos, eol - pos));
    pos = eol + 1;
    std::string token;
    if (!(ls >> token) || token[0] == '#') continue;  // blank or comment line
    if (records++ < vertices) {
      size_t values = 1;
      while (ls >> token && token[0] != '#') ++values;
      if (values < min_vertex_values)
        throw Error(
            file,
            "vertex line " + std::to_string(line) + " has " + std::to_string(values) + " values",
            "an OFF vertex is one line of at least " + std::to_string(min_vertex_values) +
                " numbers",
            "the file is corrupt");
      continue;
    }
    auto notInteger = [&](const std::string& what) {
      return Error(file,
                   "face " + what + " '" + printableExcerpt(token, 20) + "' on line " +
                       std::to_string(line) + " is not an integer",
                   "a face line is 'count index index ...' with integers", "the file is corrupt");
    };
    if (!isIntegerIn(token, 0, 1 << 20)) throw notInteger("vertex count");
    const long count = std::stol(token);
    for (long k = count; k > 0; --k) {
      if (!(ls >> token) || token[0] == '#')
        throw Error(file,
                    "face line " + std::to_string(line) + " lists fewer than its " +
                        std::to_string(count) + " vertex indices",
                    "a face line is 'count index index ...'", "the file is corrupt");
      if (!isIntegerIn(token, std::numeric_limits<int32_t>::min(),
                       std::numeric_limits<int32_t>::max()))
        throw notInteger("index");
    }
  }
  if (records < vertices + faces)
    throw Error(file,
                "file ends after " + std::to_string(records) + " of " +
                    std::to_string(vertices + faces) + " vertex and face lines",
                "the header declares " + std::to_string(vertices) + " vertices and " +
                    std::to_string(faces) + " faces, one per line",
                "the file is truncated or corrupt");
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

}  // namespace

void blankOffComments(std::string& bytes) {
  if (bytes.substr(0, bytes.find('\n')).find("BINARY") != std::string::npos) return;
  for (size_t i = 0; i < bytes.size(); ++i) {
    if (bytes[i] != '#') continue;
    while (i < bytes.size() && bytes[i] != '\n') bytes[i++] = ' ';
  }
}

void checkDeclaredCounts(const std::string& bytes, const std::string& ext,
                         const std::string& file) {
  if (ext == "ply") checkPly(bytes, file);
  if (ext == "off") checkOff(bytes, file);
  if (ext == "obj") checkObj(bytes, file);
}

}  // namespace proxyvis::detail
