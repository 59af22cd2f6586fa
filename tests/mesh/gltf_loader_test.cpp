// The glTF loader on documents written here by hand (tests/mesh/gltf_builder.h): every index and
// component type, strides, sparse accessors, quantized positions, strips and fans, node
// transforms, Draco and meshopt compression (the files it must refuse: gltf_refusals_test.cpp).
#include <gtest/gtest.h>
#include <meshoptimizer.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "gltf_builder.h"
#include "gltf_test_util.h"
#include "mesh/io/gltf_scene_content.h"
#include "mesh/io/internal/draco_io.h"
#include "mesh/io/mesh_io.h"
#include "mesh_test_util.h"
#include "util/error.h"

namespace proxyvis::test {
namespace {

TEST(GltfLoader, EveryIndexTypeGivesTheSameTetrahedron) {
  for (int type : {kUByte, kUShort, kUInt}) {
    const TriMesh m = parseGlb(tetra(type));
    ASSERT_EQ(m.numVertices(), 4u) << type;
    ASSERT_EQ(m.numTriangles(), 4u) << type;
    EXPECT_NEAR(m.signedVolume(), 1.0 / 6.0, 1e-7) << type;
    for (size_t k = 0; k < 12; ++k) EXPECT_EQ(m.triangles[k / 3][k % 3], kTetraIndices[k]);
  }
}

TEST(GltfLoader, InterleavedStrideAndNoIndices) {
  // Each position followed by 4 bytes of something else (stride 16); three vertices, no indices.
  std::vector<float> interleaved = {0, 0, 0, 9, 1, 0, 0, 9, 0, 1, 0, 9};
  GltfBuilder b;
  const int p = b.accessor(b.view(interleaved, 16), kFloat, 3, "VEC3");
  b.root(b.node({{"mesh", b.mesh(p)}}));
  const TriMesh m = parseGlb(b);
  ASSERT_EQ(m.numTriangles(), 1u);
  EXPECT_EQ(m.vertices[1], Vec3f(1, 0, 0));
  EXPECT_EQ(m.vertices[2], Vec3f(0, 1, 0));
}

// A strip and a fan over a square in z = 0: every triangle must face +z like the first.
TEST(GltfLoader, StripsAndFansBecomeTriangleListsWithOneWinding) {
  const std::vector<float> square = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};  // strip order
  for (int mode : {5, 6}) {
    GltfBuilder b;
    const int p = b.accessor(b.view(square), kFloat, 4, "VEC3");
    std::vector<uint16_t> idx =
        mode == 5 ? std::vector<uint16_t>{0, 1, 2, 3} : std::vector<uint16_t>{0, 1, 3, 2};
    const int i = b.accessor(b.view(idx), kUShort, 4, "SCALAR");
    b.root(b.node({{"mesh", b.mesh(p, i, mode)}}));
    const TriMesh m = parseGlb(b);
    ASSERT_EQ(m.numTriangles(), 2u) << mode;
    for (const Triangle& t : m.triangles) {
      const Vec3d a(m.vertices[t[0]]), c1(m.vertices[t[1]]), c2(m.vertices[t[2]]);
      EXPECT_GT(cross(c1 - a, c2 - a).z, 0) << "mode " << mode;
    }
  }
}

TEST(GltfLoader, PointsAndLinesAreRefusedNamingMeshAndPrimitive) {
  for (int mode : {0, 1, 2, 3}) {
    GltfBuilder b;
    const int p = b.accessor(b.view(kTetraPositions), kFloat, 4, "VEC3");
    b.root(b.node({{"mesh", b.mesh(p, -1, mode, "wires")}}));
    const std::string e = errorOf([&] { parseGlb(b); });
    EXPECT_NE(e.find("meshes[0].primitives[0] (mesh 'wires') draws"), std::string::npos) << e;
  }
}

TEST(GltfLoader, SparseAccessorReplacesItsElements) {
  GltfBuilder b = tetra();
  // Vertex 3 moves from (0,0,1) to (0,0,2) through a sparse substitution.
  const int idx = b.view(std::vector<uint16_t>{3});
  const int val = b.view(std::vector<float>{0, 0, 2});
  b.doc["accessors"][0]["sparse"] = {{"count", 1},
                                     {"indices", {{"bufferView", idx}, {"componentType", kUShort}}},
                                     {"values", {{"bufferView", val}}}};
  const TriMesh m = parseGlb(b);
  EXPECT_EQ(m.vertices[3], Vec3f(0, 0, 2));
  EXPECT_NEAR(m.signedVolume(), 2.0 / 6.0, 1e-7);
}

TEST(GltfLoader, QuantizedPositionsAreDequantized) {
  // KHR_mesh_quantization: normalized shorts and unsigned bytes, scaled back by the node.
  for (int type : {kShort, kUByte, kByte, kUShort}) {
    GltfBuilder b;
    b.doc["extensionsUsed"] = {"KHR_mesh_quantization"};
    b.doc["extensionsRequired"] = {"KHR_mesh_quantization"};
    const double unit = type == kShort ? 32767 : type == kUByte ? 255 : type == kByte ? 127 : 65535;
    std::string bytes;
    for (float f : kTetraPositions) {
      const long q = std::lround(f * unit);
      if (type == kShort || type == kUShort) {
        const uint16_t v = uint16_t(q);
        bytes.append(reinterpret_cast<const char*>(&v), 2);
      } else {
        bytes.push_back(char(q));
      }
      if (bytes.size() % ((type == kShort || type == kUShort) ? 8 : 4) ==
          ((type == kShort || type == kUShort) ? 6 : 3))
        bytes.append((type == kShort || type == kUShort) ? 2 : 1, '\0');  // 4-byte aligned vertices
    }
    const int stride = (type == kShort || type == kUShort) ? 8 : 4;
    const int p = b.accessor(b.view(bytes, stride), type, 4, "VEC3", /*normalized=*/true);
    const int i = b.accessor(b.view(kTetraIndices), kUInt, 12, "SCALAR");
    b.root(b.node({{"mesh", b.mesh(p, i)}, {"scale", {2.0, 2.0, 2.0}}}));
    const TriMesh m = parseGlb(b);
    EXPECT_EQ(m.vertices[1], Vec3f(2, 0, 0)) << type;
    EXPECT_NEAR(m.signedVolume(), 8.0 / 6.0, 1e-6) << type;
  }
}

TEST(GltfLoader, NodeTransformsComposeFromTheRoot) {
  GltfBuilder b = tetra();
  // Parent: translate by (10, 0, 0); child: rotate 90 degrees about z, then scale 2 (T * R * S).
  b.doc["nodes"][0] = {{"mesh", 0},
                       {"rotation", {0.0, 0.0, std::sqrt(0.5), std::sqrt(0.5)}},
                       {"scale", {2.0, 2.0, 2.0}}};
  b.doc["scenes"][0]["nodes"] = json::array();
  const int parent = b.node({{"translation", {10.0, 0.0, 0.0}}, {"children", {0}}});
  b.root(parent);
  TriMesh m = parseGlb(b);
  // (1,0,0) -> scale (2,0,0) -> rotate (0,2,0) -> translate (10,2,0).
  EXPECT_NEAR(m.vertices[1].x, 10, 1e-5);
  EXPECT_NEAR(m.vertices[1].y, 2, 1e-5);
  EXPECT_NEAR(m.signedVolume(), 8.0 / 6.0, 1e-5);
  // The same as a matrix (column-major), and a mirror: winding turned back, volume positive.
  b.doc["nodes"][1] = {{"matrix", {-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 0, 0, 1}},
                       {"children", {0}}};
  b.doc["nodes"][0] = {{"mesh", 0}};
  m = parseGlb(b);
  EXPECT_EQ(m.vertices[1], Vec3f(4, 0, 0));
  EXPECT_NEAR(m.signedVolume(), 1.0 / 6.0, 1e-6);
}

TEST(GltfLoader, GpuInstancesArePlacedAfterTheirNode) {
  GltfBuilder b = tetra();
  // Two instances: translated by (0,0,0) and (5,0,0), the second also scaled by 2.
  const int t = b.accessor(b.view(std::vector<float>{0, 0, 0, 5, 0, 0}), kFloat, 2, "VEC3");
  const int s = b.accessor(b.view(std::vector<float>{1, 1, 1, 2, 2, 2}), kFloat, 2, "VEC3");
  b.doc["extensionsUsed"] = {"EXT_mesh_gpu_instancing"};
  b.doc["nodes"][0]["translation"] = {0.0, 10.0, 0.0};
  b.doc["nodes"][0]["extensions"] = {
      {"EXT_mesh_gpu_instancing", {{"attributes", {{"TRANSLATION", t}, {"SCALE", s}}}}}};
  const TriMesh m = parseGlb(b);
  ASSERT_EQ(m.numTriangles(), 8u);
  EXPECT_EQ(m.vertices[1], Vec3f(1, 10, 0));
  EXPECT_EQ(m.vertices[5], Vec3f(7, 10, 0));
  EXPECT_NEAR(m.signedVolume(), 9.0 / 6.0, 1e-6);
}

TEST(GltfLoader, PickOneNodeOrOneMeshByName) {
  GltfBuilder b = tetra();
  b.doc["meshes"][0]["name"] = "tetra";
  b.doc["nodes"][0] = {{"name", "near"}, {"mesh", 0}, {"translation", {1.0, 0.0, 0.0}}};
  b.root(b.node({{"name", "far"}, {"children", {2}}, {"translation", {0.0, 100.0, 0.0}}}));
  b.node({{"name", "far child"}, {"mesh", 0}, {"scale", {2.0, 2.0, 2.0}}});
  auto pick = [&](const GltfPick& p) { return parseMeshBytesIn(b.glb(), "t.glb", {}, p); };
  EXPECT_EQ(pick({}).numTriangles(), 8u);
  const TriMesh far = pick({"", "far"});  // the node and its child, placed in the world
  ASSERT_EQ(far.numTriangles(), 4u);
  EXPECT_EQ(far.vertices[1], Vec3f(2, 100, 0));
  const TriMesh child = pick({"", "far child"});  // its parent's transform still applies
  EXPECT_EQ(child.vertices[1], Vec3f(2, 100, 0));
  const TriMesh mesh = pick({"tetra", ""});  // the mesh in its own coordinates
  EXPECT_EQ(mesh.vertices[1], Vec3f(1, 0, 0));
  EXPECT_NE(errorOf([&] {
              pick({"", "nowhere"});
            }).find("no node is named 'nowhere'; the file's nodes: 'near', 'far', 'far child'"),
            std::string::npos);
  b.doc["nodes"][2]["name"] = "far";
  EXPECT_NE(errorOf([&] { pick({"", "far"}); }).find("2 nodes are named 'far'"), std::string::npos);
}

TEST(GltfLoader, HiddenNodesAreLeftOutUnlessPickedByName) {
  GltfBuilder b = tetra();
  b.doc["nodes"][0]["name"] = "shown";
  b.doc["nodes"][0]["children"] = {1};
  b.node({{"name", "hidden"},
          {"mesh", 0},
          {"translation", {5.0, 0.0, 0.0}},
          {"extensions", {{"KHR_node_visibility", {{"visible", false}}}}}});
  auto load = [&](const GltfPick& p) { return parseMeshBytesIn(b.glb(), "t.glb", {}, p); };
  EXPECT_EQ(load({}).numTriangles(), 4u);
  const TriMesh hidden = load({"", "hidden"});
  ASSERT_EQ(hidden.numTriangles(), 4u);
  EXPECT_EQ(hidden.vertices[1], Vec3f(6, 0, 0));
}

TEST(GltfScene, CameraLightsAndInstances) {
  ScratchDir dir;
  GltfBuilder b = tetra();
  // A second mesh, emissive only: a light, no surface. Its node places it at y = 10.
  const int p = b.accessor(b.view(kTetraPositions), kFloat, 4, "VEC3");
  const int i = b.accessor(b.view(kTetraIndices), kUInt, 12, "SCALAR");
  const int light = b.mesh(p, i, 4, "lamp");
  b.doc["meshes"][size_t(light)]["primitives"][0]["material"] = 0;
  b.doc["materials"] = {
      {{"emissiveFactor", {1.0, 0.5, 0.25}},
       {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4.0}}}}}}};
  b.root(b.node({{"mesh", light}, {"translation", {0.0, 10.0, 0.0}}}));
  b.root(b.node({{"mesh", 0}, {"translation", {3.0, 0.0, 0.0}}}));  // a second instance
  // A camera at (0, 2, 8) turned 90 degrees about y: it looks down -x.
  b.doc["cameras"] = {{{"type", "perspective"},
                       {"perspective", {{"yfov", 0.5}, {"aspectRatio", 2.0}, {"znear", 0.1}}}}};
  b.root(b.node({{"camera", 0},
                 {"translation", {0.0, 2.0, 8.0}},
                 {"rotation", {0.0, std::sqrt(0.5), 0.0, std::sqrt(0.5)}}}));
  writeBytes(dir.path() / "s.glb", b.glb());
  const GltfSceneContent c = readGltfScene(dir.path() / "s.glb");
  ASSERT_EQ(c.meshes.size(), 1u);
  EXPECT_EQ(c.meshes[0].index, 0);
  ASSERT_EQ(c.instances.size(), 2u);
  std::vector<float> xs;  // where each instance puts the vertex (1, 0, 0), in any order
  for (const auto& inst : c.instances) xs.push_back(inst.transform.apply(Vec3f(1, 0, 0)).x);
  std::sort(xs.begin(), xs.end());
  EXPECT_EQ(xs, (std::vector<float>{1, 4}));
  ASSERT_EQ(c.lights.size(), 1u);
  EXPECT_EQ(c.lights[0].triangles.size(), 4u);
  EXPECT_EQ(c.lights[0].radiance, Vec3f(4, 2, 1));
  EXPECT_EQ(c.lights[0].triangles[0][1], Vec3f(0, 11, 0));  // vertex 2 of triangle 0, placed
  ASSERT_TRUE(c.camera.has_value());
  EXPECT_NEAR(c.camera->yfov_deg, 0.5 * 180 / M_PI, 1e-9);
  EXPECT_EQ(c.camera->aspect, 2.0);
  EXPECT_EQ(c.camera->eye, Vec3f(0, 2, 8));
  const Vec3f forward = c.camera->look_at - c.camera->eye;
  EXPECT_NEAR(forward.x, -1, 1e-6);
  EXPECT_NEAR(forward.z, 0, 1e-6);
  EXPECT_NEAR(c.camera->up.y, 1, 1e-6);
  // The prototype loads without its emissive primitives.
  GltfPick pick;
  pick.mesh_index = 0;
  pick.surfaces_only = true;
  EXPECT_EQ(loadMesh(dir.path() / "s.glb", pick).numTriangles(), 4u);
}

