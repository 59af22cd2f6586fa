// Ray-parity solids. A set of triangles in which every edge has an even number of faces is a
// cycle modulo 2, and in space such a cycle bounds exactly one finite region modulo 2: the points
// from which a ray crosses it an odd number of times. Every path from that region to the outside
// crosses one of the triangles, which is what an inside proxy needs of its original, whether the
// surface is manifold or not. orient_polygon_soup splits non-manifold edges and vertices without
// moving a triangle, so CGAL's ray parity on the split mesh locates points against the input.
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "mesh/edge_counts.h"
#include "proxies/shared/cgal/parity_solid_mesh.h"
#include "proxies/shared/parity_solid.h"

namespace proxyvis {
namespace cgal {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Side = CGAL::Side_of_triangle_mesh<SurfaceMesh, Kernel>;
using Tree = Side::AABB_tree;
using FaceIndex = SurfaceMesh::Face_index;

Face sortedCorners(Face f) {
  std::sort(f.begin(), f.end());
  return f;
}

// Coincident triangles (same three corners, any order) kept modulo 2: an even number of copies
// adds an even number of crossings to every ray, so none is kept; an odd number keeps one.
void dropCoincidentPairs(std::vector<Face>& faces) {
  std::vector<std::pair<Face, std::size_t>> keyed;
  keyed.reserve(faces.size());
  for (std::size_t i = 0; i < faces.size(); ++i) keyed.emplace_back(sortedCorners(faces[i]), i);
  std::sort(keyed.begin(), keyed.end());
  std::vector<char> keep(faces.size(), 0);
  for (std::size_t begin = 0; begin < keyed.size();) {
    std::size_t end = begin + 1;
    while (end < keyed.size() && keyed[end].first == keyed[begin].first) ++end;
    if ((end - begin) % 2 == 1) keep[keyed[begin].second] = 1;
    begin = end;
  }
  std::vector<Face> kept;
  kept.reserve(faces.size());
  for (std::size_t i = 0; i < faces.size(); ++i)
    if (keep[i]) kept.push_back(faces[i]);
  faces = std::move(kept);
}

// Which way a face's normal points, by locating two points just off its centroid: +1 out of the
// interior, -1 into it, 0 undecided (another sheet too close, or no area).
int facePointsOut(const SurfaceMesh& mesh, FaceIndex f, const ParityLocator& side) {
  const auto h = mesh.halfedge(f);
  const Point3 &a = mesh.point(mesh.source(h)), &b = mesh.point(mesh.target(h)),
               &c = mesh.point(mesh.target(mesh.next(h)));
  const Kernel::Vector_3 n = CGAL::cross_product(b - a, c - a);
  const double twice_area = std::sqrt(n.squared_length());
  const double perimeter = std::sqrt((b - a).squared_length()) +
                           std::sqrt((c - b).squared_length()) +
                           std::sqrt((a - c).squared_length());
  if (!(twice_area > 0) || !(perimeter > 0)) return 0;
  // A thousandth of the inscribed radius off the face: well clear of its edges' neighbours.
  const double step = 1e-3 * twice_area / perimeter;
  const Point3 centre = CGAL::centroid(a, b, c);
  const Kernel::Vector_3 offset = n * (step / twice_area);
  const CGAL::Bounded_side front = side(centre + offset), back = side(centre - offset);
  if (front == CGAL::ON_UNBOUNDED_SIDE && back == CGAL::ON_BOUNDED_SIDE) return 1;
  if (front == CGAL::ON_BOUNDED_SIDE && back == CGAL::ON_UNBOUNDED_SIDE) return -1;
  return 0;
}

double faceArea2(const SurfaceMesh& mesh, FaceIndex f) {
  const auto h = mesh.halfedge(f);
  const Point3 &a = mesh.point(mesh.source(h)), &b = mesh.point(mesh.target(h)),
               &c = mesh.point(mesh.target(mesh.next(h)));
  return CGAL::cross_product(b - a, c - a).squared_length();
}

// orient_polygon_soup orients each connected piece consistently but not necessarily outward:
// each piece is turned by a vote of its largest faces' parity probes (it only affects the
// volume; containment is decided by parity alone).
void orientPiecesOutward(SurfaceMesh& mesh) {
  auto piece = mesh.add_property_map<FaceIndex, std::size_t>("f:parity_piece", 0).first;
  const std::size_t pieces = PMP::connected_components(mesh, piece);
  std::vector<std::vector<FaceIndex>> faces_of(pieces);
  for (FaceIndex f : mesh.faces()) faces_of[piece[f]].push_back(f);
  std::vector<std::vector<FaceIndex>> to_flip;
  {
    ParityLocator side(mesh);
    for (std::vector<FaceIndex>& fs : faces_of) {
      std::vector<std::pair<double, FaceIndex>> by_area;
      by_area.reserve(fs.size());
      for (FaceIndex f : fs) by_area.emplace_back(faceArea2(mesh, f), f);
      const std::size_t probes = std::min<std::size_t>(by_area.size(), 16);
      std::partial_sort(by_area.begin(), by_area.begin() + probes, by_area.end(),
                        [](const auto& x, const auto& y) { return x.first > y.first; });
      int out = 0, in = 0;
      for (std::size_t i = 0; i < probes && std::max(out, in) < 3; ++i) {
        const int vote = facePointsOut(mesh, by_area[i].second, side);
        out += vote > 0;
        in += vote < 0;
      }
      if (in > out) to_flip.push_back(std::move(fs));
    }
  }
  for (const std::vector<FaceIndex>& fs : to_flip) PMP::reverse_face_orientations(fs, mesh);
  mesh.remove_property_map(piece);
}

}  // namespace

ParitySolid makeParitySolid(std::vector<Point3> points, std::vector<Face> faces) {
  ParitySolid s;
  PMP::merge_duplicate_points_in_polygon_soup(points, faces);
  // A triangle whose corners welded together is a segment: it bounds nothing (and
  // orient_polygon_soup loops for ever on it).
  std::erase_if(faces, [](const Face& f) { return f[0] == f[1] || f[1] == f[2] || f[0] == f[2]; });
  dropCoincidentPairs(faces);
  PMP::remove_isolated_points_in_polygon_soup(points, faces);
  const EdgeCounts edges = countEdges(faces);
  s.boundary_edges = edges.boundary;
  s.odd_edges = edges.odd;
  PMP::orient_polygon_soup(points, faces);
  PMP::polygon_soup_to_polygon_mesh(points, faces, s.mesh);
  if (s.watertight()) orientPiecesOutward(s.mesh);
  return s;
}

ParitySolid makeParitySolid(const TriMesh& mesh) {
  cgal::Soup<Face> soup = cgal::toSoup<Face>(mesh);
  return makeParitySolid(std::move(soup.points), std::move(soup.faces));
}

struct ParityLocator::Impl {
  std::vector<FaceIndex> faces;
  std::optional<Tree> tree;
  std::optional<Side> side;
};

ParityLocator::ParityLocator(const SurfaceMesh& mesh) : impl_(std::make_unique<Impl>()) {
  for (FaceIndex f : mesh.faces())
    if (faceArea2(mesh, f) > 0) impl_->faces.push_back(f);
  if (impl_->faces.empty()) return;
  impl_->tree.emplace(impl_->faces.begin(), impl_->faces.end(), mesh);
  impl_->side.emplace(*impl_->tree);
}

ParityLocator::~ParityLocator() = default;

CGAL::Bounded_side ParityLocator::operator()(const Point3& p) const {
  // Without a face of positive area nothing is enclosed.
  return impl_->side ? (*impl_->side)(p) : CGAL::ON_UNBOUNDED_SIDE;
}

double signedVolume(const SurfaceMesh& mesh) {
  if (mesh.is_empty()) return 0;
  const CGAL::Bbox_3 box = PMP::bbox(mesh);
  const Point3 o((box.xmin() + box.xmax()) / 2, (box.ymin() + box.ymax()) / 2,
                 (box.zmin() + box.zmax()) / 2);
  double six_volume = 0;
  for (FaceIndex f : mesh.faces()) {
    const auto h = mesh.halfedge(f);
    const Point3 &a = mesh.point(mesh.source(h)), &b = mesh.point(mesh.target(h)),
                 &c = mesh.point(mesh.target(mesh.next(h)));
    six_volume += CGAL::scalar_product(a - o, CGAL::cross_product(b - o, c - o));
  }
  return six_volume / 6;
}

}  // namespace cgal

std::optional<double> parityVolume(const TriMesh& mesh) {
  const cgal::ParitySolid s = cgal::makeParitySolid(mesh);
  if (!s.watertight()) return std::nullopt;
  return cgal::signedVolume(s.mesh);
}

Error noInteriorError(const std::string& source, uint64_t boundary_edges, uint64_t odd_edges,
                      const std::string& what) {
  std::string found;
  if (boundary_edges > 0) found = fmt::format("{} boundary edges", boundary_edges);
  if (odd_edges > 0)
    found += fmt::format("{}{} edges with an odd number (3, 5, ...) of faces",
                         found.empty() ? "" : ", ", odd_edges);
  if (found.empty()) found = "no triangles of positive area";
  const std::string why = fmt::format(
      "{} needs a surface that bounds a volume (every edge shared by an even number of faces)",
      what);
  if (boundary_edges > 0)
    return Error(source, found, why,
                 "use --kind outside or --kind general; --fill-holes builds it from the "
                 "hole-filled mesh but writes it as class general, since rays pass through holes");
  return Error(source, found, why, "use --kind outside or --kind general");
}

}  // namespace proxyvis
