// Inside proxies from CGAL: alpha_wrap_3 carving from interior seed points (P. Portaneri et al.,
// "Alpha wrapping with an offset", ACM TOG 41(4), 2022, §5: seeds start the carving inside),
// and hole filling (P. Liepa, "Filling holes in meshes", SGP 2003) for scans such as bun_zipper.
#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/alpha_wrap_3.h>
#include <fmt/core.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>

#include "proxies/inside/inside_proxy.h"
#include "proxies/shared/cgal/parity_solid_mesh.h"
#include "proxies/shared/cgal/weld.h"
#include "proxies/shared/cgal/wrap_budget.h"
#include "proxies/shared/input_geometry.h"
#include "proxies/shared/parity_solid.h"
#include "proxies/shared/wrap_size.h"
#include "util/error.h"

namespace proxyvis {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using cgal::Kernel;
using cgal::Point3;
using cgal::SurfaceMesh;
using cgal::toWeldedMesh;
using Side = CGAL::Side_of_triangle_mesh<SurfaceMesh, Kernel>;
using Tree = Side::AABB_tree;

size_t countBorderHalfedges(const SurfaceMesh& sm) {
  size_t n = 0;
  for (auto h : sm.halfedges())
    if (sm.is_border(h)) ++n;
  return n;
}

// The input as a ray-parity solid (its own triangles, non-manifold edges split, so a watertight
// non-manifold scan has an inside too), or an Error that says why it has no inside.
SurfaceMesh solidInput(const TriMesh& input, const char* method) {
  cgal::ParitySolid solid = cgal::makeParitySolid(input);
  if (!solid.watertight())
    throw noInteriorError(input.source, solid.boundary_edges, solid.odd_edges,
                          fmt::format("the inside proxy ({})", method));
  return std::move(solid.mesh);
}

// The faces whose corners are not collinear. CGAL's inside test retries a ray that hits a
// degenerate face with another one, without end when every ray does (all faces degenerate);
// a zero-area face bounds nothing, so leaving it out changes no answer.
std::vector<SurfaceMesh::Face_index> nonDegenerateFaces(const SurfaceMesh& sm) {
  std::vector<SurfaceMesh::Face_index> kept;
  for (auto f : sm.faces()) {
    const auto h = sm.halfedge(f);
    if (!CGAL::collinear(sm.point(sm.source(h)), sm.point(sm.target(h)),
                         sm.point(sm.target(sm.next(h)))))
      kept.push_back(f);
  }
  return kept;
}

// Grid points inside the mesh whose distance to the surface is a local maximum over their 26
// neighbours and exceeds min_depth; deepest first, at most max_seeds. The grid has at most
// (seed_grid + 1)^3 points and the budget is polled for every slice of it.
std::vector<Point3> findSeeds(const SurfaceMesh& sm, const InsideWrapOptions& options,
                              double min_depth, const std::string& source) {
  const std::vector<SurfaceMesh::Face_index> kept = nonDegenerateFaces(sm);
  if (kept.empty())
    throw Error(source, "every face is degenerate (zero area)",
                "the mesh encloses no volume to seed an inside wrap", "check the mesh");
  Tree tree(kept.begin(), kept.end(), sm);
  tree.accelerate_distance_queries();
  Side side(tree);
  const CGAL::Bbox_3 box = PMP::bbox(sm);
  const double longest =
      std::max({box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin()});
  const int grid = std::clamp(options.seed_grid, 2, 200);
  const double h = longest / grid;
  if (!(h > 0)) throw Error(source, "the mesh has no extent", "there is no inside to seed");
  const int n[3] = {std::min(grid, int(std::ceil((box.xmax() - box.xmin()) / h))) + 1,
                    std::min(grid, int(std::ceil((box.ymax() - box.ymin()) / h))) + 1,
                    std::min(grid, int(std::ceil((box.zmax() - box.zmin()) / h))) + 1};
  auto point = [&](int i, int j, int k) {
    return Point3(box.xmin() + (i + 0.5) * h, box.ymin() + (j + 0.5) * h,
                  box.zmin() + (k + 0.5) * h);
  };
  auto index = [&](int i, int j, int k) { return (size_t(k) * n[1] + j) * n[0] + i; };
  std::vector<double> depth(size_t(n[0]) * n[1] * n[2], 0.0);
  std::atomic<bool> stopped{false};
  tbb::parallel_for(0, n[2], [&](int k) {
    if (stopped || (options.budget && options.budget->expired())) {
      stopped = true;
      return;
    }
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        const Point3 p = point(i, j, k);
        if (side(p) == CGAL::ON_BOUNDED_SIDE)
          depth[index(i, j, k)] = std::sqrt(tree.squared_distance(p));
      }
  });
  checkBudget(options.budget, "the seed search of the inside wrap");
  std::vector<std::pair<double, Point3>> maxima;
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        const double d = depth[index(i, j, k)];
        if (!(d > min_depth)) continue;
        bool is_max = true;
        for (int dk = -1; dk <= 1 && is_max; ++dk)
          for (int dj = -1; dj <= 1 && is_max; ++dj)
            for (int di = -1; di <= 1 && is_max; ++di) {
              const int a = i + di, b = j + dj, c = k + dk;
              if (a < 0 || b < 0 || c < 0 || a >= n[0] || b >= n[1] || c >= n[2]) continue;
              if (depth[index(a, b, c)] > d) is_max = false;
            }
        if (is_max) maxima.emplace_back(d, point(i, j, k));
      }
  std::stable_sort(maxima.begin(), maxima.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<Point3> seeds;
  for (size_t i = 0; i < maxima.size() && i < options.max_seeds; ++i)
    seeds.push_back(maxima[i].second);
  return seeds;
}

}  // namespace

