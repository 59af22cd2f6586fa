#pragma once
// A triangle soup as a CGAL Surface_mesh with the same triangles, for point location by ray
// parity and the volume it bounds (proxies/shared/parity_solid.h says which surfaces have an
// inside). Pulls in CGAL; include it only from .cpp files.
#include <CGAL/enum.h>

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "mesh/cgal_bridge.h"
#include "mesh/tri_mesh.h"

namespace proxyvis::cgal {

using cgal::Kernel;
using cgal::Point3;
using cgal::SurfaceMesh;
using Face = cgal::SoupTriangle;

struct ParitySolid {
  // The soup's triangles after welding exactly equal positions, dropping triangles with a repeated
  // corner (segments) and coincident triangles two by two (a pair changes no parity), with its
  // non-manifold edges and vertices split by orient_polygon_soup: a valid Surface_mesh of the same
  // triangles, so ray parity against it is ray parity against the input. Where an edge was split
  // the mesh has border halfedges even when the soup is watertight. When watertight, every
  // connected piece is oriented with its normals pointing out of the parity interior.
  SurfaceMesh mesh;
  uint64_t boundary_edges = 0;  // welded edges with one face
  uint64_t odd_edges = 0;       // welded edges with 3, 5, ... faces
  bool watertight() const {
    return mesh.number_of_faces() > 0 && boundary_edges == 0 && odd_edges == 0;
  }
};

ParitySolid makeParitySolid(std::vector<Point3> points, std::vector<Face> faces);
ParitySolid makeParitySolid(const TriMesh& mesh);

// Point location by ray parity against the faces of positive area of `mesh` (CGAL's
// Side_of_triangle_mesh on its own AABB tree, which has no closedness precondition; a zero-area
// face bounds nothing). `mesh` must outlive the locator. Safe to call from several threads.
class ParityLocator {
 public:
  explicit ParityLocator(const SurfaceMesh& mesh);
  ~ParityLocator();
  ParityLocator(const ParityLocator&) = delete;
  ParityLocator& operator=(const ParityLocator&) = delete;
  CGAL::Bounded_side operator()(const Point3& p) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Sum of the signed volumes of the faces' tetrahedra (about the box centre): the parity volume
// for a watertight ParitySolid.
double signedVolume(const SurfaceMesh& mesh);

}  // namespace proxyvis::cgal
