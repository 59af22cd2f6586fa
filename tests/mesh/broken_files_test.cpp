// Bad input: every broken file is a proxyvis::Error (exit code 2 in the apps) whose message
// names the file; nothing crashes and nothing allocates what a lying header asks for.
#include <gtest/gtest.h>

#include <cstring>
#include <limits>

#include "mesh/mesh_io.h"
#include "mesh_test_util.h"
#include "util/error.h"

namespace proxyvis::test {
namespace {
namespace fs = std::filesystem;

// Loads `path`, expects an Error (not a WriteError) naming the file and containing `fragment`.
void expectLoadError(const fs::path& path, const std::string& fragment) {
  try {
    const TriMesh m = loadMesh(path);
    ADD_FAILURE() << path << " loaded (" << m.numVertices() << " vertices, " << m.numTriangles()
                  << " triangles) but should have failed with '" << fragment << "'";
  } catch (const WriteError& e) {
    ADD_FAILURE() << "WriteError instead of Error: " << e.what();
  } catch (const Error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(path.string()), std::string::npos) << msg;
    EXPECT_EQ(e.file(), path.string());
    EXPECT_NE(msg.find(fragment), std::string::npos) << "'" << fragment << "' not in: " << msg;
    EXPECT_EQ(e.exitCode(), kExitBadInput);
  }
}

std::string binaryPlyHeader(size_t vertices, size_t faces) {
  return "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(vertices) +
         "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
         std::to_string(faces) + "\nproperty list uchar int vertex_indices\nend_header\n";
}

template <typename T>
void append(std::string& s, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  s.append(bytes, sizeof(T));
}

// One binary PLY triangle with the given positions and indices.
std::string binaryPlyTriangle(const float (&xyz)[9], const int (&idx)[3]) {
  std::string s = binaryPlyHeader(3, 1);
  for (float v : xyz) append(s, v);
  append(s, uint8_t(3));
  for (int i : idx) append(s, int32_t(i));
  return s;
}

class BrokenFiles : public ::testing::Test {
 protected:
  // Writes `bytes` to `name` in the scratch folder and expects loading it to fail (see
  // expectLoadError).
  void expectBroken(const std::string& name, const std::string& bytes,
                    const std::string& fragment) {
    writeBytes(dir / name, bytes);
    expectLoadError(dir / name, fragment);
  }
  ScratchDir dir{"broken"};
};

TEST_F(BrokenFiles, MissingFile) {
  expectLoadError(dir / "nope.ply", "not found");
}

TEST_F(BrokenFiles, DirectoryInsteadOfFile) {
  fs::create_directory(dir / "folder.obj");
  expectLoadError(dir / "folder.obj", "directory");
}

TEST_F(BrokenFiles, EmptyFile) {
  for (const char* name : {"empty.ply", "empty.obj", "empty.off", "empty.drc"}) {
    expectBroken(name, "", "empty");
  }
}

TEST_F(BrokenFiles, UnknownExtension) {
  fs::copy_file(dataFile("bunny.off"), dir / "bunny.stl");
  expectLoadError(dir / "bunny.stl", "unknown mesh file extension");
  fs::copy_file(dataFile("bunny.off"), dir / "bunny");
  expectLoadError(dir / "bunny", "unknown mesh file extension");
}

TEST_F(BrokenFiles, TruncatedBinaryPly) {
  ScratchDir scratch("trunc_src");
  saveMesh(loadMesh(dataFile("bunny.off")), scratch / "bunny.ply");
  const std::string full = readBytes(scratch / "bunny.ply");
  // A quarter of the file: the header's counts no longer fit (caught before reading).
  expectBroken("quarter.ply", full.substr(0, full.size() / 4), "truncated");
  // Half: fits the minimum size of the declared records, OpenMesh's reader notices the end.
  expectBroken("half.ply", full.substr(0, full.size() / 2), "end of file");
  // A few bytes short: only the reader can notice (the last face is incomplete).
  expectBroken("short.ply", full.substr(0, full.size() - 5), "");
  // Header only.
  expectBroken("header.ply", full.substr(0, full.find("end_header") + 11), "truncated");
}

TEST_F(BrokenFiles, TruncatedAsciiOffAndDraco) {
  const std::string off = readBytes(dataFile("bunny.off"));
  expectBroken("short.off", off.substr(0, off.size() / 3),
               "header declares 3485 vertices and 6966 faces");
  const std::string drc = readBytes(dataFile("draco/bunny.drc"));
  expectBroken("short.drc", drc.substr(0, drc.size() / 2), "Draco");
}

TEST_F(BrokenFiles, NanAndInfCoordinates) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  expectBroken("nan.ply", binaryPlyTriangle({0, 0, 0, 1, 0, 0, 0, nan, 0}, {0, 1, 2}), "NaN");
  expectBroken("inf.ply", binaryPlyTriangle({0, 0, 0, inf, 0, 0, 0, 1, 0}, {0, 1, 2}), "infinite");
  expectBroken("nan.obj", "v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n", "");
  expectBroken("inf.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 inf 0\n3 0 1 2\n", "");
}