TEST(GltfLoader, AFileWithoutNodesGivesEveryMesh) {
  GltfBuilder b = tetra();
  b.doc.erase("nodes");
  b.doc.erase("scenes");
  b.doc.erase("scene");
  EXPECT_EQ(parseGlb(b).numTriangles(), 4u);
}

TEST(GltfLoader, MeshoptCompressedViewsDecodeExactly) {
  // EXT_meshopt_compression: the data lives in buffer 0, buffer 1 is the data-less fallback.
  std::vector<float> positions = kTetraPositions;
  std::string vtx(meshopt_encodeVertexBufferBound(4, 12), '\0');
  vtx.resize(meshopt_encodeVertexBuffer(reinterpret_cast<unsigned char*>(vtx.data()), vtx.size(),
                                        positions.data(), 4, 12));
  std::string idx(meshopt_encodeIndexBufferBound(12, 4), '\0');
  idx.resize(meshopt_encodeIndexBuffer(reinterpret_cast<unsigned char*>(idx.data()), idx.size(),
                                       kTetraIndices.data(), 12));
  GltfBuilder b;
  b.doc["extensionsUsed"] = {"EXT_meshopt_compression"};
  b.doc["extensionsRequired"] = {"EXT_meshopt_compression"};
  b.doc["buffers"].push_back(
      {{"byteLength", 96}, {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}});
  auto compressed = [&](const std::string& bytes, size_t stride, size_t count, const char* mode) {
    const int v = b.view(bytes);
    json& view = b.doc["bufferViews"][size_t(v)];
    view["extensions"] = {{"EXT_meshopt_compression",
                           {{"buffer", 0},
                            {"byteOffset", view["byteOffset"]},
                            {"byteLength", bytes.size()},
                            {"byteStride", stride},
                            {"count", count},
                            {"mode", mode}}}};
    view["buffer"] = 1;
    view["byteOffset"] = 0;
    view["byteLength"] = stride * count;
    if (std::string(mode) == "ATTRIBUTES") view["byteStride"] = stride;
    return v;
  };
  const int p = b.accessor(compressed(vtx, 12, 4, "ATTRIBUTES"), kFloat, 4, "VEC3");
  const int i = b.accessor(compressed(idx, 4, 12, "TRIANGLES"), kUInt, 12, "SCALAR");
  b.root(b.node({{"mesh", b.mesh(p, i)}}));
  const TriMesh m = parseGlb(b);
  ASSERT_EQ(m.numTriangles(), 4u);
  for (size_t k = 0; k < 4; ++k)
    EXPECT_EQ(m.vertices[k], Vec3f(kTetraPositions[3 * k], kTetraPositions[3 * k + 1],
                                   kTetraPositions[3 * k + 2]));
  EXPECT_NEAR(m.signedVolume(), 1.0 / 6.0, 1e-7);
  // A count that the compressed bytes cannot hold is refused before anything is allocated.
  b.doc["bufferViews"][0]["extensions"]["EXT_meshopt_compression"]["count"] = 2000000000;
  const std::string e = errorOf([&] { parseGlb(b); });
  EXPECT_NE(e.find("elements of 12 bytes"), std::string::npos) << e;
}

