#include "output_paths.h"

#include <fmt/core.h>

#include <algorithm>
#include <cctype>
#include <set>

namespace proxyvis {

namespace {
std::string lowercase(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}
}  // namespace

std::vector<std::string> proxyFileStems(const std::vector<std::string>& names) {
  std::vector<std::string> stems;
  std::set<std::string> taken;  // lower case: case-insensitive file systems
  for (const std::string& name : names) {
    std::string stem;
    for (unsigned char c : name)
      stem += (std::isalnum(c) || c == '.' || c == '_' || c == '-') ? char(c) : '_';
    const size_t first = stem.find_first_not_of('.');
    stem = first == std::string::npos ? std::string() : stem.substr(first);
    if (stem.empty()) stem = "mesh";
    std::string unique = stem;
    for (int n = 2; taken.count(lowercase(unique)); ++n) unique = fmt::format("{}-{}", stem, n);
    taken.insert(lowercase(unique));
    stems.push_back(unique);
  }
  return stems;
}

}  // namespace proxyvis
