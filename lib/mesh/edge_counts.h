#pragma once
// How many faces share each undirected edge of a triangle list: the one count behind the mesh
// validation report (boundary, non-manifold, odd edges), the ray-parity solid of the proxy
// generators and the exact containment check. The counts mean something only on welded indices
// (one index per position) without triangles that repeat a corner; callers weld their own way.
#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace proxyvis {

struct EdgeCounts {
  uint64_t edges = 0;         // distinct undirected edges
  uint64_t boundary = 0;      // edges with one face
  uint64_t non_manifold = 0;  // edges with more than two faces
  uint64_t odd = 0;           // non-manifold edges with an odd number (3, 5, ...) of faces
};

// `faces`: triangles as three vertex indices each (any integer type). Sorts the 3F edges: O(F log
// F).
template <typename Face>
EdgeCounts countEdges(const std::vector<Face>& faces) {
  std::vector<std::pair<uint64_t, uint64_t>> edges;
  edges.reserve(faces.size() * 3);
  for (const Face& f : faces)
    for (int k = 0; k < 3; ++k)
      edges.push_back(std::minmax(uint64_t(f[k]), uint64_t(f[(k + 1) % 3])));
  std::sort(edges.begin(), edges.end());
  EdgeCounts c;
  for (size_t begin = 0; begin < edges.size();) {
    size_t end = begin + 1;
    while (end < edges.size() && edges[end] == edges[begin]) ++end;
    const size_t n = end - begin;
    ++c.edges;
    c.boundary += n == 1;
    c.non_manifold += n > 2;
    c.odd += n > 2 && n % 2 == 1;
    begin = end;
  }
  return c;
}

}  // namespace proxyvis
