// Bad input: every broken file is a proxyvis::Error (exit code 2 in the apps) whose message
// names the file; nothing crashes and nothing allocates what a lying header asks for.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstring>
#include <limits>
#include <set>

#include "mesh/io/mesh_io.h"
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
  // Half: fits the minimum size of the declared records; walking the records finds the end.
  expectBroken("half.ply", full.substr(0, full.size() / 2), "file ends inside face");
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

// An OFF file that ends on its counts' line has no vertex or face line at all (the check once
// walked the records only from the next newline on, and let these through to OpenMesh).
TEST_F(BrokenFiles, OffEndingOnItsCountsLineIsTruncated) {
  expectBroken("counts_only.off", "CNOFF # c\n# comment line\n4 2 0 # counts",
               "file ends after 0 of 6 vertex and face lines");
  expectBroken("one_line.off", "OFF\n3 1 0 0 0 0 1 0 0 0 1 0 3 0 1 2",
               "file ends after 0 of 4 vertex and face lines");
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

// The robustness run's file: 127 bytes declaring 2^31-1 vertices that have no properties (zero
// bytes each, so no file size could bound them); OpenMesh reserved 12 GB for them.
TEST_F(BrokenFiles, ElementWithoutPropertiesIsRefused) {
  const std::string header =
      "ply\nformat binary_little_endian 1.0\nelement vertex 2147483647\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n";
  ASSERT_EQ(header.size(), 127u);
  expectBroken("no_properties.ply", header, "2147483647 'vertex' elements with no properties");
  std::string ascii = header;
  ascii.replace(ascii.find("binary_little_endian"), 20, "ascii");
  expectBroken("no_properties_ascii.ply", ascii + "3 0 1 2\n", "with no properties");
  // An element of no records needs no properties.
  writeBytes(dir / "empty_element.ply",
             "ply\nformat ascii 1.0\nelement extra 0\nelement vertex 3\nproperty float x\n"
             "property float y\nproperty float z\nelement face 1\n"
             "property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n"
             "3 0 1 2\n");
  EXPECT_EQ(loadMesh(dir / "empty_element.ply").numTriangles(), 1u);
}

TEST_F(BrokenFiles, DevicesAndFifosAreNeverOpened) {
  for (const char* name : {"zero.ply", "zero.obj", "zero.off", "zero.drc"}) {
    fs::create_symlink("/dev/zero", dir / name);
    expectLoadError(dir / name, "not a regular file");
  }
  for (const char* name : {"fifo.ply", "fifo.obj", "fifo.off", "fifo.drc"}) {
    ASSERT_EQ(::mkfifo((dir / name).c_str(), 0600), 0);
    expectLoadError(dir / name, "not a regular file");  // would block forever if opened
  }
}

// Numbers beyond float range made OpenMesh's readers fail mid-stream: OFF and PLY then used
// uninitialised values (a changed triangle or a garbage index, different on every run) and OBJ
// dropped the vertex so that later faces silently used the next one. Each is an Error naming
// the line.
TEST_F(BrokenFiles, CoordinatesBeyondFloatRangeNameTheLine) {
  expectBroken("big.off", "OFF\n3 1 0\n0 0 0\n1e39 0 0\n0 1 0\n3 0 1 2\n",
               "number beyond float range on line 4: '1e39'");
  expectBroken("big.obj", "v 0 0 0\nv 1 0 0\nv 0 -1e39 0\nv 0 0 1\nf 1 2 3\nf 1 3 4\n",
               "number beyond float range on line 3: '-1e39'");
  expectBroken("big.ply",
               "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
               "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
               "end_header\n0 0 0\n1 0 0\n0 0 4e38\n3 0 1 2\n",
               "number beyond float range on line 12: '4e38'");
  expectBroken("huge.off", "OFF\n3 1 0\n0 0 0\n1e400 0 0\n0 1 0\n3 0 1 2\n", "line 4");
  // The largest float itself is fine, and so is a value that underflows to zero.
  const TriMesh edge = loadMesh([&] {
    writeBytes(dir / "edge.off", "OFF\n3 1 0\n0 0 0\n3.4e38 0 0\n0 1e-50 1\n3 0 1 2\n");
    return dir / "edge.off";
  }());
  EXPECT_EQ(edge.vertices[1].x, 3.4e38f);
  EXPECT_EQ(edge.vertices[2].y, 0.0f);
}

TEST_F(BrokenFiles, NonNumbersInTextFormatsNameTheLine) {
  expectBroken("nan.obj", "v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n", "not a number on line 3");
  expectBroken("inf.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 inf 0\n3 0 1 2\n", "not a number on line 5");
  // A bad vertex line must not shift the vertices after it: the face would use another one.
  expectBroken("bad_vertex.obj", "v 0 0 0\nv 1 x 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 3 4\n",
               "not a number on line 2: 'x'");
}

// Integers are read with operator>>: "1.5" or "1e5" became index 1 and shifted the rest, a count
// "3.5" or an index beyond int failed the stream and OpenMesh went on with uninitialised values.
TEST_F(BrokenFiles, NonIntegerCountsAndIndicesNameTheLine) {
  const std::string off = "OFF\n3 1 0\n0 0 0\n1 0 0\n# comment\n\n0 1 0\n";
  expectBroken("frac_index.off", off + "3 0 1 1.5\n", "face index '1.5' on line 8");
  expectBroken("frac_count.off", off + "3.5 0 1 2\n", "face vertex count '3.5' on line 8");
  expectBroken("big_index.off", off + "3 0 1 3000000000\n", "'3000000000' on line 8");
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n";
  expectBroken("exp_index.ply", ply + "3 0 1 1e5\n", "'1e5' on line 13 is not a valid int value");
  expectBroken("big_index.ply", ply + "3 0 1 3000000000\n", "'3000000000' on line 13");
  expectBroken("frac_length.ply", ply + "3.0 0 1 2\n", "is not a valid list length");
  expectBroken("neg_uchar.ply", ply + "300 0 1 2\n", "'300' on line 13");
  // An OBJ face whose index overflows int was dropped without a word.
  expectBroken("big_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 9999999999\n",
               "bad face index '9999999999' on line 5");
  // Colours after the indices of an OFF face may be decimals.
  // OpenMesh reads an OFF vertex from one line: a short line left coordinates uninitialised.
  expectBroken("split_vertex.off", "OFF\n3 1 0\n0 0 0\n1\n0 0\n0 1 0\n3 0 1 2\n",
               "vertex line 4 has 1 values");
  expectBroken("joined_vertices.off", "OFF\n3 1 0\n0 0 0\n1 0 0 0 1 0\n3 0 1 2\n",
               "file ends after 3 of 4 vertex and face lines");
  expectBroken("comment_vertex.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 # 1 0\n3 0 1 2\n",
               "vertex line 5 has 1 values");
  // Comments inside the body are OFF too (OpenMesh skipped them only in the header).
  writeBytes(dir / "colour.off", off + "3 0 1 2 0.5 0.25 1\n");
  const TriMesh coloured = loadMesh(dir / "colour.off");
  EXPECT_EQ(coloured.triangles, (std::vector<Triangle>{{0, 1, 2}}));
  EXPECT_EQ(coloured.vertices[2], Vec3f(0, 1, 0));
}

// A binary list length is read from the file: 2e9 in a 100-byte file kept OpenMesh reading past
// the end for minutes.
TEST_F(BrokenFiles, BinaryListLongerThanTheFileIsRefused) {
  for (const bool big_endian : {false, true}) {
    std::string ply = "ply\nformat " +
                      std::string(big_endian ? "binary_big_endian" : "binary_little_endian") +
                      " 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                      "property float z\nelement face 1\nproperty list int int vertex_indices\n"
                      "end_header\n";
    ply += std::string(36, '\0');  // three vertices at the origin (0.0f in either byte order)
    const char count[4] = {0x77, 0x35, (char)0x94, 0x00};  // 2000000000 = 0x77359400
    for (int k = 0; k < 4; ++k) ply.push_back(big_endian ? count[k] : count[3 - k]);
    ply += std::string(12, '\0');
    expectBroken(big_endian ? "long_list_be.ply" : "long_list_le.ply", ply,
                 "its list of 2000000000 items needs 8000000000 bytes, 12 are left");
  }
  std::string negative = binaryPlyHeader(3, 1) + std::string(36, '\0');
  negative.replace(negative.find("uchar"), 5, "char");
  negative.push_back(char(-3));
  negative += std::string(12, '\0');
  expectBroken("negative_list.ply", negative, "list length -3 in face 0");
}

// Binary formats have no lines: a non-finite value names the vertex.
TEST_F(BrokenFiles, NonFiniteBinaryCoordinateNamesTheVertex) {
  std::string ply =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty double x\n"
      "property double y\nproperty double z\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n";
  for (double v : {0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1e39, 0.0}) append(ply, v);
  append(ply, uint8_t(3));
  for (int i : {0, 1, 2}) append(ply, int32_t(i));
  expectBroken("big_double.ply", ply, "vertex 2 has a NaN or infinite coordinate");
}

// Bytes of a corrupt file never reach the terminal: quoted text keeps printable ASCII only.
TEST_F(BrokenFiles, MessagesQuoteOnlyPrintableText) {
  const std::string cases[][2] = {
      {"bin_name.ply",
       "ply\nformat ascii 1.0\nelement v\x01\xfe\x1b[31m 3\nproperty float x\nend_header\n"},
      {"bin_keyword.ply", "ply\nformat ascii 1.0\n\x07\x9b\xff junk\nend_header\n"},
      {"bin_format.ply", "ply\nformat \x1b\x80 1.0\nend_header\n"},
      {"bin_token.off", "OFF\n3 1 0\n0 0 0\n1 \x1b\xff 0\n0 1 0\n3 0 1 2\n"},
      {"bin_token.obj", "v 0 0 0\nv 1 \x1b]0;x\x07 0\nv 0 1 0\nf 1 2 3\n"},
      {"bin_face.obj",
       "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 \x9b"
       "3\n"},
      {"bin.drc", std::string("DRACO\x02\x02\x01\x01\x00\x00\xff\xfe\x1b", 14)},
  };
  for (const auto& [name, bytes] : cases) {
    writeBytes(dir / name, bytes);
    try {
      loadMesh(dir / name);
      ADD_FAILURE() << name << " loaded";
    } catch (const Error& e) {
      for (unsigned char c : std::string(e.what()))
        EXPECT_TRUE(c >= 32 && c < 127) << name << ": byte " << int(c) << " in " << e.what();
    }
  }
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
  std::set<std::string> files;
  for (const auto& entry : fs::directory_iterator(dir.path()))
    files.insert(entry.path().filename().string());
  EXPECT_EQ(files, (std::set<std::string>{"cube.off", "cube.off.sha256"}));  // no temporary
}

}  // namespace
}  // namespace proxyvis::test
