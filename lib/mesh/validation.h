#pragma once
// Validation report of a triangle mesh: what tools and proxy generators need to know before
// trusting it (closed? manifold? degenerate? self-intersecting?).
#include <cstdint>
#include <nlohmann/json_fwd.hpp>
#include <optional>

#include "mesh/tri_mesh.h"

namespace proxyvis {

struct ValidationOptions {
  // Self-intersection test (CGAL); O(n log n) but slow on millions of faces. Pairs of triangles
  // that touch only at a non-manifold (pinched) vertex are counted too.
  bool self_intersections = false;
};

struct MeshReport {
  uint64_t vertices = 0, faces = 0;
  uint64_t unreferenced_vertices = 0;
  Bounds3f bounds;
  uint64_t nonfinite_vertices = 0;  // NaN or inf coordinates
  // Zero-area triangles: two equal corners after welding (left out of topology), or three
  // distinct collinear corners (kept in the topology: their edges join their neighbours).
  uint64_t degenerate_faces = 0;
  uint64_t duplicate_faces = 0;        // same three (welded) vertices as an earlier face
  uint64_t components = 0;             // sharing a vertex, after welding exactly equal positions
  uint64_t boundary_edges = 0;         // edges with one face
  uint64_t non_manifold_edges = 0;     // edges with more than two faces
  uint64_t non_manifold_vertices = 0;  // vertices whose faces form more than one fan
  uint64_t odd_edges = 0;              // non-manifold edges with an odd number (3, 5, ...) of faces
  bool closed = false;                 // no boundary and no non-manifold edges
  // Every edge has an even number of faces (closed, or non-manifold edges with 4, 6, ... faces):
  // the surface bounds a volume by ray parity (proxies/shared/parity_solid.h).
  bool watertight = false;
  bool manifold = false;                            // no non-manifold edges or vertices
  std::optional<int64_t> genus;                     // closed manifold meshes only
  std::optional<double> volume;                     // closed meshes only
  std::optional<uint64_t> self_intersecting_pairs;  // only when requested
};

MeshReport validateMesh(const TriMesh& mesh, const ValidationOptions& options = {});

nlohmann::json toJson(const MeshReport& report);

// Human-readable multi-line summary.
std::string formatReport(const MeshReport& report, const std::string& title);

}  // namespace proxyvis
