// Draco: decoding vs the reference decodings of npm draco3d 1.5.9, encoding round trips within
// the quantization error, and OBJ -> PLY -> DRC -> OBJ through every writer.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "mesh/io/internal/draco_io.h"
#include "mesh/io/mesh_io.h"
#include "mesh/validation.h"
#include "mesh_test_util.h"
#include "util/error.h"

namespace proxyvis::test {
namespace {

void expectIdentical(const TriMesh& a, const TriMesh& b) {
  ASSERT_EQ(a.numVertices(), b.numVertices());
  ASSERT_EQ(a.numTriangles(), b.numTriangles());
  size_t vertex_mismatches = 0, face_mismatches = 0;
  for (size_t i = 0; i < a.numVertices(); ++i)
    vertex_mismatches += !(a.vertices[i] == b.vertices[i]);
  for (size_t f = 0; f < a.numTriangles(); ++f) face_mismatches += a.triangles[f] != b.triangles[f];
  EXPECT_EQ(vertex_mismatches, 0u);
  EXPECT_EQ(face_mismatches, 0u);
}

class DracoReference : public ::testing::TestWithParam<std::string> {};

TEST_P(DracoReference, DecodeEqualsReferenceDecodingExactly) {
  const TriMesh decoded = loadMesh(dataFile("draco/" + GetParam() + ".drc"));
  const TriMesh reference = loadMesh(dataFile("draco/" + GetParam() + ".ref_decoded.ply"));
  expectIdentical(decoded, reference);
}

INSTANTIATE_TEST_SUITE_P(Data, DracoReference, ::testing::Values("bunny", "bunny_gltf"));

// For every vertex of `b`, the closest vertex of `a` and the distance (vertex order differs after
// Draco, so there is no index correspondence); candidates come from a grid of cell size `cell`.
struct NearestMap {
  std::vector<uint32_t> index;
  double max_distance = 0;
};
NearestMap nearestVertices(const TriMesh& a, const TriMesh& b, double cell) {
  auto cellOf = [&](const Vec3f& v) {
    return std::array<long, 3>{std::lround(v.x / cell), std::lround(v.y / cell),
                               std::lround(v.z / cell)};
  };
  std::map<std::array<long, 3>, std::vector<uint32_t>> grid;
  for (uint32_t i = 0; i < a.numVertices(); ++i) grid[cellOf(a.vertices[i])].push_back(i);
  NearestMap map;
  for (const Vec3f& v : b.vertices) {
    double best = INFINITY;
    uint32_t best_index = UINT32_MAX;
    const std::array<long, 3> c = cellOf(v);
    for (long dx = -1; dx <= 1; ++dx)
      for (long dy = -1; dy <= 1; ++dy)
        for (long dz = -1; dz <= 1; ++dz) {
          auto it = grid.find({c[0] + dx, c[1] + dy, c[2] + dz});
          if (it == grid.end()) continue;
          for (uint32_t w : it->second) {
            const double d = length(Vec3d(v) - Vec3d(a.vertices[w]));
            if (d < best) best = d, best_index = w;
          }
        }
    map.index.push_back(best_index);
    map.max_distance = std::max(map.max_distance, best);
  }
  return map;
}

// Triangles of `m` as index triples, renamed by `rename` and rotated to start at the smallest
// index (winding kept), so meshes with different vertex and face orders compare equal.
std::multiset<Triangle> canonicalTriangles(const TriMesh& m, const std::vector<uint32_t>& rename) {
  std::multiset<Triangle> set;
  for (const Triangle& t : m.triangles) {
    Triangle r{rename[t[0]], rename[t[1]], rename[t[2]]};
    std::rotate(r.begin(), std::min_element(r.begin(), r.end()), r.end());
    set.insert(r);
  }
  return set;
}
std::vector<uint32_t> identity(size_t n) {
  std::vector<uint32_t> v(n);
  for (size_t i = 0; i < n; ++i) v[i] = uint32_t(i);
  return v;
}

TEST(DracoRoundTrip, ObjToPlyToDrcToObjWithinQuantization) {
  ScratchDir dir("roundtrip");
  const TriMesh original = loadMesh(dataFile("spot_triangulated.obj"));
  saveMesh(original, dir / "spot.ply");
  const TriMesh ply = loadMesh(dir / "spot.ply");
  expectIdentical(ply, original);  // binary PLY keeps float32 and the order exactly

  const int bits = 14;
  saveMesh(ply, dir / "spot.drc", {.draco_quantization = bits});
  const TriMesh drc = loadMesh(dir / "spot.drc");
  saveMesh(drc, dir / "spot_back.obj");
  const TriMesh back = loadMesh(dir / "spot_back.obj");
  expectIdentical(back, drc);  // OBJ writes 9 significant digits: float32 survives exactly

  // Draco quantizes all axes over the largest extent: error <= step / 2 per axis.
  const Vec3f extent = original.bounds().extent();
  const double range = std::max({extent.x, extent.y, extent.z});
  const double step = range / double((1 << bits) - 1);
  const double max_error = std::sqrt(3.0) * step / 2 * 1.01;
  ASSERT_EQ(back.numTriangles(), original.numTriangles());
  ASSERT_EQ(back.numVertices(), original.numVertices());
  const NearestMap map = nearestVertices(original, back, 0.01);
  EXPECT_LE(map.max_distance, max_error);
  EXPECT_LE(nearestVertices(back, original, 0.01).max_distance, max_error);
  // Spot's shortest edge is far longer than the error, so nearest = the same vertex: the
  // triangles must be exactly the original ones.
  EXPECT_EQ(canonicalTriangles(back, map.index),
            canonicalTriangles(original, identity(original.numVertices())));
  // And topology survives: spot stays a closed genus-0 surface.
  const MeshReport r = validateMesh(back);
  EXPECT_TRUE(r.closed);
  EXPECT_EQ(r.genus, 0);
}

TEST(DracoRoundTrip, LosslessKeepsEveryPositionExactly) {
  ScratchDir dir("lossless");
  const TriMesh original = loadMesh(dataFile("bunny.off"));
  saveMesh(original, dir / "bunny.drc", {.draco_quantization = 0});
  const TriMesh back = loadMesh(dir / "bunny.drc");
  ASSERT_EQ(back.numTriangles(), original.numTriangles());
  const NearestMap map = nearestVertices(original, back, 0.001);
  EXPECT_EQ(map.max_distance, 0.0);
  EXPECT_EQ(canonicalTriangles(back, map.index),
            canonicalTriangles(original, identity(original.numVertices())));
}

TEST(DracoRoundTrip, MoreBitsSmallerError) {
  ScratchDir dir("bits");
  const TriMesh original = loadMesh(dataFile("bunny.off"));
  double previous = INFINITY;
  for (int bits : {8, 11, 14}) {
    const auto path = dir / (std::to_string(bits) + "bits.drc");
    saveMesh(original, path, {.draco_quantization = bits});
    const double error = nearestVertices(original, loadMesh(path), 0.01).max_distance;
    EXPECT_LT(error, previous) << bits << " bits";
    previous = error;
  }
}

TEST(DracoRoundTrip, AsciiPlyAndOffKeepFloatsExactly) {
  ScratchDir dir("ascii");
  const TriMesh original = loadMesh(dataFile("foliage/BUSH11.ply"));  // non-manifold foliage
  saveMesh(original, dir / "a.ply", {.binary = false});
  EXPECT_EQ(readBytes(dir / "a.ply").find("format ascii"), 4u);
  expectIdentical(loadMesh(dir / "a.ply"), original);
  saveMesh(original, dir / "a.off");
  expectIdentical(loadMesh(dir / "a.off"), original);
  saveMesh(original, dir / "a.obj");
  expectIdentical(loadMesh(dir / "a.obj"), original);
}

// Re-encoding the bundled dragon (itself 16-bit Draco) must not weld or split vertices either.
TEST(DracoRoundTrip, DragonStaysClosedAtSixteenBits) {
  ScratchDir dir("dragon");
  saveMesh(loadMesh(dataFile("dragon.drc")), dir / "dragon.drc", {.draco_quantization = 16});
  const MeshReport r = validateMesh(loadMesh(dir / "dragon.drc"));
  EXPECT_TRUE(r.closed);
  EXPECT_TRUE(r.manifold);
  EXPECT_EQ(r.genus, 1);
}

// Single flipped bytes of the bundled dragon that Draco decodes without complaint. What can be
// validated after decoding is: quantized values within their bits, a finite quantization box, and
// an origin at the scale of the data (one flip made every y -1.7e38, and proxy-gen crashed on it).
// Flips of the entropy-coded values themselves decode to another valid mesh: only the .sha256
// sidecar notices those (sidecar_test.cpp).
TEST(DracoCorruption, QuantizationFlipsAreRefused) {
  ScratchDir dir("draco_flips");
  const std::string original = readBytes(dataFile("dragon.drc"));
  const struct {
    size_t from_end;
    const char* fragment;
  } flips[] = {
      {10, "spanning"},             // origin y -> -1.7e38: all y collapse to one value
      {19, "is out of its range"},  // a quantized value beyond 16 bits
      {2, "is not a finite box"},   // negative range
  };
  for (const auto& flip : flips) {
    std::string bytes = original;
    bytes[bytes.size() - flip.from_end] = char(bytes[bytes.size() - flip.from_end] ^ 0xff);
    const auto path = dir / ("flip" + std::to_string(flip.from_end) + ".drc");
    writeBytes(path, bytes);
    try {
      const TriMesh m = loadMesh(path);
      ADD_FAILURE() << path << " loaded, bounds y " << m.bounds().lo.y;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(flip.fragment), std::string::npos) << e.what();
      EXPECT_EQ(e.file(), path.string());
    }
  }
}

TEST(DracoCorruption, HeaderFaceCountIsReadForCurrentFiles) {
  EXPECT_EQ(detail::declaredDracoFaceCount(readBytes(dataFile("dragon.drc"))), 100000);
  // Bitstream 1.1 (the reference bunny, bun_zipper's 69,451 faces): fixed-width counts.
  EXPECT_EQ(detail::declaredDracoFaceCount(readBytes(dataFile("draco/bunny.drc"))), 69451);
  // Sequential connectivity (speed 10) declares its count too.
  ScratchDir dir("draco_header");
  saveMesh(unitCube(), dir / "seq.drc", {.draco_speed = 10});
  EXPECT_EQ(detail::declaredDracoFaceCount(readBytes(dir / "seq.drc")), 12);
  saveMesh(unitCube(), dir / "eb.drc", {.draco_speed = 5});
  EXPECT_EQ(detail::declaredDracoFaceCount(readBytes(dir / "eb.drc")), 12);
  EXPECT_EQ(detail::declaredDracoFaceCount("DRACO"), -1);
}

}  // namespace
}  // namespace proxyvis::test
