#pragma once
// Text quoted from a file into a message: a corrupt file can hold any bytes, and an error line
// must stay one line of printable text on the terminal.
#include <string>
#include <string_view>

namespace proxyvis::detail {

// The first `max_chars` characters of `text` with every byte outside printable ASCII (control
// characters, newlines, bytes >= 127) replaced by '?'.
inline std::string printableExcerpt(std::string_view text, size_t max_chars = 60) {
  std::string shown(text.substr(0, max_chars));
  for (char& c : shown)
    if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) c = '?';
  return shown;
}

}  // namespace proxyvis::detail
