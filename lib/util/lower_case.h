#pragma once
// ASCII lower case, for what compares case-insensitively: file extensions (".PLY" is a PLY
// file), hex digests and mesh names turned into file names.
#include <algorithm>
#include <filesystem>
#include <string>

namespace proxyvis {

inline std::string lowerCase(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return char(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c); });
  return s;
}

// The extension with its dot, in lower case ("" when there is none).
inline std::string lowerExtension(const std::filesystem::path& path) {
  return lowerCase(path.extension().string());
}

}  // namespace proxyvis
