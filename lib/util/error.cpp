#include "util/error.h"

#include <cstdio>
#include <cstdlib>

namespace proxyvis {

namespace {
// Messages quote the input (a key, a token, a library's diagnostic): its control and non-ASCII
// bytes are written as \xNN so the message stays one printable line on any terminal.
std::string printable(const std::string& text) {
  static const char kHex[] = "0123456789abcdef";
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x20 && u < 0x7f) {
      out += c;
    } else {
      out += "\\x";
      out += kHex[u >> 4];
      out += kHex[u & 15];
    }
  }
  return out;
}

std::string composeMessage(const std::string& file, const std::string& what, const std::string& why,
                           const std::string& todo) {
  std::string msg = file.empty() ? what : file + ": " + what;
  if (!why.empty()) msg += "; " + why;
  if (!todo.empty()) msg += " (" + todo + ")";
  return printable(msg);
}
}  // namespace

Error::Error(std::string file, std::string what, std::string why, std::string todo)
    : std::runtime_error(composeMessage(file, what, why, todo)), file_(std::move(file)) {}

void checkFailed(const char* file, int line, const char* expr, const std::string& msg) {
  // One fprintf so that messages from several threads do not interleave.
  std::fprintf(stderr, "internal error at %s:%d: check '%s' failed%s%s\n", file, line, expr,
               msg.empty() ? "" : ": ", msg.c_str());
  std::abort();
}

}  // namespace proxyvis
