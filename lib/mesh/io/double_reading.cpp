#include "mesh/io/double_reading.h"

#include <CGAL/IO/polygon_soup_io.h>
#include <fmt/core.h>

#include <array>
#include <fstream>
#include <map>
#include <tuple>

#include "mesh/cgal_bridge.h"
#include "util/error.h"
#include "util/lower_case.h"

namespace proxyvis {

namespace {

std::vector<Vec3d> widened(const TriMesh& mesh) {
  std::vector<Vec3d> out;
  out.reserve(mesh.vertices.size());
  for (const Vec3f& v : mesh.vertices) out.emplace_back(v);
  return out;
}

bool plyIsAscii(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string line;
  for (int i = 0; i < 3 && std::getline(in, line); ++i)
    if (line.rfind("format ", 0) == 0) return line.find("ascii") != std::string::npos;
  return false;
}

using FloatKey = std::tuple<float, float, float>;

FloatKey keyOf(const Vec3f& v) {
  return {v.x, v.y, v.z};
}

}  // namespace

bool readsAsFloat(const TriMesh& mesh, const std::vector<Vec3d>& positions) {
  if (positions.size() != mesh.vertices.size()) return false;
  for (size_t i = 0; i < positions.size(); ++i)
    if (!(positions[i] == Vec3d(mesh.vertices[i]))) return false;
  return true;
}

bool storesDecimals(const std::filesystem::path& file) {
  const std::string ext = lowerExtension(file);
  return ext == ".off" || ext == ".obj" || (ext == ".ply" && plyIsAscii(file));
}

std::vector<Vec3d> readDoublePositions(const std::filesystem::path& file, const TriMesh& mesh) {
  if (!storesDecimals(file)) return widened(mesh);
  std::vector<cgal::Point3> points;
  std::vector<std::vector<std::size_t>> polygons;
  bool ok = false;
  try {
    ok = CGAL::IO::read_polygon_soup(file.string(), points, polygons,
                                     CGAL::parameters::verbose(false));
  } catch (const std::exception& e) {
    throw Error(file.string(), "cannot read the mesh in double", e.what());
  }
  if (!ok)
    throw Error(file.string(), "cannot read the mesh in double",
                "CGAL's reader refused the file that proxyvis read");
  auto rounded = [](const cgal::Point3& p) {
    return Vec3f(float(p.x()), float(p.y()), float(p.z()));
  };
  // In file order when both readers kept it (OFF, PLY, and OBJ files without texture seams).
  bool same_order = points.size() == mesh.vertices.size();
  for (size_t i = 0; same_order && i < points.size(); ++i)
    same_order = rounded(points[i]) == mesh.vertices[i];
  std::vector<Vec3d> out;
  out.reserve(mesh.vertices.size());
  if (same_order) {
    for (const cgal::Point3& p : points) out.emplace_back(p.x(), p.y(), p.z());
    return out;
  }
  // Otherwise by value: each float vertex takes the double that rounds to it, which must be one.
  std::map<FloatKey, Vec3d> by_float;
  std::map<FloatKey, bool> ambiguous;
  for (const cgal::Point3& p : points) {
    const Vec3d d(p.x(), p.y(), p.z());
    const auto [it, added] = by_float.emplace(keyOf(rounded(p)), d);
    if (!added && !(it->second == d)) ambiguous[it->first] = true;
  }
  for (const Vec3f& v : mesh.vertices) {
    const auto it = by_float.find(keyOf(v));
    if (it == by_float.end() || ambiguous.count(it->first))
      throw Error(file.string(), "cannot match the double reading to the float one",
                  fmt::format("vertex ({}, {}, {}) has {} double counterpart", v.x, v.y, v.z,
                              it == by_float.end() ? "no" : "more than one"));
    out.push_back(it->second);
  }
  return out;
}

}  // namespace proxyvis
