// Byte-flip fuzzing: small valid files with random bytes changed must either load (and then be a
// consistent mesh) or throw proxyvis::Error; never crash, hang or throw anything else.
#include <gtest/gtest.h>

#include <algorithm>

#include "mesh/io/mesh_io.h"
#include "mesh_test_util.h"
#include "util/error.h"
#include "util/rng.h"

namespace proxyvis::test {
namespace {

struct FuzzStats {
  int loaded = 0, rejected = 0;
};

FuzzStats fuzz(const std::string& original, const std::string& ext, uint64_t seed, int rounds) {
  ScratchDir dir("fuzz_" + ext);
  FuzzStats stats;
  for (int round = 0; round < rounds; ++round) {
    Rng rng(seed, uint64_t(round));
    std::string bytes = original;
    const int flips = 1 + int(rng.nextU32() % 8);
    for (int k = 0; k < flips; ++k) {
      const size_t at = rng.nextU32() % bytes.size();
      // Half the flips write a random byte, half a "dangerous" one (digits, signs, separators).
      static const char kDangerous[] = "0123456789-+.eE \n\t\0\xff";
      bytes[at] = (rng.nextU32() & 1) ? char(rng.nextU32()) : kDangerous[rng.nextU32() % 20];
    }
    if (rng.nextU32() % 4 == 0) bytes.resize(rng.nextU32() % bytes.size());  // and truncate
    // (Appending instead of "f" + to_string(): GCC 12 warns -Wrestrict on that pattern.)
    std::string name = std::to_string(round);
    name.append(".").append(ext);
    const auto path = dir / name;
    writeBytes(path, bytes);
    try {
      const TriMesh m = loadMesh(path);
      // Whatever loads is a valid mesh: finite, indices in range, at least one triangle.
      EXPECT_FALSE(m.triangles.empty());
      size_t bad = 0;
      for (const Vec3f& v : m.vertices) bad += !isFinite(v);
      for (const Triangle& t : m.triangles)
        for (uint32_t i : t) bad += i >= m.numVertices();
      EXPECT_EQ(bad, 0u) << "round " << round;
      ++stats.loaded;
    } catch (const Error& e) {
      const std::string msg = e.what();
      EXPECT_NE(msg.find(path.string()), std::string::npos) << msg;
      // Nothing of the corrupt bytes reaches the terminal except printable ASCII.
      EXPECT_TRUE(
          std::all_of(msg.begin(), msg.end(), [](unsigned char c) { return c >= 32 && c < 127; }))
          << "round " << round << ": " << msg;
      ++stats.rejected;
    }
    std::filesystem::remove(path);
  }
  return stats;
}

// A small mesh (an open 4x4 grid plus a closed tetrahedron) in every text format.
TriMesh smallMesh() {
  TriMesh m;
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) m.vertices.emplace_back(float(x), float(y), 0.5f * float(x * y));
  for (uint32_t y = 0; y < 3; ++y)
    for (uint32_t x = 0; x < 3; ++x) {
      const uint32_t i = y * 4 + x;
      m.triangles.push_back({i, i + 1, i + 5});
      m.triangles.push_back({i, i + 5, i + 4});
    }
  return m;
}

constexpr int kRounds = 5000;  // 20,000 per format also passed (4 s)

class Fuzz : public ::testing::TestWithParam<std::pair<std::string, bool>> {};

TEST_P(Fuzz, ByteFlipsLoadOrThrowError) {
  const auto& [ext, binary] = GetParam();
  ScratchDir dir("fuzz_src_" + ext + (binary ? "_binary" : "_ascii"));  // sources are inputs
  const auto source = dir / ("small." + ext);
  saveMesh(smallMesh(), source, {.binary = binary, .draco_quantization = 12});
  const std::string original = readBytes(source);
  ASSERT_GT(original.size(), 50u);
  const FuzzStats stats = fuzz(original, ext, binary ? 7 : 11, kRounds);
  // The fuzzer must exercise both outcomes, or it tests nothing.
  EXPECT_GT(stats.rejected, 0);
  EXPECT_EQ(stats.loaded + stats.rejected, kRounds);
  // OpenMesh's readers are singletons with state: after thousands of failed reads the intact
  // file must still load exactly.
  const TriMesh again = loadMesh(source);
  const TriMesh expected = smallMesh();
  if (ext == "drc") {  // Draco reorders vertices and faces
    EXPECT_EQ(again.numTriangles(), expected.numTriangles());
  } else {
    EXPECT_EQ(again.triangles, expected.triangles);
    EXPECT_EQ(again.vertices, expected.vertices);
  }
  RecordProperty("loaded", stats.loaded);
  RecordProperty("rejected", stats.rejected);
}

INSTANTIATE_TEST_SUITE_P(Formats, Fuzz,
                         ::testing::Values(std::make_pair(std::string("ply"), true),
                                           std::make_pair(std::string("ply"), false),
                                           std::make_pair(std::string("obj"), false),
                                           std::make_pair(std::string("off"), false),
                                           std::make_pair(std::string("drc"), true),
                                           std::make_pair(std::string("glb"), true),
                                           std::make_pair(std::string("gltf"), false)),
                         [](const auto& info) {
                           return info.param.first + (info.param.second ? "_binary" : "_ascii");
                         });

}  // namespace
}  // namespace proxyvis::test
