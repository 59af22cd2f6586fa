// Every loader on the real files: counts and bounding boxes against the shared data set's MANIFEST
// (numbers computed there by an independent Python reader, copied here by hand), and every file of
// data/ against its row in data/README.md (counts, size, sha256).
#include <gtest/gtest.h>

#include <fstream>
#include <regex>

#include "mesh/io/mesh_io.h"
#include "mesh_test_util.h"
#include "util/sha256.h"

namespace proxyvis::test {
namespace {

struct Expected {
  const char* file;  // under data/
  size_t triangles, vertices;
  Vec3f lo, hi;      // MANIFEST bounding box (6 significant digits)
  double tolerance;  // absolute, for the box: print precision, or quantization for .drc
};
void PrintTo(const Expected& e, std::ostream* os) {
  *os << e.file;
}

// Quantization step of dragon.drc: 16 bits over the largest extent (14.0934).
constexpr double kDragonStep = 14.0934 / 65535.0;

const Expected kBundled[] = {
    {"bunny.off",
     6966,
     3485,
     {-0.0947581f, 0.0329874f, -0.0619614f},
     {0.0610375f, 0.187363f, 0.0588308f},
     1e-6},
    {"bun_zipper.ply",
     69451,
     35947,
     {-0.0946899f, 0.0329874f, -0.0618736f},
     {0.0610091f, 0.187321f, 0.0587997f},
     1e-6},
    {"dragon.drc",
     100000,
     50000,
     {-7.0467f, 0, -3.1513f},
     {7.0467f, 9.9399f, 3.1513f},
     kDragonStep},
    {"spot_triangulated.obj",
     5856,
     2930,
     {-0.471552f, -0.736784f, -0.668909f},
     {0.471552f, 0.953646f, 1.049f},
     1e-5},
    {"teapot.obj", 6320, 3644, {-3, 0, -2}, {3.434f, 3.15f, 2}, 1e-5},
    {"scenes/cornell_box.obj", 36, 76, {0, 0, 0}, {556, 548.8f, 559.2f}, 1e-3},
    {"draco/bunny.drc",
     69451,
     34834,
     {-0.0946899f, 0.0329874f, -0.0618736f},
     {0.0610091f, 0.187318f, 0.0588043f},
     1e-6},
    {"draco/bunny_gltf.drc",
     69451,
     34834,
     {-0.09469f, 0.032987f, -0.061874f},
     {0.061009f, 0.187317f, 0.0588039f},
     1e-6},
    {"draco/bunny.ref_decoded.ply",
     69451,
     34834,
     {-0.0946899f, 0.0329874f, -0.0618736f},
     {0.0610091f, 0.187318f, 0.0588043f},
     1e-6},
    {"foliage/BUSH11.ply",
     5243,
     12057,
     {-0.543172f, -0.566425f, -0.002257f},
     {0.559391f, 0.576986f, 1.22618f},
     1e-5},
    {"foliage/GRASS1.ply",
     2165,
     4627,
     {-0.711959f, -0.644327f, -0.020976f},
     {0.676298f, 0.682661f, 0.52432f},
     1e-5},
    {"foliage/URTICADIOICA1.ply",
     12159,
     15218,
     {-0.465781f, -0.516814f, -0.000213f},
     {0.553383f, 0.56916f, 0.646222f},
     1e-5},
    {"foliage/YELLOWFLOWER1.ply",
     792,
     1716,
     {-0.268353f, -0.282291f, -0.00052f},
     {0.298829f, 0.3215f, 0.55306f},
     1e-5},
    // 16 bits over 100 m.
    {"foliage/terrain.drc", 130050, 65536, {0, 0, -0.24f}, {100, 100, 9.8494f}, 100.0 / 65535.0},
};

class BundledMesh : public ::testing::TestWithParam<Expected> {};

TEST_P(BundledMesh, CountsAndBoundsMatchManifest) {
  const Expected& e = GetParam();
  const TriMesh m = loadMesh(dataFile(e.file));
  EXPECT_EQ(m.numTriangles(), e.triangles);
  EXPECT_EQ(m.numVertices(), e.vertices);
  EXPECT_EQ(m.source, dataFile(e.file).string());
  const Bounds3f b = m.bounds();
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(b.lo[k], e.lo[k], e.tolerance + 1e-6 * std::abs(e.lo[k])) << "axis " << k;
    EXPECT_NEAR(b.hi[k], e.hi[k], e.tolerance + 1e-6 * std::abs(e.hi[k])) << "axis " << k;
  }
}

INSTANTIATE_TEST_SUITE_P(Data, BundledMesh, ::testing::ValuesIn(kBundled),
                         [](const ::testing::TestParamInfo<Expected>& info) {
                           std::string name = info.param.file;
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

// Every mesh row of data/README.md (including the foliage with non-manifold edges that
// OpenMesh's own mesh kernel would refuse, and the hard set): triangles and vertices as listed.
TEST(DataReadme, EveryMeshMatchesItsTriangleAndVertexCounts) {
  std::ifstream in(dataFile("README.md"));
  const std::regex row(R"(^\| ([^ |]+\.(ply|obj|off|drc)) \| ([0-9,]+) / ([0-9,]+) \|)");
  std::string line;
  int checked = 0;
  while (std::getline(in, line)) {
    std::smatch m;
    if (!std::regex_search(line, m, row)) continue;
    const TriMesh mesh = loadMesh(dataFile(m[1].str()));
    EXPECT_EQ(mesh.numTriangles(), readmeNumber(m[3].str())) << m[1];
    EXPECT_EQ(mesh.numVertices(), readmeNumber(m[4].str())) << m[1];
    ++checked;
  }
  EXPECT_EQ(checked, 65);  // every bundled mesh (21, and the 44 ecosys prototypes)
}

// Every file row of data/README.md: the bundled bytes are the ones recorded (copies keep the
// original's sha256; converted files the one recorded when they were made).
TEST(DataReadme, EveryFileMatchesItsSizeAndSha256) {
  std::ifstream in(dataFile("README.md"));
  const std::regex row(R"(^\| ([^ |]+) \|.* \| ([0-9,]+) \| `([0-9a-f]{64})` \|$)");
  std::string line;
  int checked = 0;
  while (std::getline(in, line)) {
    std::smatch m;
    if (!std::regex_match(line, m, row)) continue;
    const auto file = dataFile(m[1].str());
    EXPECT_EQ(std::filesystem::file_size(file), readmeNumber(m[2].str())) << m[1];
    EXPECT_EQ(sha256OfFile(file), m[3].str()) << m[1];
    ++checked;
  }
  EXPECT_EQ(checked, 67);  // 65 meshes, the Cornell box's .mtl and the ecosys instance list
}

TEST(LoadMesh, ExtensionIsCaseInsensitive) {
  ScratchDir dir("case");
  std::filesystem::copy_file(dataFile("bunny.off"), dir / "BUNNY.OFF");
  EXPECT_EQ(loadMesh(dir / "BUNNY.OFF").numTriangles(), 6966u);
  EXPECT_TRUE(isSupportedMeshExtension("a.Ply"));
  EXPECT_TRUE(isSupportedMeshExtension("a.drc"));
  EXPECT_FALSE(isSupportedMeshExtension("a.stl"));
  EXPECT_FALSE(isSupportedMeshExtension("noext"));
}

TEST(LoadMesh, PolygonsAreFanTriangulatedInOrder) {
  ScratchDir dir("fan");
  writeBytes(dir / "quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nf 1 2 3 4\nf 2 5 3\n");
  const TriMesh m = loadMesh(dir / "quad.obj");
  ASSERT_EQ(m.numVertices(), 5u);
  ASSERT_EQ(m.numTriangles(), 3u);
  EXPECT_EQ(m.triangles[0], (Triangle{0, 1, 2}));
  EXPECT_EQ(m.triangles[1], (Triangle{0, 2, 3}));
  EXPECT_EQ(m.triangles[2], (Triangle{1, 4, 2}));
  EXPECT_EQ(m.vertices[4], Vec3f(2, 0, 0));
}

TEST(LoadMesh, KeepsFacesOpenMeshKernelsWouldReject) {
  // Three triangles on one edge (non-manifold) and a pinched vertex: all faces, vertex order kept.
  ScratchDir dir("nonmanifold");
  writeBytes(dir / "fin.off",
             "OFF\n6 4 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n-1 -1 -1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n"
             "3 0 5 3\n");
  const TriMesh m = loadMesh(dir / "fin.off");
  ASSERT_EQ(m.numTriangles(), 4u);
  EXPECT_EQ(m.numVertices(), 6u);
  EXPECT_EQ(m.triangles[2], (Triangle{0, 1, 4}));
  EXPECT_EQ(m.vertices[5], Vec3f(-1, -1, -1));
}

}  // namespace
}  // namespace proxyvis::test
