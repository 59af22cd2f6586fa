#include "util/error.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>

namespace proxyvis {

std::string systemError(int err) {
  return err == 0 ? std::string("unknown error") : std::string(std::strerror(err));
}

std::string printableText(std::string_view text) {
  static const char* kHex = "0123456789abcdef";
  std::string out;
  out.reserve(text.size());
  for (const unsigned char c : text) {
    if (c >= 0x20 && c < 0x7f) {
      out += char(c);
    } else {
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 15];
    }
  }
  return out;
}

namespace {
std::string composeMessage(const std::string& file, const std::string& what, const std::string& why,
                           const std::string& todo) {
  std::string msg = file.empty() ? what : file + ": " + what;
  if (!why.empty()) msg += "; " + why;
  if (!todo.empty()) msg += " (" + todo + ")";
  return printableText(msg);
}
}  // namespace

Error::Error(std::string file, std::string what, std::string why, std::string todo)
    : std::runtime_error(composeMessage(file, what, why, todo)), file_(std::move(file)) {}

ErrorReport errorReport(const std::exception& e) {
  if (const auto* error = dynamic_cast<const Error*>(&e)) return {error->what(), error->exitCode()};
  if (dynamic_cast<const std::bad_alloc*>(&e))
    return {"out of memory; the input is too large for this machine", kExitBadInput};
  return {printableText(e.what()), kExitBadInput};
}

void checkFailed(const char* file, int line, const char* expr, const std::string& msg) {
  // One fprintf so that messages from several threads do not interleave.
  std::fprintf(stderr, "internal error at %s:%d: check '%s' failed%s%s\n", file, line, expr,
               msg.empty() ? "" : ": ", msg.c_str());
  std::abort();
}

}  // namespace proxyvis
