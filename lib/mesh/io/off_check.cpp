// OFF: the keyword line and the counts, the counts against the file size, then one walk over the
// body's tokens that applies every check OpenMesh's reader needs (see checkOff).
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>

#include "mesh/io/internal/header_check.h"
#include "mesh/io/internal/printable.h"
#include "mesh/io/internal/text_check.h"
#include "util/error.h"

namespace proxyvis::detail {
namespace {

// What the keyword says about a vertex line: its leading values (positions, then normals with N,
// then texture coordinates with ST) and whether colours (C) follow them, so that its length
// varies.
struct OffVertexLayout {
  size_t values = 3;
  bool colours = false;
};

// The keyword is [ST][C][N][4][n]OFF, nothing else: a first word that only ended in "4OFF" after
// binary bytes made OpenMesh read 84 million empty faces from 490 bytes (fuzz_off).
OffVertexLayout checkKeyword(const std::string& magic, const std::string& file) {
  OffVertexLayout layout;
  size_t k = 0;
  for (const char* prefix : {"ST", "C", "N"}) {
    if (magic.compare(k, std::strlen(prefix), prefix) != 0) continue;
    k += std::strlen(prefix);
    if (prefix[0] == 'S') layout.values += 2;
    if (prefix[0] == 'C') layout.colours = true;
    if (prefix[0] == 'N') layout.values += 3;
  }
  const bool higher_dimension = k < magic.size() && (magic[k] == '4' || magic[k] == 'n');
  if (magic.compare(k + (higher_dimension ? 1 : 0), std::string::npos, "OFF") != 0)
    throw Error(file, "not an OFF file", "the first word is not OFF (or COFF, NOFF, STOFF, ...)",
                "check that the file is an OFF mesh");
  if (higher_dimension)
    throw Error(file, "4D or n-dimensional OFF ('" + magic + "')",
                "only 3D positions can be loaded", "convert the mesh to plain OFF");
  return layout;
}

// OpenMesh takes the counts from after the keyword's line and ignores the rest of that line:
// counts there were checked here while OpenMesh read 12147483648 from the next line and added
// vertices for minutes (fuzz_off). Only a comment may follow the keyword. A binary OFF (BINARY
// anywhere on that line, even in a comment, is how OpenMesh decides) has binary counts that no
// check here could bound: a 100-byte file allocated for seconds (fuzz_off). No bundled or test
// file is binary OFF; PLY is the binary format we read.
void checkKeywordLine(const std::string& rest, const std::string& file) {
  std::istringstream words(rest);
  for (std::string word; words >> word && word[0] != '#';)
    if (word != "BINARY")
      throw Error(file, "text after the OFF keyword on its line",
                  "the vertex and face counts are read from the next line",
                  "put the counts on a line of their own");
  if (rest.find("BINARY") != std::string::npos)
    throw Error(file, "binary OFF is not supported",
                "its counts cannot be validated before OpenMesh allocates for them",
                "convert it to ASCII OFF or to binary PLY");
}

// OpenMesh reads an ASCII OFF record by record, one line each: a vertex line with fewer values
// than it expects leaves the rest uninitialised, and a face record ("k i1 .. ik [colour]") is read
// with operator>> into int (see isIntegerIn). So every vertex line must hold `min_vertex_values`
// numbers and every face line a count and that many integer indices. Fed the body's tokens in
// order, from the line after the counts.
class RecordLines {
 public:
  RecordLines(uint64_t vertices, uint64_t faces, size_t min_vertex_values, const std::string& file)
      : vertices_(vertices), faces_(faces), min_vertex_values_(min_vertex_values), file_(file) {}

  void add(const std::string& token, size_t line) {
    if (line != line_) {
      finishLine();
      line_ = line;
      if (records_ == vertices_ + faces_) {
        in_record_ = false;  // lines after the records are not read
        return;
      }
      in_record_ = true;
      vertex_ = records_++ < vertices_;
      values_ = 1;
      if (!vertex_) {
        if (!isIntegerIn(token, 0, 1 << 20)) throw notInteger("vertex count", token);
        indices_left_ = std::stol(token);
        face_count_ = indices_left_;
      }
      return;
    }
    if (!in_record_) return;
    ++values_;
    if (vertex_ || indices_left_ == 0) return;  // a face's colour values are not read as indices
    if (!isIntegerIn(token, std::numeric_limits<int32_t>::min(),
                     std::numeric_limits<int32_t>::max()))
      throw notInteger("index", token);
    --indices_left_;
  }

  void finish() {
    finishLine();
    if (records_ < vertices_ + faces_)
      throw Error(file_,
                  "file ends after " + std::to_string(records_) + " of " +
                      std::to_string(vertices_ + faces_) + " vertex and face lines",
                  "the header declares " + std::to_string(vertices_) + " vertices and " +
                      std::to_string(faces_) + " faces, one per line",
                  "the file is truncated or corrupt");
  }

