#include "proxies/shared/internal/refine_cycles.h"

#include <CGAL/Polygon_mesh_processing/self_intersections.h>

#include <map>
#include <utility>

#include "mesh/cgal_bridge.h"
#include "proxies/shared/internal/relax_toward_input.h"

namespace proxyvis::cgal {
namespace {

// Loop's 1-to-4 split without smoothing: every edge gets its midpoint (rounded to float).
TriMesh splitEdges(const TriMesh& mesh) {
  TriMesh out = mesh;
  out.triangles.clear();
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> mid;
  auto midpoint = [&](uint32_t a, uint32_t b) {
    const auto key = std::minmax(a, b);
    auto [it, inserted] = mid.try_emplace({key.first, key.second}, uint32_t(out.vertices.size()));
    if (inserted) out.vertices.push_back((mesh.vertices[a] + mesh.vertices[b]) * 0.5f);
    return it->second;
  };
  for (const Triangle& t : mesh.triangles) {
    const uint32_t ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
    out.triangles.push_back({t[0], ab, ca});
    out.triangles.push_back({ab, t[1], bc});
    out.triangles.push_back({ca, bc, t[2]});
    out.triangles.push_back({ab, bc, ca});
  }
  return out;
}

// A float midpoint leaves its face's plane by a rounding error, which can reach an input
// surface that the relaxation brought the face close to.
bool touchesInput(const TriMesh& mesh, const InputBound& bound) {
  for (const Triangle& t : mesh.triangles)
    if (bound.touches(
            {Vec3d(mesh.vertices[t[0]]), Vec3d(mesh.vertices[t[1]]), Vec3d(mesh.vertices[t[2]])}))
      return true;
  return false;
}

}  // namespace

bool crossesItself(const TriMesh& mesh) {
  SurfaceMesh sm;
  return !toSurfaceMesh(mesh, sm) || CGAL::Polygon_mesh_processing::does_self_intersect(sm);
}

int refineCycles(TriMesh& mesh, const InputBound& bound, int cycles, int relax_sweeps,
                 const CollapseToBudget& collapse_to_budget, const TimeBudget* budget) {
  int improved = 0;
  TriMesh current = mesh;
  for (int cycle = 0; cycle < cycles; ++cycle) {
    if (budget && budget->expired()) break;
    TriMesh fine = splitEdges(current);
    if (touchesInput(fine, bound)) break;
    relaxTowardInput(fine, bound, relax_sweeps, budget);
    std::optional<TriMesh> next = collapse_to_budget(fine);
    if (!next) break;
    relaxTowardInput(*next, bound, relax_sweeps, budget);
    if (crossesItself(*next)) break;
    current = *next;
    if (next->signedVolume() < mesh.signedVolume()) {
      mesh = std::move(*next);
      ++improved;
    }
  }
  return improved;
}

}  // namespace proxyvis::cgal
