#include "proxies/scene/output_paths.h"

#include <fmt/core.h>

#include <algorithm>
#include <cctype>
#include <set>
#include "util/lower_case.h"

namespace proxyvis {

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
    for (int n = 2; taken.count(lowerCase(unique)); ++n) unique = fmt::format("{}-{}", stem, n);
    taken.insert(lowerCase(unique));
    stems.push_back(unique);
  }
  return stems;
}

}  // namespace proxyvis