 private:
  void finishLine() {
    if (!in_record_) return;
    if (vertex_ && values_ < min_vertex_values_)
      throw Error(
          file_,
          "vertex line " + std::to_string(line_) + " has " + std::to_string(values_) + " values",
          "an OFF vertex is one line of at least " + std::to_string(min_vertex_values_) +
              " numbers",
          "the file is corrupt");
    if (!vertex_ && indices_left_ > 0)
      throw Error(file_,
                  "face line " + std::to_string(line_) + " lists fewer than its " +
                      std::to_string(face_count_) + " vertex indices",
                  "a face line is 'count index index ...'", "the file is corrupt");
  }
  Error notInteger(const std::string& what, const std::string& token) const {
    return Error(file_,
                 "face " + what + " '" + printableExcerpt(token, 20) + "' on line " +
                     std::to_string(line_) + " is not an integer",
                 "a face line is 'count index index ...' with integers", "the file is corrupt");
  }

  uint64_t vertices_, faces_;
  size_t min_vertex_values_;
  const std::string& file_;
  uint64_t records_ = 0;
  size_t line_ = 0;
  bool in_record_ = false, vertex_ = true;
  size_t values_ = 0;
  long indices_left_ = 0, face_count_ = 0;
};

// OpenMesh reads a face's vertex count as unsigned, so a "-34" made it loop 4 billion times
// pushing vertex handles (fuzz_off, twice: after the first fix only counts at the start of a line
// were checked). Which token it takes as a count depends on how it reads colours, so every value
// among the faces is bounded: indices are below nv, colours at most 255, a count at most the
// values that can follow; none is negative. The faces start after the vertices counted by values
// (3 per vertex, +3 with N, +2 with ST) or by lines (one vertex per line, which colours need),
// whichever comes first, so that a vertex line with more or fewer values than expected cannot
// hide a face value. Fed the tokens after the face count; the first is the edge count.
class FaceValues {
 public:
  FaceValues(const OffVertexLayout& layout, uint64_t vertices, size_t file_size,
             const std::string& file)
      : vertices_(vertices),
        file_size_(file_size),
        file_(file),
        vertex_values_(layout.colours ? std::numeric_limits<uint64_t>::max()
                                      : vertices * layout.values) {}

  void add(const std::string& token, size_t line, size_t end) {
    if (!edge_seen_) {
      edge_seen_ = true;
      return;
    }
    if (line != line_) ++lines_;
    line_ = line;
    if (values_++ < vertex_values_ && lines_ <= vertices_) return;
    const uint64_t left = (file_size_ - end) / 2 + 1;  // values that can still follow
    // The digits OpenMesh's unsigned read would take: "40.51" is a count of 40.
    const std::string digits = token.substr(0, token.find_first_not_of("0123456789"));
    if (token[0] == '-' ||
        (!digits.empty() &&
         (digits.size() > 12 || std::stoull(digits) > std::max({vertices_, left, uint64_t(255)}))))
      throw Error(file_, "value '" + printableExcerpt(token, 20) + "' among the faces",
                  "face values are vertex counts, vertex indices below " +
                      std::to_string(vertices_) + " or colours, none negative",
                  "the file is corrupt");
  }

 private:
  uint64_t vertices_;
  size_t file_size_;
  const std::string& file_;
  uint64_t vertex_values_;
  bool edge_seen_ = false;
  uint64_t values_ = 0, lines_ = 0;
  size_t line_ = 0;
};

}  // namespace

void checkOff(const std::string& bytes, const std::string& file) {
  TextTokens tokens(bytes, 0, false);
  const std::string magic = tokens.next() ? tokens.token() : std::string();
  const OffVertexLayout layout = checkKeyword(magic, file);
  const size_t keyword_line_end = std::min(bytes.find('\n', tokens.end()), bytes.size());
  checkKeywordLine(bytes.substr(tokens.end(), keyword_line_end - tokens.end()), file);

  tokens.setHashComments(true);
  std::string counts[2];
  for (std::string& count : counts) {
    if (!tokens.next())
      throw Error(file, "OFF header has no vertex and face counts", {}, "the file is corrupt");
    count = tokens.token();
  }
  const uint64_t nv = parseCount(counts[0], file, "vertices");
  const uint64_t nf = parseCount(counts[1], file, "faces");
  // ASCII records are at least "x y z\n" (6 bytes) and "3 a b c\n" (8 bytes).
  const uint64_t need = nv * 6 + nf * 8;
  if (need > bytes.size() + 1)
    tooMany(file, std::to_string(nv) + " vertices and " + std::to_string(nf) + " faces", need,
            bytes.size());

  RecordLines records(nv, nf, layout.values, file);
  FaceValues faces(layout, nv, bytes.size(), file);
  const size_t counts_line = tokens.line();
  // OpenMesh's stream fails on a token that is not a number and it goes on with uninitialised
  // values, so every token is one; then the records' and the faces' checks.
  while (tokens.next()) {
    checkNumberToken(tokens.token(), file, tokens.line(), "body");
    if (tokens.line() > counts_line) records.add(tokens.token(), tokens.line());
    faces.add(tokens.token(), tokens.line(), tokens.end());
  }
  records.finish();
}

}  // namespace proxyvis::detail
