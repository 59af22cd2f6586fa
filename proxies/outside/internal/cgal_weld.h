#pragma once
// Private to proxies/: a TriMesh as a valid oriented CGAL Surface_mesh, whatever its soup. Pulls
// in CGAL's polygon-soup repair; only proxies/**/*.cpp may include it.
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>

#include "proxies/outside/internal/cgal_mesh.h"

namespace proxyvis::cgal {

// Welds equal positions, drops unreferenced points and builds an oriented Surface_mesh.
// Non-manifold vertices are split by orient_polygon_soup, so the result is always valid.
inline SurfaceMesh toWeldedMesh(const TriMesh& input) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  Soup soup = toSoup(input);
  PMP::merge_duplicate_points_in_polygon_soup(soup.points, soup.faces);
  PMP::remove_isolated_points_in_polygon_soup(soup.points, soup.faces);
  PMP::orient_polygon_soup(soup.points, soup.faces);
  SurfaceMesh sm;
  PMP::polygon_soup_to_polygon_mesh(soup.points, soup.faces, sm);
  return sm;
}

}  // namespace proxyvis::cgal
