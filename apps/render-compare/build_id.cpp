#include "build_id.h"

#include <fmt/format.h>

#include <fstream>
#include <vector>

#include "util/fnv1a.h"

namespace proxyvis {

const std::string& buildId() {
  static const std::string id = [] {
    std::ifstream in("/proc/self/exe", std::ios::binary);
    Fnv1a hash;
    std::vector<char> buffer(1 << 20);
    while (in) {
      in.read(buffer.data(), std::streamsize(buffer.size()));
      hash.add(std::string_view(buffer.data(), size_t(in.gcount())));
    }
    return fmt::format("{}-{:016x}", PROXYVIS_VERSION, hash.h);
  }();
  return id;
}

}  // namespace proxyvis
