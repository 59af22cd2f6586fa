#include "mesh/validation.h"

#include <algorithm>
#include <array>
#include <bit>
#include <numeric>
#include <vector>

#include "mesh/edge_counts.h"
#include "mesh/internal/self_intersections.h"
#include "util/disjoint_sets.h"

namespace proxyvis {
namespace {

// Maps every vertex to the first vertex with bit-identical coordinates (MANIFEST: topology is
// computed after welding positions that are exactly equal). Equal means equal as numbers, so
// -0 and +0 weld (the teapot writes both); non-finite vertices weld with nobody.
std::vector<uint32_t> weldExactDuplicates(const std::vector<Vec3f>& v) {
  auto bits = [](float x) { return std::bit_cast<uint32_t>(x == 0.0f ? 0.0f : x); };
  auto key = [&](uint32_t i) {
    return std::array<uint32_t, 3>{bits(v[i].x), bits(v[i].y), bits(v[i].z)};
  };
  std::vector<uint32_t> order(v.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
    const auto ka = key(a), kb = key(b);
    return ka != kb ? ka < kb : a < b;
  });
  std::vector<uint32_t> weld(v.size());
  for (size_t k = 0; k < order.size(); ++k) {
    const uint32_t i = order[k];
    const bool same = k > 0 && isFinite(v[i]) && key(order[k - 1]) == key(i);
    weld[i] = same ? weld[order[k - 1]] : i;
  }
  return weld;
}

// Vertices whose incident triangles form more than one fan: per vertex, the "link" graph joins
// the two other corners of every incident triangle; one fan = one connected link.
uint64_t countNonManifoldVertices(const std::vector<Triangle>& tris) {
  struct Corner {
    uint32_t v, a, b;
  };
  std::vector<Corner> corners;
  corners.reserve(tris.size() * 3);
  for (const Triangle& t : tris)
    for (int k = 0; k < 3; ++k) corners.push_back({t[k], t[(k + 1) % 3], t[(k + 2) % 3]});
  std::sort(corners.begin(), corners.end(),
            [](const Corner& x, const Corner& y) { return x.v < y.v; });

  uint64_t count = 0;
  std::vector<uint32_t> local;
  for (size_t begin = 0; begin < corners.size();) {
    size_t end = begin;
    while (end < corners.size() && corners[end].v == corners[begin].v) ++end;
    local.clear();
    for (size_t c = begin; c < end; ++c) {
      local.push_back(corners[c].a);
      local.push_back(corners[c].b);
    }
    std::sort(local.begin(), local.end());
    local.erase(std::unique(local.begin(), local.end()), local.end());
    auto id = [&](uint32_t x) {
      return uint32_t(std::lower_bound(local.begin(), local.end(), x) - local.begin());
    };
    DisjointSets link(local.size());
    for (size_t c = begin; c < end; ++c) link.unite(id(corners[c].a), id(corners[c].b));
    size_t fans = 0;
    for (uint32_t i = 0; i < local.size(); ++i) fans += link.find(i) == i;
    count += fans > 1;
    begin = end;
  }
  return count;
}

}  // namespace

MeshReport validateMesh(const TriMesh& mesh, const ValidationOptions& options) {
  MeshReport r;
  r.vertices = mesh.vertices.size();
  r.faces = mesh.triangles.size();
  const size_t nv = mesh.vertices.size();

  std::vector<char> referenced(nv, 0);
  for (const Triangle& t : mesh.triangles)
    for (uint32_t i : t)
      if (i < nv) referenced[i] = 1;
  for (size_t i = 0; i < nv; ++i) {
    const bool finite = isFinite(mesh.vertices[i]);
    r.nonfinite_vertices += !finite;
    r.unreferenced_vertices += !referenced[i];
    if (referenced[i] && finite) r.bounds.extend(mesh.vertices[i]);
  }

  // Topology on welded, non-degenerate triangles. Triangles with an out-of-range index cannot
  // come from loadMesh; one built in memory is counted as degenerate rather than crash.
  const std::vector<uint32_t> weld = weldExactDuplicates(mesh.vertices);
  std::vector<Triangle> tris;
  tris.reserve(mesh.triangles.size());
  for (const Triangle& t : mesh.triangles) {
    if (t[0] >= nv || t[1] >= nv || t[2] >= nv) {
      ++r.degenerate_faces;
      continue;
    }
    const Triangle w{weld[t[0]], weld[t[1]], weld[t[2]]};
    if (w[0] == w[1] || w[1] == w[2] || w[0] == w[2]) {
      ++r.degenerate_faces;
      continue;
    }
    // Three distinct but collinear corners: no area, no normal, but its edges still join its
    // neighbours, so it stays in the topology (a sliver does not open a closed mesh).
    const Vec3f &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    if (isFinite(a) && isFinite(b) && isFinite(c) && detail::areCollinear(a, b, c))
      ++r.degenerate_faces;
    tris.push_back(w);
  }

  std::vector<Triangle> sorted_tris = tris;
  for (Triangle& t : sorted_tris) std::sort(t.begin(), t.end());
  std::sort(sorted_tris.begin(), sorted_tris.end());
  for (size_t i = 1; i < sorted_tris.size(); ++i)
    r.duplicate_faces += sorted_tris[i] == sorted_tris[i - 1];

  const EdgeCounts edges = countEdges(tris);
  r.boundary_edges = edges.boundary;
  r.non_manifold_edges = edges.non_manifold;
  r.odd_edges = edges.odd;
  // Components share a (welded) vertex, as in the MANIFEST: a pinched vertex joins its fans.
  DisjointSets vertex_sets(nv);
  std::vector<char> used(nv, 0);
  for (const Triangle& t : tris) {
    vertex_sets.unite(t[0], t[1]);
    vertex_sets.unite(t[1], t[2]);
    used[t[0]] = used[t[1]] = used[t[2]] = 1;
  }
  for (uint32_t i = 0; i < nv; ++i) r.components += used[i] && vertex_sets.find(i) == i;
  r.non_manifold_vertices = countNonManifoldVertices(tris);

  r.closed = !tris.empty() && r.boundary_edges == 0 && r.non_manifold_edges == 0;
  r.watertight = !tris.empty() && r.boundary_edges == 0 && r.odd_edges == 0;
  r.manifold = r.non_manifold_edges == 0 && r.non_manifold_vertices == 0;
  if (r.closed && r.manifold) {
    const int64_t v = std::count(used.begin(), used.end(), 1);
    const int64_t euler = v - int64_t(edges.edges) + int64_t(tris.size());
    r.genus = (2 * int64_t(r.components) - euler) / 2;
  }
  if (r.closed && r.nonfinite_vertices == 0) r.volume = mesh.signedVolume();
  if (options.self_intersections)
    r.self_intersecting_pairs = detail::countSelfIntersectingPairs(mesh);
  return r;
}

}  // namespace proxyvis
