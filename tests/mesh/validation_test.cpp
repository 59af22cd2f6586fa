// validateMesh against the MANIFEST's topology tables (independent Python + CGAL cross-check)
// and against hand-made meshes whose answers are known in closed form.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>

#include "mesh/edge_counts.h"
#include "mesh/io/mesh_io.h"
#include "mesh/validation.h"
#include "mesh_test_util.h"

namespace proxyvis::test {
namespace {

struct Topology {
  const char* file;  // under data/
  uint64_t components, unreferenced, boundary, nm_edges, nm_vertices, duplicates;
  bool closed, manifold;
  std::optional<int64_t> genus;
};
// Names the row by its file in test listings (gtest would print the struct's bytes, pointer
// included, into every discovered test name).
void PrintTo(const Topology& t, std::ostream* os) {
  *os << t.file;
}

// MANIFEST "Topology details" and "Files" tables.
const Topology kBundledTopology[] = {
    {"bunny.off", 1, 0, 0, 0, 0, 0, true, true, 0},
    {"bun_zipper.ply", 1, 1113, 223, 0, 0, 0, false, true, std::nullopt},
    {"dragon.drc", 1, 0, 0, 0, 0, 0, true, true, 1},  // must survive 16-bit quantization
    {"spot_triangulated.obj", 1, 0, 0, 0, 0, 0, true, true, 0},
    {"teapot.obj", 3, 0, 160, 0, 1, 0, false, false, std::nullopt},
    {"scenes/cornell_box.obj", 4, 4, 8, 0, 0, 0, false, true, std::nullopt},
    {"draco/bunny.drc", 1, 0, 223, 0, 0, 0, false, true, std::nullopt},
    {"draco/bunny_gltf.drc", 1, 0, 223, 0, 0, 0, false, true, std::nullopt},
    {"foliage/BUSH11.ply", 351, 0, 2137, 3, 0, 1, false, false, std::nullopt},
    {"foliage/GRASS1.ply", 295, 0, 2755, 0, 0, 0, false, true, std::nullopt},
    {"foliage/URTICADIOICA1.ply", 229, 0, 3161, 4, 12, 0, false, false, std::nullopt},
    {"foliage/YELLOWFLOWER1.ply", 42, 0, 396, 0, 0, 0, false, true, std::nullopt},
    {"foliage/terrain.drc", 1, 0, 1020, 0, 0, 0, false, true, std::nullopt},
};

class BundledTopology : public ::testing::TestWithParam<Topology> {};

TEST_P(BundledTopology, MatchesManifest) {
  const Topology& e = GetParam();
  const MeshReport r = validateMesh(loadMesh(dataFile(e.file)));
  EXPECT_EQ(r.components, e.components);
  EXPECT_EQ(r.unreferenced_vertices, e.unreferenced);
  EXPECT_EQ(r.boundary_edges, e.boundary);
  EXPECT_EQ(r.non_manifold_edges, e.nm_edges);
  EXPECT_EQ(r.non_manifold_vertices, e.nm_vertices);
  EXPECT_EQ(r.duplicate_faces, e.duplicates);
  EXPECT_EQ(r.degenerate_faces, 0u);
  EXPECT_EQ(r.nonfinite_vertices, 0u);
  EXPECT_EQ(r.closed, e.closed);
  EXPECT_EQ(r.manifold, e.manifold);
  EXPECT_EQ(r.genus, e.genus);
  EXPECT_EQ(r.volume.has_value(), e.closed);
  EXPECT_FALSE(r.self_intersecting_pairs.has_value());
}

INSTANTIATE_TEST_SUITE_P(Data, BundledTopology, ::testing::ValuesIn(kBundledTopology),
                         [](const ::testing::TestParamInfo<Topology>& info) {
                           std::string name = info.param.file;
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

// Every row of data/README.md's topology table (copied from the shared data set's MANIFEST),
// read from the README itself.
TEST(DataReadme, EveryTopologyRowMatches) {
  std::ifstream in(dataFile("README.md"));
  // | file | components | distinct | unreferenced | boundary | nm edges | nm vertices |
  //   inconsistently oriented | degenerate | duplicate |
  const std::regex row(
      R"(^\| ([^ |]+) \| ([0-9,]+) \| ([0-9,]+) \| ([0-9,]+) \| ([0-9,]+) \| ([0-9,]+) \| ([0-9,]+) \| ([0-9,]+) \| ([0-9,]+) \| ([0-9,]+) \|$)");
  auto n = [](const std::ssub_match& s) { return readmeNumber(s.str()); };
  std::string line;
  int checked = 0;
  while (std::getline(in, line)) {
    std::smatch m;
    if (!std::regex_match(line, m, row)) continue;
    const MeshReport r = validateMesh(loadMesh(dataFile(m[1].str())));
    const std::string f = m[1].str();
    EXPECT_EQ(r.components, n(m[2])) << f;
    EXPECT_EQ(r.unreferenced_vertices, n(m[4])) << f;
    EXPECT_EQ(r.boundary_edges, n(m[5])) << f;
    EXPECT_EQ(r.non_manifold_edges, n(m[6])) << f;
    EXPECT_EQ(r.non_manifold_vertices, n(m[7])) << f;
    EXPECT_EQ(r.degenerate_faces, n(m[9])) << f;
    EXPECT_EQ(r.duplicate_faces, n(m[10])) << f;
    ++checked;
  }
  EXPECT_EQ(checked, 11);  // the files bundled unchanged
}

// countEdges (mesh/edge_counts.h) serves validation, the ray-parity solid and the check with any
// index type: a "book" of pages on edge (0, 1), counted by hand.
TEST(EdgeCounts, PagesOnOneEdge) {
  std::vector<std::array<std::size_t, 3>> book = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  EdgeCounts c = countEdges(book);
  EXPECT_EQ(c.edges, 7u);  // (0,1) and two free edges per page
  EXPECT_EQ(c.boundary, 6u);
  EXPECT_EQ(c.non_manifold, 1u);
  EXPECT_EQ(c.odd, 1u);  // three pages
  book.push_back({1, 0, 5});
  c = countEdges(book);
  EXPECT_EQ(c.edges, 9u);
  EXPECT_EQ(c.boundary, 8u);
  EXPECT_EQ(c.non_manifold, 1u);
  EXPECT_EQ(c.odd, 0u);  // four pages: even again
  const std::vector<Triangle> one = {{7, 8, 9}};
  EXPECT_EQ(countEdges(one).boundary, 3u);
  EXPECT_EQ(countEdges(std::vector<Triangle>{}).edges, 0u);
}

TEST(Validate, UnitCubeIsClosedGenusZeroVolumeOne) {
  const MeshReport r = validateMesh(unitCube());
  EXPECT_TRUE(r.closed);
  EXPECT_TRUE(r.manifold);
  EXPECT_EQ(r.genus, 0);
  ASSERT_TRUE(r.volume.has_value());
  EXPECT_NEAR(*r.volume, 1.0, 1e-12);
  EXPECT_EQ(r.components, 1u);
  EXPECT_EQ(r.bounds.lo, Vec3f(0, 0, 0));
  EXPECT_EQ(r.bounds.hi, Vec3f(1, 1, 1));
}

TEST(Validate, TwoDisjointCubesHaveTwoComponentsAndVolumeTwo) {
  TriMesh m = unitCube();
  const TriMesh c = unitCube();
  for (const Vec3f& v : c.vertices) m.vertices.push_back(v + Vec3f(3, 0, 0));
  for (const Triangle& t : c.triangles) m.triangles.push_back({t[0] + 8, t[1] + 8, t[2] + 8});
  const MeshReport r = validateMesh(m);
  EXPECT_EQ(r.components, 2u);
  EXPECT_EQ(r.genus, 0);  // summed over components: 0 + 0
  EXPECT_NEAR(*r.volume, 2.0, 1e-12);
}

TEST(Validate, WeldsExactDuplicatePositionsBeforeTopology) {
  // The cube with every triangle owning its own three vertices (a soup): closed after welding.
  const TriMesh cube = unitCube();
  TriMesh soup;
  for (const Triangle& t : cube.triangles) {
    const uint32_t base = uint32_t(soup.vertices.size());
    for (uint32_t i : t) soup.vertices.push_back(cube.vertices[i]);
    soup.triangles.push_back({base, base + 1, base + 2});
  }
  soup.vertices[0].x = -0.0f;  // -0 and +0 are the same position
  const MeshReport r = validateMesh(soup);
  EXPECT_EQ(r.vertices, 36u);
  EXPECT_TRUE(r.closed);
  EXPECT_EQ(r.genus, 0);
}

TEST(Validate, RemovingAFaceOpensTheCube) {
  TriMesh m = unitCube();
  m.triangles.pop_back();
  const MeshReport r = validateMesh(m);
  EXPECT_FALSE(r.closed);
  EXPECT_EQ(r.boundary_edges, 3u);
  EXPECT_FALSE(r.genus.has_value());
  EXPECT_FALSE(r.volume.has_value());
}

TEST(Validate, DegenerateDuplicateAndNonFinite) {
  TriMesh m = unitCube();
  m.triangles.push_back({0, 0, 1});             // repeated index
  m.vertices.push_back(m.vertices[2]);          // vertex 8 == vertex 2
  m.triangles.push_back({2, 8, 5});             // degenerate after welding
  m.triangles.push_back({2, 1, 0});             // duplicate of {0, 2, 1}, other winding
  m.vertices.push_back({std::nanf(""), 0, 0});  // unreferenced NaN vertex 9
  const MeshReport r = validateMesh(m);
  EXPECT_EQ(r.degenerate_faces, 2u);
  EXPECT_EQ(r.duplicate_faces, 1u);
  EXPECT_EQ(r.nonfinite_vertices, 1u);
  EXPECT_EQ(r.unreferenced_vertices, 1u);
  EXPECT_EQ(r.non_manifold_edges, 3u);  // the duplicate puts a third face on 3 edges
  EXPECT_FALSE(r.closed);
}

TEST(Validate, BowTieVertexIsNonManifold) {
  TriMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
  m.triangles = {{0, 1, 2}, {0, 3, 4}};
  const MeshReport r = validateMesh(m);
  EXPECT_EQ(r.non_manifold_vertices, 1u);
  EXPECT_EQ(r.non_manifold_edges, 0u);
  EXPECT_EQ(r.components, 1u);
  EXPECT_FALSE(r.manifold);
}

TEST(Validate, SelfIntersectionsOnlyWhenRequested) {
  const TriMesh cube = unitCube();
  EXPECT_EQ(validateMesh(cube, {.self_intersections = true}).self_intersecting_pairs, 0u);

  // A triangle piercing the cube's top and bottom: it crosses the 4 triangles it passes through
  // (2 on the top face, 2 on the bottom face; it pierces each face across its diagonal).
  TriMesh pierced = cube;
  pierced.vertices.push_back({0.2f, 0.5f, -1});
  pierced.vertices.push_back({0.8f, 0.5f, -1});
  pierced.vertices.push_back({0.5f, 0.5f, 2});
  pierced.triangles.push_back({8, 9, 10});
  const MeshReport r = validateMesh(pierced, {.self_intersections = true});
  ASSERT_TRUE(r.self_intersecting_pairs.has_value());
  EXPECT_EQ(*r.self_intersecting_pairs, 4u);
  EXPECT_FALSE(validateMesh(pierced).self_intersecting_pairs.has_value());
}

TEST(Validate, JsonAndTextReportCarryTheNumbers) {
  const MeshReport r = validateMesh(unitCube());
  const nlohmann::json j = toJson(r);
  EXPECT_EQ(j.at("faces"), 12);
  EXPECT_EQ(j.at("vertices"), 8);
  EXPECT_EQ(j.at("closed"), true);
  EXPECT_EQ(j.at("genus"), 0);
  EXPECT_TRUE(j.at("self_intersecting_pairs").is_null());
  const std::string text = formatReport(r, "cube");
  EXPECT_NE(text.find("cube"), std::string::npos);
  EXPECT_NE(text.find("genus"), std::string::npos);
  EXPECT_NE(text.find("12"), std::string::npos);
}

TEST(Validate, EmptyMesh) {
  const MeshReport r = validateMesh(TriMesh{});
  EXPECT_EQ(r.faces, 0u);
  EXPECT_FALSE(r.closed);
  EXPECT_TRUE(r.bounds.empty());
  EXPECT_TRUE(toJson(r).at("bounds").is_null());
}

// Zero-area triangles are degenerate whether two corners coincide or three distinct corners lie
// on a line. The robustness run's file: a closed "tetrahedron" on four collinear points read
// "degenerate triangles 0".
TEST(Validate, CollinearTrianglesAreDegenerate) {
  TriMesh line;
  for (int i = 0; i < 4; ++i) line.vertices.emplace_back(float(i), 0.0f, 0.0f);
  line.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  const MeshReport r = validateMesh(line);
  EXPECT_EQ(r.degenerate_faces, 4u);
  EXPECT_TRUE(r.closed);  // the edges still pair up: topology keeps collinear triangles
  ASSERT_TRUE(r.volume.has_value());
  EXPECT_EQ(*r.volume, 0.0);

  // Off the axes: 1, 2 and 4 times (0.125, 0.25, 0.5) lie on a line; moving the last corner by
  // one float step leaves the line (decided exactly, not within a tolerance).
  TriMesh m;
  m.vertices = {{0.125f, 0.25f, 0.5f}, {0.25f, 0.5f, 1.0f}, {0.5f, 1.0f, 2.0f}};
  m.triangles = {{0, 1, 2}};
  EXPECT_EQ(validateMesh(m).degenerate_faces, 1u);
  m.vertices[2].z = std::nextafter(2.0f, 3.0f);
  EXPECT_EQ(validateMesh(m).degenerate_faces, 0u);
  // A thin but real sliver is not degenerate; a repeated corner is.
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0.5f, 1e-6f, 0}};
  m.triangles = {{0, 1, 2}};
  EXPECT_EQ(validateMesh(m).degenerate_faces, 0u);
  m.triangles = {{0, 1, 1}};
  EXPECT_EQ(validateMesh(m).degenerate_faces, 1u);
}

}  // namespace
}  // namespace proxyvis::test
