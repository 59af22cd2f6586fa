#pragma once
// A TriMesh as a valid oriented CGAL Surface_mesh, whatever its soup, built on the one conversion
// (mesh/cgal_bridge.h). Pulls in CGAL's polygon-soup repair; include it only from .cpp files.
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>

#include "mesh/cgal_bridge.h"

namespace proxyvis::cgal {

// Welds equal positions, drops triangles that welding made degenerate and unreferenced points,
// and builds an oriented Surface_mesh.
// Non-manifold vertices are split by orient_polygon_soup, so the result is always valid.
inline SurfaceMesh toWeldedMesh(const TriMesh& input) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  auto soup = toSoup(input);
  PMP::merge_duplicate_points_in_polygon_soup(soup.points, soup.faces);
  // A triangle whose corners welded together is no polygon: orient_polygon_soup loops for ever
  // on it (found by fuzz_proxy_gen).
  std::erase_if(soup.faces, [](const std::array<std::size_t, 3>& f) {
    return f[0] == f[1] || f[1] == f[2] || f[0] == f[2];
  });
  PMP::remove_isolated_points_in_polygon_soup(soup.points, soup.faces);
  PMP::orient_polygon_soup(soup.points, soup.faces);
  SurfaceMesh sm;
  PMP::polygon_soup_to_polygon_mesh(soup.points, soup.faces, sm);
  return sm;
}

}  // namespace proxyvis::cgal
