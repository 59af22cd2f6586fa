#include "render/render_scene_build.h"

#include <fmt/core.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <string>

namespace proxyvis {

namespace {

// A cgroup limit file holds a byte count, or "max" (v2) / a huge number (v1) for no limit.
uint64_t cgroupLimit(const char* path) {
  std::ifstream in(path);
  std::string text;
  if (!(in >> text) || text.empty() || text.find_first_not_of("0123456789") != std::string::npos)
    return 0;
  try {
    return std::stoull(text);
  } catch (...) {
    return 0;  // out of range: no usable limit
  }
}

std::string gigabytes(double bytes) {
  return fmt::format("{:.1f} GB", bytes / 1e9);
}

std::string gibibytes(double bytes) {
  return fmt::format("{:.3g} GiB", bytes / double(1ull << 30));
}

std::string millions(uint64_t n) {
  return fmt::format("{:.1f} M", double(n) / 1e6);
}

}  // namespace

uint64_t availableMemoryBytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
  uint64_t bytes = pages > 0 && page > 0 ? uint64_t(pages) * uint64_t(page) : 0;
  for (const char* path :
       {"/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory/memory.limit_in_bytes"}) {
    const uint64_t limit = cgroupLimit(path);
    if (limit > 0 && (bytes == 0 || limit < bytes)) bytes = limit;
  }
  return bytes;
}

double defaultMemoryBudgetBytes() {
  const uint64_t available = availableMemoryBytes();
  return available == 0 ? kMaxDefaultBudgetBytes
                        : std::min(kMaxDefaultBudgetBytes, 0.5 * double(available));
}

std::string BuildChoice::description() const {
  const std::string size =
      fmt::format("{} triangles, ~{} est.", millions(flat_triangles), gigabytes(estimated_bytes));
  if (!has_instances) return "one BVH of the placed meshes (" + size + ")";
  return flat ? "flattened BVH (" + size + ")" : "instanced BVHs (flattened: " + size + ")";
}

BuildChoice chooseBuild(InstanceBuild mode, bool has_instances, uint64_t flat_triangles,
                        double budget_bytes) {
  BuildChoice c;
  c.has_instances = has_instances;
  c.flat_triangles = flat_triangles;
  c.estimated_bytes = kFlatBytesPerTriangle * double(flat_triangles);
  if (!has_instances) {
    c.flat = true;
    c.reason = "no instances: every mesh is in one BVH";
    return c;
  }
  if (mode == InstanceBuild::kFlat) {
    c.flat = true;
    c.reason = "--build flat";
    return c;
  }
  if (mode == InstanceBuild::kInstanced) {
    c.reason = "--build instanced";
    return c;
  }
  c.budget_bytes = budget_bytes < 0 ? defaultMemoryBudgetBytes() : budget_bytes;
  const bool fits = c.estimated_bytes <= c.budget_bytes;
  const bool pays = flat_triangles <= kAutoFlattenMaxTriangles;
  c.flat = fits && pays;
  if (c.flat)
    c.reason = fmt::format(
        "--build auto: flattened tracing is expected faster at this size and its ~{} fit the "
        "memory budget of {} (--memory-budget)",
        gigabytes(c.estimated_bytes), gibibytes(c.budget_bytes));
  else if (!fits)
    c.reason = fmt::format(
        "--build auto: flattening would need ~{}, over the memory budget of {} (--memory-budget)",
        gigabytes(c.estimated_bytes), gibibytes(c.budget_bytes));
  else
    c.reason = fmt::format(
        "--build auto: above {} flattened triangles a flattened BVH was measured no faster than "
        "instances and takes far longer to build (--build flat forces it)",
        millions(kAutoFlattenMaxTriangles));
  return c;
}

}  // namespace proxyvis
