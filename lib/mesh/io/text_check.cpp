#include "mesh/io/internal/text_check.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>

#include "mesh/io/internal/printable.h"
#include "util/error.h"

namespace proxyvis::detail {

namespace {
bool isSpace(char c) {
  return std::isspace(static_cast<unsigned char>(c)) != 0;
}
}  // namespace

TextTokens::TextTokens(const std::string& bytes, size_t from, bool hash_comments)
    : bytes_(bytes),
      pos_(std::min(from, bytes.size())),
      line_(1 + size_t(std::count(bytes.begin(), bytes.begin() + long(pos_), '\n'))),
      hash_comments_(hash_comments) {}

bool TextTokens::next() {
  while (pos_ < bytes_.size()) {
    const char c = bytes_[pos_];
    if (hash_comments_ && c == '#') {
      while (pos_ < bytes_.size() && bytes_[pos_] != '\n') ++pos_;
    } else if (isSpace(c)) {
      line_ += c == '\n';
      ++pos_;
    } else {
      break;
    }
  }
  if (pos_ >= bytes_.size()) return false;
  const size_t begin = pos_;
  while (pos_ < bytes_.size() && !isSpace(bytes_[pos_])) ++pos_;
  token_.assign(bytes_, begin, pos_ - begin);
  token_line_ = line_;
  return true;
}

bool isIntegerIn(const std::string& t, int64_t lo, int64_t hi) {
  const size_t sign = (!t.empty() && (t[0] == '-' || t[0] == '+')) ? 1 : 0;
  if (t.size() <= sign || t.size() - sign > 12 ||
      t.find_first_not_of("0123456789", sign) != std::string::npos)
    return false;
  const int64_t v = std::stoll(t);
  return v >= lo && v <= hi;
}

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

void tooMany(const std::string& file, const std::string& declared, uint64_t need, uint64_t have) {
  throw Error(file, "header declares " + declared,
              "that needs at least " + std::to_string(need) + " bytes but the file has " +
                  std::to_string(have),
              "the file is truncated or its header is corrupt");
}

}  // namespace proxyvis::detail
