#pragma once
// Which build of a program is running: written into what one process leaves for another (proxy
// cache keys, proxy-gen's shard manifests, render-compare's plans and unit results), so that work
// of another build, which may round or decide differently, is never mixed in.
#include <string>

namespace proxyvis {

// "exe-sha256:<hex>", the SHA-256 of the running executable's bytes (/proc/self/exe: the same
// binary copied to other machines gives the same id, any rebuild that changes it another), or the
// version and compile time when the executable cannot be read. Computed once per process.
const std::string& programBuildId();

}  // namespace proxyvis