TEST_F(BrokenFiles, IndexOutOfRange) {
  expectBroken("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n", "out of range");
  expectBroken("bad.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n", "out of range");
  expectBroken("neg.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", "");
  expectBroken("bad.ply", binaryPlyTriangle({0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 1, 1000}),
               "out of range");
  expectBroken(
      "ascii.ply",
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n",
      "out of range");
}

TEST_F(BrokenFiles, HugeDeclaredCounts) {
  // 2^31 - 1 vertices claimed in a tiny file: must fail before any allocation.
  expectBroken("huge.ply", binaryPlyHeader(2147483647u, 1) + std::string(1000, '\0'), "2147483647");
  expectBroken("huge_faces.ply", binaryPlyHeader(3, 2000000000u) + std::string(1000, '\0'),
               "2000000000");
  expectBroken("over.ply", binaryPlyHeader(4294967296u, 1) + std::string(100, '\0'), "4294967296");
  expectBroken("huge.off", "OFF\n2000000000 1 0\n0 0 0\n", "2000000000");
  expectBroken("neg.off", "OFF\n-5 1 0\n0 0 0\n", "");
}

TEST_F(BrokenFiles, GarbageBytes) {
  std::string garbage;
  uint32_t x = 12345;
  for (int i = 0; i < 4096; ++i) {
    x = x * 1664525u + 1013904223u;  // fixed LCG: the same garbage every run
    garbage.push_back(char(x >> 24));
  }
  for (const char* name : {"g.ply", "g.obj", "g.off", "g.drc"}) {
    expectBroken(name, garbage, "");
  }
  expectBroken("text.obj", "this is not a mesh\njust words\n", "no triangles");
}

TEST_F(BrokenFiles, NoTriangles) {
  expectBroken("points.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n", "no triangles");
  expectBroken("points.obj", "v 0 0 0\nv 1 0 0\n", "no triangles");
}

TEST_F(BrokenFiles, SaveToMissingDirectoryIsWriteErrorAndLeavesNothing) {
  const TriMesh cube = unitCube();
  for (const char* name : {"cube.ply", "cube.obj", "cube.off", "cube.drc"}) {
    const fs::path target = dir / "missing" / name;
    EXPECT_THROW(saveMesh(cube, target), WriteError) << name;
    EXPECT_FALSE(fs::exists(target));
    EXPECT_FALSE(fs::exists(dir / "missing"));
  }
  EXPECT_TRUE(fs::is_empty(dir.path()));
}

TEST_F(BrokenFiles, SaveWithUnknownExtensionIsErrorAndLeavesNothing) {
  try {
    saveMesh(unitCube(), dir / "cube.stl");
    ADD_FAILURE() << "saved an .stl";
  } catch (const WriteError&) {
    ADD_FAILURE() << "an unknown extension is bad input, not a write failure";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("cube.stl"), std::string::npos);
  }
  EXPECT_TRUE(fs::is_empty(dir.path()));
}

TEST_F(BrokenFiles, SaveOverwritesAtomically) {
  saveMesh(unitCube(), dir / "cube.off");
  saveMesh(loadMesh(dataFile("bunny.off")), dir / "cube.off");
  EXPECT_EQ(loadMesh(dir / "cube.off").numTriangles(), 6966u);
  size_t files = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir.path())) ++files;
  EXPECT_EQ(files, 1u);  // no temporary left behind
}

}  // namespace
}  // namespace proxyvis::test
