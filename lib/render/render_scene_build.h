#pragma once
// How a scene's instances are traced: as Embree instances of one BVH per mesh, or flattened
// (every instance's triangles copied into one BVH, originals and proxies alike). Flattened
// tracing is expected to be faster wherever there are instances (earlier measurements: ecosys 78
// ns flattened vs 140 ns instanced per shadow ray; on a loaded shared machine it was not:
// docs/rendering.md, "BVH build") but costs the memory of every instance's triangles; `auto`
// flattens when the estimated bytes of the flattened Embree scenes fit a memory budget.
#include <cstdint>
#include <string>

namespace proxyvis {

enum class InstanceBuild { kInstanced, kFlat, kAuto };

// Bytes Embree allocates per flattened triangle at its peak during the build (vertex and index
// buffers, the BVH with spatial splits, build scratch), from the device's memory monitor
// (bench_scene_trace, Embree 3.13.5): 156 on ecosys (12.3 M triangles; 113 once built), 182 on
// foliage (1 M; 113 once built). The larger, rounded up: the estimate must not undershoot.
inline constexpr double kFlatBytesPerTriangle = 185;
// `auto` flattens only scenes up to this many flattened triangles: flattening paid on foliage
// (1 M triangles: instanced exact was 0.93x the flattened one) but not on ecosys (12.3 M: 905 vs
// 864 ns CPU per shadow ray flattened vs instanced, and 21 s to build instead of 0.9 s;
// bench_scene_trace, 2 threads), whose flattened BVH no longer fits any cache.
inline constexpr uint64_t kAutoFlattenMaxTriangles = 4'000'000;
// The default budget: the smaller of this and half the memory the process may use.
inline constexpr double kMaxDefaultBudgetBytes = 4.0 * (1ull << 30);

// Physical memory, or the cgroup's memory limit when one is set and smaller (cgroup v2
// memory.max, v1 memory.limit_in_bytes); 0 if unknown.
uint64_t availableMemoryBytes();
// min(kMaxDefaultBudgetBytes, availableMemoryBytes() / 2).
double defaultMemoryBudgetBytes();

struct BuildChoice {
  bool flat = false;  // instances flattened (or there are none)
  bool has_instances = false;
  uint64_t flat_triangles = 0;  // triangles of the flattened scenes (originals + proxies)
  double estimated_bytes = 0;   // kFlatBytesPerTriangle x flat_triangles
  double budget_bytes = 0;      // the budget `auto` compared against (0 unless auto)
  std::string reason;           // one sentence: why this build

  const char* name() const { return flat ? "flat" : "instanced"; }
  // "flattened BVH (12.2 M triangles, ~1.7 GB est.)" or "instanced BVHs (...)".
  std::string description() const;
};

// The decision for a scene whose flattened Embree scenes would hold `flat_triangles` triangles.
// A budget < 0 means defaultMemoryBudgetBytes().
BuildChoice chooseBuild(InstanceBuild mode, bool has_instances, uint64_t flat_triangles,
                        double budget_bytes);

}  // namespace proxyvis
