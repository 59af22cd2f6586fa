#pragma once
// proxy-check's settings of a check as its flags give them (--rays, --distribution, --expect,
// --precision, --seed), with its defaults, and its check of one mesh pair on meshes already read:
// the two front ends that take them are apps/proxy-check and the Python module's
// proxyvis.check() (apps/python), which get the same report from the same steps.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "mesh/tri_mesh.h"
#include "proxies/check/pair_check.h"
#include "util/vec3.h"

namespace proxyvis {

// Ten billion segments take hours; more is a typo (2^64-1 would never end).
inline constexpr uint64_t kMaxCheckRays = 10'000'000'000ULL;

struct ProxyCheckSettings {
  uint64_t rays = 1'000'000;            // --rays: segments per proxy, 1 to kMaxCheckRays
  std::string distribution = "sphere";  // --distribution: sphere, or scene (scenes only)
  std::string expect;                   // --expect: outside, inside, general; empty = none
  std::string precision = "both";       // --precision: float, double or both
  uint64_t seed = 0;                    // --seed
  bool quiet = false;                   // --quiet: no progress bar
  uint64_t max_error_segments = 0;      // error segments kept (--dump-errors, --html)
};

// proxy-check's help text of a setting's flag ("--rays", "--distribution", "--expect",
// "--precision"), as --help prints it. PV_CHECK fails for another flag.
const char* proxyCheckHelp(std::string_view flag);

// The pair-check options of `settings` (a scene's pairs and a mesh pair). Throws Error for what
// proxy-check's flags refuse: rays out of range, an unknown expect, distribution or precision.
PairCheckOptions pairCheckOptions(const ProxyCheckSettings& settings);

// The check of one mesh pair as proxy-check ORIGINAL PROXY makes it. `original_double`: the
// original's vertices read in double (readDoublePositions of its file, or the caller's doubles),
// needed unless settings.precision is "float" (then ignored; may be null). Throws Error for the
// scene distribution (a pair has no camera or lights), a double reading of another size, bad
// settings or empty meshes; a missing double reading is the caller's bug (PV_CHECK).
PairCheckReport checkMeshPair(const TriMesh& original, const std::vector<Vec3d>* original_double,
                              const TriMesh& proxy, const ProxyCheckSettings& settings);

// Whether checkMeshPair needs the original's double reading for `settings`.
inline bool needsDoubleReading(const ProxyCheckSettings& settings) {
  return settings.precision != "float";
}

// Throws the Error checkMeshPair throws for the scene distribution, before anything is read.
void requireSphereDistribution(const ProxyCheckSettings& settings);

}  // namespace proxyvis
