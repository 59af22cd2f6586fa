#pragma once
// Adding a triangle soup to an OpenMesh half-edge mesh without its "complex vertex / complex
// edge / patch re-linking failed" rejections (printed on stderr, the face dropped): each face is
// tested first with the same conditions PolyConnectivity::add_face applies, and a face that would
// be rejected (a non-manifold edge or vertex of the input) is added on copies of its vertices
// instead, one layer of copies after another, so no face is lost and nothing is printed.
#include <OpenMesh/Core/Mesh/PolyConnectivity.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "mesh/tri_mesh.h"

namespace proxyvis {

// OpenMesh's progress log (e.g. the multiple-choice decimater's "no collapses performed in over
// 20 iterations in a row" when it stalls) is not for the user: switched off for the process.
// Its error stream stays on: the mesh loader captures it for its messages.
inline void silenceOpenMeshLog() {
  static const bool silenced = [] {
    ::omlog().disable();
    return true;
  }();
  (void)silenced;
}

// Whether mesh.add_face(v[0], v[1], v[2]) would succeed (OpenMesh 9 PolyConnectivity::add_face:
// every vertex on a boundary or isolated, every existing edge free on the face's side, and a
// free gap to relink around every vertex between two existing edges).
template <typename Mesh>
bool openMeshAccepts(const Mesh& mesh, const std::array<typename Mesh::VertexHandle, 3>& v) {
  using HalfedgeHandle = typename Mesh::HalfedgeHandle;
  std::array<HalfedgeHandle, 3> he;
  for (int i = 0; i < 3; ++i) {
    if (!mesh.is_boundary(v[i])) return false;  // complex vertex
    he[i] = mesh.find_halfedge(v[i], v[(i + 1) % 3]);
    if (he[i].is_valid() && !mesh.is_boundary(he[i])) return false;  // complex edge
  }
  for (int i = 0; i < 3; ++i) {
    const HalfedgeHandle inner_prev = he[i], inner_next = he[(i + 1) % 3];
    if (!inner_prev.is_valid() || !inner_next.is_valid()) continue;
    if (mesh.next_halfedge_handle(inner_prev) == inner_next) continue;
    HalfedgeHandle boundary_prev = mesh.opposite_halfedge_handle(inner_next);
    size_t steps = 0;
    do {
      boundary_prev = mesh.opposite_halfedge_handle(mesh.next_halfedge_handle(boundary_prev));
      if (++steps > mesh.n_halfedges()) return false;
    } while (!mesh.is_boundary(boundary_prev));
    if (boundary_prev == inner_prev) return false;  // patch re-linking failed
  }
  return true;
}

// Adds `triangles` over `vertices` (handles of the mesh's vertices, by index); skips triangles
// with repeated corners. Returns the number of faces put on copied vertices.
template <typename Mesh>
size_t addFacesSplittingComplex(Mesh& mesh,
                                const std::vector<typename Mesh::VertexHandle>& vertices,
                                const std::vector<Triangle>& triangles) {
  using VertexHandle = typename Mesh::VertexHandle;
  silenceOpenMeshLog();
  std::vector<std::unordered_map<uint32_t, VertexHandle>> layers;
  size_t split = 0;
  for (const Triangle& t : triangles) {
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;
    std::array<VertexHandle, 3> v{vertices[t[0]], vertices[t[1]], vertices[t[2]]};
    // Copies shared by the faces of one layer keep a rejected sheet connected (decimable).
    for (size_t layer = 0; !openMeshAccepts(mesh, v); ++layer) {
      if (layer == layers.size()) layers.emplace_back();
      for (int k = 0; k < 3; ++k) {
        auto [it, fresh] = layers[layer].try_emplace(t[k]);
        // A copy: add_vertex may grow the point array that point() refers into.
        if (fresh) {
          const typename Mesh::Point p = mesh.point(vertices[t[k]]);
          it->second = mesh.add_vertex(p);
        }
        v[k] = it->second;
      }
      if (layer == 0) ++split;
    }
    mesh.add_face(v[0], v[1], v[2]);
  }
  return split;
}

}  // namespace proxyvis
