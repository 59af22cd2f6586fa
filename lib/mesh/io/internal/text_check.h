#pragma once
// What the PLY, OFF and OBJ checks share: one tokenizer over a file's bytes and the checks of a
// single token (a number OpenMesh can read, an integer within a type's range, a count).
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>

namespace proxyvis::detail {

// Readers index with int: anything above this cannot be loaded anyway.
inline constexpr uint64_t kMaxCount = uint64_t(std::numeric_limits<int32_t>::max());

// Whitespace-separated tokens of `bytes` from `from` on, with the line each is on. With
// hash_comments, a '#' where a token would start begins a comment that runs to the end of the line
// (OFF); a '#' inside a token is part of it.
class TextTokens {
 public:
  TextTokens(const std::string& bytes, size_t from, bool hash_comments);
  // Moves to the next token; false at the end of the bytes.
  bool next();
  const std::string& token() const { return token_; }
  size_t line() const { return token_line_; }  // 1-based
  size_t end() const { return pos_; }          // the offset just past the token
  void setHashComments(bool on) { hash_comments_ = on; }

 private:
  const std::string& bytes_;
  size_t pos_;
  size_t line_;
  size_t token_line_ = 0;
  bool hash_comments_;
  std::string token_;
};

// An integer token within [lo, hi]: OpenMesh reads integers with operator>>, which takes "1.5"
// or "1e5" as 1 and leaves the rest for the next field (shifting every value after it), and
// fails the stream on values beyond the type (after which it uses uninitialised values).
bool isIntegerIn(const std::string& token, int64_t lo, int64_t hi);

// A number token of an ASCII mesh: a plain decimal (istream >> float, what OpenMesh uses, rejects
// "nan", "inf" and hex) within float range. OpenMesh reads values beyond float range (1e39) as a
// failed stream: its OFF and PLY readers then use uninitialised values and its OBJ reader drops
// the vertex, shifting every later index. Throws Error naming the file and the line; `what` is
// the part of the file ("body", "coordinates").
void checkNumberToken(const std::string& token, const std::string& file, size_t line,
                      const std::string& what);

// A header's element count: digits only, at most kMaxCount. Throws Error otherwise.
uint64_t parseCount(const std::string& token, const std::string& file, const std::string& what);

// Throws the Error for a header whose counts need more bytes than the file has. `declared` is what
// the header declares, with its counts ("3485 vertices and 6966 faces").
[[noreturn]] void tooMany(const std::string& file, const std::string& declared, uint64_t need,
                          uint64_t have);

}  // namespace proxyvis::detail
