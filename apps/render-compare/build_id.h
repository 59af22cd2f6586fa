#pragma once
// Which build of render-compare wrote a plan or a unit result: a unit rendered by another binary
// may trace or round differently, so the merge refuses to mix builds.
#include <string>

namespace proxyvis {

// "<version>-<16 hex digits>": the version and the FNV-1a 64 hash of this executable's bytes
// (/proc/self/exe), computed once. The same binary copied to other machines gives the same id.
const std::string& buildId();

}  // namespace proxyvis
