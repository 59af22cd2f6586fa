// The glTF loader on the files it must refuse, each with one error naming what is wrong: corrupt
// GLB containers, accessors and indices outside their data, empty buffers, node indices out of
// range, cycles, unsupported required extensions, and URIs that leave the folder (an external
// buffer beside the file is read).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "gltf_builder.h"
#include "gltf_test_util.h"
#include "mesh/io/gltf_scene_content.h"
#include "mesh/io/mesh_io.h"
#include "mesh_test_util.h"
#include "util/error.h"

namespace proxyvis::test {
namespace {
using json = nlohmann::json;

TEST(GltfLoader, CorruptGlbContainersAreRefused) {
  const std::string good = tetra().glb();
  auto with = [&](size_t at, uint32_t value) {
    std::string s = good;
    std::memcpy(s.data() + at, &value, 4);
    return s;
  };
  const std::vector<std::pair<std::string, std::string>> cases = {
      {good.substr(0, 10), "truncated GLB"},
      {good.substr(0, good.size() - 8), "GLB header length lies"},
      {with(8, uint32_t(good.size() + 100)), "GLB header length lies"},
      {with(12, 1u << 30), "GLB chunk 0 length lies"},
      {with(16, 0x004E4942), "GLB chunk 0 is not JSON"},
      {with(4, 1), "GLB version 1"},
      {"{\"asset\":{\"version\":\"2.0\"}}", "not a GLB file"}};
  for (const auto& c : cases) {
    const std::string& bytes = c.first;  // a lambda cannot capture a structured binding in clang 14
    EXPECT_NE(errorOf([&] { parseMeshBytes(bytes, "c.glb"); }).find(c.second), std::string::npos)
        << c.second;
  }
}

TEST(GltfLoader, AccessorsAndIndicesOutsideTheirDataAreRefused) {
  GltfBuilder b = tetra();
  b.doc["accessors"][0]["count"] = 5;  // 60 bytes from a 48-byte view
  EXPECT_NE(errorOf([&] { parseGlb(b); }).find("reaches past its buffer view"), std::string::npos);
  b = tetra();
  b.doc["bufferViews"][0]["byteLength"] = 4096;
  EXPECT_NE(errorOf([&] { parseGlb(b); }).find("bufferViews[0] lies outside its buffer"),
            std::string::npos);
  b = tetra();
  b.doc["accessors"][0].erase("bufferView");
  b.doc["accessors"][0]["count"] = 2000000000;  // zeros that no byte of the file describes
  EXPECT_NE(errorOf([&] { parseGlb(b); }).find("no data"), std::string::npos);
  b = tetra(kUByte);
  b.bin[48 + 5] = char(200);  // index 5 of the tetrahedron's index view
  EXPECT_NE(errorOf([&] { parseGlb(b); }).find("indices[5] is 200"), std::string::npos);
  b = tetra();
  b.doc["accessors"][0]["type"] = "VEC2";
  EXPECT_NE(errorOf([&] { parseGlb(b); }).find("has the wrong type"), std::string::npos);
}

// fuzz_glb: a GLB buffer of byteLength 0 made tinygltf read byte 0 of an empty vector (an
// std::out_of_range, not an Error naming the file).
TEST(GltfLoader, EmptyBufferIsRefusedBeforeTinygltfSeesIt) {
  GltfBuilder b = tetra();
  json doc = b.doc;
  doc["buffers"][0] = {{"byteLength", 0}};
  const std::string e = errorOf([&] { parseMeshBytes(glbBytes(doc.dump(), b.bin), "e.glb"); });
  EXPECT_NE(e.find("e.glb: buffers[0].byteLength is missing or 0"), std::string::npos) << e;
}

// A node's mesh or camera index beyond the file's: the same Error for the mesh and the scene
// reader (the scene reader once indexed with at() and threw std::out_of_range).
TEST(GltfLoader, NodeIndicesOutOfRangeAreRefusedByEveryReader) {
  ScratchDir dir;
  GltfBuilder b = tetra();
  b.doc["nodes"][0]["mesh"] = 5;
  writeBytes(dir.path() / "m.glb", b.glb());
  EXPECT_NE(errorOf([&] { loadMesh(dir.path() / "m.glb"); }).find("nodes[0] names mesh 5"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { readGltfScene(dir.path() / "m.glb"); }).find("nodes[0] names mesh 5"),
            std::string::npos);
  b = tetra();
  b.doc["nodes"][0]["camera"] = 2;
  writeBytes(dir.path() / "c.glb", b.glb());
  EXPECT_NE(errorOf([&] { readGltfScene(dir.path() / "c.glb"); }).find("nodes[0] names camera 2"),
            std::string::npos);
}

TEST(GltfLoader, NodeCyclesAndSharedChildrenAreRefused) {
  GltfBuilder b = tetra();
  b.doc["nodes"][0]["children"] = {0};
  EXPECT_NE(errorOf([&] { parseGlb(b); }).find("nodes[0] is reached twice"), std::string::npos);
  b = tetra();
  b.node({{"children", {0}}});
  b.root(1);
  EXPECT_NE(errorOf([&] { parseGlb(b); }).find("reached twice"), std::string::npos);
}

TEST(GltfLoader, UnsupportedRequiredExtensionIsNamed) {
  GltfBuilder b = tetra();
  b.doc["extensionsUsed"] = {"KHR_materials_variants"};
  b.doc["extensionsRequired"] = {"KHR_materials_variants"};
  EXPECT_NE(errorOf([&] {
              parseGlb(b);
            }).find("extensionsRequired[0] 'KHR_materials_variants' is not supported"),
            std::string::npos);
}

TEST(GltfLoader, ExternalBufferBesideTheFileIsRead) {
  ScratchDir dir;
  const GltfBuilder b = tetra();
  writeBytes(dir.path() / "tetra data.bin", b.bin);
  writeBytes(dir.path() / "t.gltf", b.gltf("tetra%20data.bin"));
  EXPECT_EQ(loadMesh(dir.path() / "t.gltf").numTriangles(), 4u);
  // Parsed from bytes alone there is no folder to read from.
  EXPECT_NE(
      errorOf([&] { parseMeshBytes(b.gltf("tetra%20data.bin"), "t.gltf"); }).find("cannot be read"),
      std::string::npos);
}

TEST(GltfLoader, UrisThatLeaveTheFolderAreNeverRead) {
  ScratchDir dir;
  const GltfBuilder b = tetra();
  std::filesystem::create_directories(dir.path() / "asset");
  writeBytes(dir.path() / "secret.bin", b.bin);
  const std::string abs = (dir.path() / "secret.bin").string();
  for (const std::string& uri :
       {std::string("../secret.bin"), std::string("%2e%2e/secret.bin"), abs, "file://" + abs,
        std::string("http://example.com/t.bin"), std::string("sub\\..\\..\\secret.bin")}) {
    writeBytes(dir.path() / "asset/t.gltf", b.gltf(uri));
    const std::string e = errorOf([&] { loadMesh(dir.path() / "asset/t.gltf"); });
    EXPECT_NE(e.find("buffers[0].uri"), std::string::npos) << uri << ": " << e;
    EXPECT_NE(e.find("leaves the asset's folder"), std::string::npos) << uri << ": " << e;
  }
  // A link inside the folder that points out of it is not followed.
  std::filesystem::create_symlink(dir.path() / "secret.bin", dir.path() / "asset/link.bin");
  writeBytes(dir.path() / "asset/t.gltf", b.gltf("link.bin"));
  EXPECT_NE(errorOf([&] { loadMesh(dir.path() / "asset/t.gltf"); }).find("cannot be read"),
            std::string::npos);
}

}  // namespace
}  // namespace proxyvis::test
