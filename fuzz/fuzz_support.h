#pragma once
// What the fuzz targets count as a finding. A proxyvis::Error is the expected answer to garbage,
// provided its message is one printable line (programs print it as their single error line).
// Anything else is reported to libFuzzer by aborting: another exception type, a loaded result
// that breaks the loader's own promises. Crashes, sanitizer reports, timeouts and memory
// blow-ups are caught by libFuzzer itself (fuzz/run.sh sets the limits).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <typeinfo>

#include "util/error.h"

namespace proxyvis::fuzz {

inline std::string bytesOf(const uint8_t* data, size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

[[noreturn]] inline void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz finding: %s\n", what.c_str());
  std::fflush(stderr);
  std::abort();
}

// An error message must be one line of printable ASCII: the bytes of a corrupt file must not
// reach the terminal (escape sequences, newlines that split the one error line).
inline void checkErrorMessage(const Error& e) {
  const std::string message = e.what();
  if (message.empty()) finding("Error with an empty message");
  for (char c : message) {
    const auto u = static_cast<unsigned char>(c);
    if (u != '\t' && (u < 0x20 || u > 0x7e))
      finding("Error message with a non-printable byte " + std::to_string(u) + ": " + message);
  }
}

// Runs `parse` (which also checks whatever it produced); an Error is the expected outcome.
template <class Parse>
void parsedOrRefused(Parse&& parse) {
  try {
    parse();
  } catch (const Error& e) {
    checkErrorMessage(e);
  } catch (const std::exception& e) {
    finding(std::string("exception other than proxyvis::Error (") + typeid(e).name() +
            "): " + e.what());
  }
}

}  // namespace proxyvis::fuzz