TriMesh fillHoles(const TriMesh& input, size_t* holes) {
  SurfaceMesh sm = toWeldedMesh(input);
  size_t filled = 0;
  std::vector<SurfaceMesh::Halfedge_index> borders;
  for (auto h : sm.halfedges())
    if (sm.is_border(h)) borders.push_back(h);
  std::vector<bool> seen(sm.number_of_halfedges(), false);
  for (auto h : borders) {
    if (seen[h.idx()] || !sm.is_border(h)) continue;
    for (auto g : CGAL::halfedges_around_face(h, sm)) seen[g.idx()] = true;
    std::vector<SurfaceMesh::Face_index> new_faces;
    std::vector<SurfaceMesh::Vertex_index> new_vertices;
    PMP::triangulate_refine_and_fair_hole(sm, h, std::back_inserter(new_faces),
                                          std::back_inserter(new_vertices));
    ++filled;
  }
  if (holes) *holes = filled;
  if (!CGAL::is_closed(sm))
    throw Error(
        input.source,
        fmt::format("{} boundary edges remain after hole filling", countBorderHalfedges(sm)),
        "the holes could not all be triangulated", "repair the mesh, or use --kind outside");
  if (!PMP::is_outward_oriented(sm)) PMP::reverse_face_orientations(sm);
  return cgal::fromSurfaceMesh(sm, input.source);
}

TriMesh makeInsideWrapProxy(const TriMesh& input, const InsideWrapOptions& options,
                            InsideStats* stats) {
  if (!(options.alpha > 0) || !(options.offset > 0))
    throw Error("", "alpha and offset must be positive fractions of the diagonal",
                "alpha_wrap_3 is undefined otherwise");
  requireProxyGeometry(input, GeometryNeed::kSolid, "an inside wrap");
  requireWrapSize(input, options.alpha, options.offset, "the inside wrap");
  SurfaceMesh sm = solidInput(input, "wrap");
  const double diag = input.diagonal();
  const double offset = options.offset * diag;
  std::vector<Point3> seeds = findSeeds(sm, options, 2 * offset, input.source);
  if (seeds.empty())
    throw Error(input.source, "no interior point is deeper than twice the offset",
                "the inner wrap is carved from interior seeds", "lower --offset");
  if (stats) stats->seeds = seeds.size();
  SurfaceMesh wrap;
  // seed_points belongs to the SECOND (output) named-parameter pack: in the first it is
  // silently ignored and the result is an outer wrap (measured with CGAL 5.5).
  cgal::WrapBudgetVisitor visitor(options.budget, kMaxEstimatedWrapFaces / 4, input.source);
  CGAL::alpha_wrap_3(sm, options.alpha * diag, offset, wrap, CGAL::parameters::default_values(),
                     CGAL::parameters::seed_points(seeds).visitor(visitor));
  if (wrap.number_of_faces() == 0)
    throw Error(input.source, "the inner alpha wrap is empty", "no seed region could be carved",
                "lower --alpha or --offset");
  TriMesh out = cgal::fromSurfaceMesh(wrap, "inside wrap of " + input.source);
  // The carved region is the inside here, and the wrap's faces point into it: flip them.
  if (out.signedVolume() < 0)
    for (Triangle& t : out.triangles) std::swap(t[1], t[2]);
  return out;
}

}  // namespace proxyvis
