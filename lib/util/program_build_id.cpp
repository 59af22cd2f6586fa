#include "program_build_id.h"

#include <fmt/core.h>

#include <fstream>
#include <iterator>

#include "sha256.h"

namespace proxyvis {

const std::string& programBuildId() {
  static const std::string id = [] {
    std::ifstream in("/proc/self/exe", std::ios::binary);
    const std::string exe((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.is_open() && !in.bad() && !exe.empty()) return "exe-sha256:" + sha256Hex(exe);
    return fmt::format("version:{} compiled:{} {}", PROXYVIS_VERSION, __DATE__, __TIME__);
  }();
  return id;
}

}  // namespace proxyvis
