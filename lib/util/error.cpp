#include "util/error.h"

#include <cstdio>
#include <cstdlib>

namespace proxyvis {

namespace {
std::string composeMessage(const std::string& file, const std::string& what, const std::string& why,
                           const std::string& todo) {
  std::string msg = file.empty() ? what : file + ": " + what;
  if (!why.empty()) msg += "; " + why;
  if (!todo.empty()) msg += " (" + todo + ")";
  return msg;
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
