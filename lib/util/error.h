#pragma once
// Errors: bad input is a proxyvis::Error (the user's problem, exit code 2), an output that cannot
// be written is a WriteError (exit 3); a broken invariant is PV_CHECK (our bug, aborts).
// lib/ never calls exit(): only apps/ turn errors into exit codes (see util/app_main.h).
#include <exception>
#include <stdexcept>
#include <string>
#include <string_view>

namespace proxyvis {

enum ExitCode : int { kExitOk = 0, kExitCheckFailed = 1, kExitBadInput = 2, kExitCannotWrite = 3 };

// `text` with every byte that is not printable ASCII written as \xNN: a message stays one line of
// text whatever a file name or a corrupt file's bytes contain.
std::string printableText(std::string_view text);

// strerror(err) as a string, or "unknown error" for 0 (a failure that set no errno).
std::string systemError(int err);

// A bad-input error. The message reads "FILE: WHAT; WHY (TODO)" and is printed as one line; bytes
// that are not printable ASCII (in file names, in text quoted from a file) appear as \xNN.
// `file` may be empty for errors that are not about a file (e.g. a bad flag value).
class Error : public std::runtime_error {
 public:
  Error(std::string file, std::string what, std::string why = {}, std::string todo = {});
  const std::string& file() const { return file_; }
  virtual int exitCode() const { return kExitBadInput; }

 private:
  std::string file_;
};

// The output could not be written (permissions, full disk, missing directory): exit code 3.
class WriteError : public Error {
 public:
  using Error::Error;
  int exitCode() const override { return kExitCannotWrite; }
};

// A check requested by the user failed (e.g. a proxy guarantee): exit code 1.
class CheckFailed : public Error {
 public:
  using Error::Error;
  int exitCode() const override { return kExitCheckFailed; }
};

// What a program reports for an exception that ends its work (util/app_main.h's runApp prints
// "<program>: error: <message>" and returns exit_code; the Python module raises proxyvis.Error
// with both): an Error's message and code; out of memory as one line naming it, code 2; any
// other std::exception's text (non-printable bytes as \xNN), code 2.
struct ErrorReport {
  std::string message;
  int exit_code = kExitBadInput;
};
ErrorReport errorReport(const std::exception& e);

[[noreturn]] void checkFailed(const char* file, int line, const char* expr, const std::string& msg);

}  // namespace proxyvis

// Broken invariants: always on (cheap), print the expression and abort.
#define PV_CHECK(expr)                                                   \
  do {                                                                   \
    if (!(expr)) ::proxyvis::checkFailed(__FILE__, __LINE__, #expr, {}); \
  } while (0)
#define PV_CHECK_MSG(expr, msg)                                             \
  do {                                                                      \
    if (!(expr)) ::proxyvis::checkFailed(__FILE__, __LINE__, #expr, (msg)); \
  } while (0)