TEST(GltfLoader, DracoPrimitiveDecodes) {
  TriMesh cube = unitCube();
  const std::string drc = detail::encodeDraco(cube, 0, 5, "cube.drc");
  GltfBuilder b;
  b.doc["extensionsUsed"] = {"KHR_draco_mesh_compression"};
  b.doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  const int view = b.view(drc);
  const int p = b.accessor(-1, kFloat, cube.numVertices(), "VEC3");
  const int i = b.accessor(-1, kUInt, cube.numTriangles() * 3, "SCALAR");
  const int mesh = b.mesh(p, i);
  b.doc["meshes"][size_t(mesh)]["primitives"][0]["extensions"] = {
      {"KHR_draco_mesh_compression", {{"bufferView", view}, {"attributes", {{"POSITION", 0}}}}}};
  b.root(b.node({{"mesh", mesh}}));
  const TriMesh m = parseGlb(b);
  EXPECT_EQ(m.numTriangles(), 12u);
  EXPECT_NEAR(m.signedVolume(), 1.0, 1e-6);
}

TEST(GltfWriter, RoundTripKeepsEveryVertexAndTriangle) {
  ScratchDir dir;
  // A grid with more than 65535 vertices needs 32-bit indices; the cube fits 16 bits.
  TriMesh grid;
  const uint32_t n = 300;
  for (uint32_t y = 0; y < n; ++y)
    for (uint32_t x = 0; x < n; ++x)
      grid.vertices.push_back(Vec3f(float(x) * 0.1f, float(y) * 0.3f, float(x ^ y) * 1e-3f));
  for (uint32_t y = 0; y + 1 < n; ++y)
    for (uint32_t x = 0; x + 1 < n; ++x) {
      const uint32_t v = y * n + x;
      grid.triangles.push_back({v, v + 1, v + n});
      grid.triangles.push_back({v + 1, v + n + 1, v + n});
    }
  for (const TriMesh& mesh : {unitCube(), grid})
    for (const char* extension : {".glb", ".gltf", ".GLB"}) {
      const std::string name = std::to_string(mesh.numVertices()) + extension;
      saveMesh(mesh, dir.path() / name);
      const TriMesh back = loadMesh(dir.path() / name);
      ASSERT_EQ(back.numVertices(), mesh.numVertices()) << name;
      ASSERT_EQ(back.numTriangles(), mesh.numTriangles()) << name;
      EXPECT_TRUE(back.vertices == mesh.vertices) << name;
      EXPECT_TRUE(back.triangles == mesh.triangles) << name;
    }
}

}  // namespace
}  // namespace proxyvis::test
