// Scene file parsing: every field, errors that name the JSON path, round trip, hash.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <string>
#include <vector>

#include "scene/scene_desc.h"
#include "scene/transform.h"
#include "tests/support/scratch_dir.h"
#include "util/error.h"

namespace proxyvis {
namespace {

using test::ScratchDir;

// A triangle: loadSceneDesc only checks that referenced files exist.
constexpr const char* kTinyObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

// Every field of the format, with values that differ from the defaults.
constexpr const char* kFullScene = R"({
  // comments are allowed
  "description": "all fields",
  "camera": {"eye": [1, 2, 3], "look_at": [0, 0.5, 0], "up": [0, 0, 1], "fov_deg": 35,
             "resolution": [64, 48]},
  "lights": [
    {"type": "quad", "corner": [-1, 5, -1], "edge_u": [2, 0, 0], "edge_v": [0, 0, 2],
     "radiance": [4, 5, 6]},
    {"type": "triangle", "vertices": [[0, 6, 0], [1, 6, 0], [0, 6, 1]], "radiance": [1, 1, 1]},
    {"type": "triangles", "triangles": [[[0, 7, 0], [1, 7, 0], [0, 7, 1]]], "radiance": [2, 2, 2]}
  ],
  "meshes": [
    {"name": "a", "file": "meshes/a.obj", "albedo": [0.1, 0.2, 0.3],
     "transform": {"translate": [1, 2, 3], "scale": 2},
     "proxies": [{"kind": "outside", "method": "hull", "file": "meshes/a.hull.obj",
                  "class": "outside"},
                 {"kind": "general", "file": "meshes/a.qem.obj"}]},
    {"name": "b", "file": "meshes/a.obj", "place": false, "proxy_max_faces": 96,
     "transform": [1, 0, 0, 5, 0, 1, 0, 6, 0, 0, 1, 7, 0, 0, 0, 1]}
  ],
  "instances": {"file": "inst.txt"}
})";

struct FullSceneFixture : ::testing::Test {
  ScratchDir dir;
  std::filesystem::path scene_path;
  void SetUp() override {
    dir.write("meshes/a.obj", kTinyObj);
    dir.write("meshes/a.hull.obj", kTinyObj);
    dir.write("meshes/a.qem.obj", kTinyObj);
    dir.write("inst.txt", "# comment\nb 1 2 3\n\na 1 0 0 4 0 1 0 5 0 0 1 6  # trailing\n");
    scene_path = dir.write("scene.json", kFullScene);
  }
  // Writes the full scene with `from` replaced by `to` and returns the error message.
  std::string errorFor(const std::string& from, const std::string& to) {
    std::string text = kFullScene;
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
    const auto p = dir.write("bad.json", text);
    try {
      loadSceneDesc(p);
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("bad.json"), std::string::npos) << e.what();
      return e.what();
    }
    ADD_FAILURE() << "no error for " << to;
    return {};
  }
};

TEST_F(FullSceneFixture, ParsesEveryField) {
  const SceneDesc s = loadSceneDesc(scene_path);
  EXPECT_EQ(s.description, "all fields");
  EXPECT_EQ(s.camera.eye, Vec3f(1, 2, 3));
  EXPECT_EQ(s.camera.look_at, Vec3f(0, 0.5f, 0));
  EXPECT_EQ(s.camera.up, Vec3f(0, 0, 1));
  EXPECT_FLOAT_EQ(s.camera.fov_deg, 35);
  EXPECT_EQ(s.camera.width, 64);
  EXPECT_EQ(s.camera.height, 48);

  ASSERT_EQ(s.lights.size(), 3u);
  ASSERT_EQ(s.lights[0].triangles.size(), 2u);  // a quad is two triangles
  EXPECT_EQ(s.lights[0].triangles[0][0], Vec3f(-1, 5, -1));
  EXPECT_EQ(s.lights[0].triangles[0][2], Vec3f(1, 5, 1));  // corner + u + v
  EXPECT_EQ(s.lights[0].radiance, Vec3f(4, 5, 6));
  ASSERT_EQ(s.lights[1].triangles.size(), 1u);
  EXPECT_EQ(s.lights[1].triangles[0][2], Vec3f(0, 6, 1));
  EXPECT_EQ(s.lights[2].radiance, Vec3f(2, 2, 2));

  ASSERT_EQ(s.meshes.size(), 2u);
  const SceneMeshDesc& a = s.meshes[0];
  EXPECT_EQ(a.name, "a");
  EXPECT_EQ(a.file, dir.path() / "meshes/a.obj");  // resolved relative to the scene file
  EXPECT_EQ(a.albedo, Vec3f(0.1f, 0.2f, 0.3f));
  EXPECT_TRUE(a.place);
  EXPECT_EQ(a.transform.apply({1, 1, 1}), Vec3f(3, 4, 5));  // scale 2, then translate
  ASSERT_EQ(a.proxies.size(), 2u);
  EXPECT_EQ(a.proxies[0].kind, "outside");
  EXPECT_EQ(a.proxies[0].method, "hull");
  EXPECT_EQ(a.proxies[0].file, dir.path() / "meshes/a.hull.obj");
  EXPECT_EQ(a.proxies[0].verified_class, ProxyClass::kOutside);
  EXPECT_FALSE(a.proxies[1].verified_class.has_value());  // unverified: treated as general
  const SceneMeshDesc& b = s.meshes[1];
  EXPECT_FALSE(b.place);
  EXPECT_EQ(b.transform.apply({0, 0, 0}), Vec3f(5, 6, 7));
  EXPECT_EQ(b.albedo, Vec3f(0.7f, 0.7f, 0.7f));  // default
  EXPECT_EQ(b.proxy_max_faces, 96u);
  EXPECT_FALSE(a.proxy_max_faces.has_value());  // the run's --max-faces / --ratio

  EXPECT_EQ(s.instances_file, dir.path() / "inst.txt");
  ASSERT_EQ(s.instances.size(), 2u);
  EXPECT_EQ(s.instances[0].mesh, 1u);
  EXPECT_EQ(s.instances[0].transform.apply({0, 0, 0}), Vec3f(1, 2, 3));
  EXPECT_EQ(s.instances[1].mesh, 0u);
  EXPECT_EQ(s.instances[1].transform.apply({1, 1, 1}), Vec3f(5, 6, 7));
  EXPECT_EQ(s.findMesh("b"), 1);
  EXPECT_EQ(s.findMesh("c"), -1);
}

TEST_F(FullSceneFixture, RotateComposesAsTranslateRotateScale) {
  const std::string text = R"({"camera": {"eye": [0,0,5], "look_at": [0,0,0]},
    "lights": [{"type": "triangle", "vertices": [[0,6,0],[1,6,0],[0,6,1]], "radiance": [1,1,1]}],
    "meshes": [{"name": "a", "file": "meshes/a.obj",
                "transform": {"translate": [10, 0, 0], "rotate": [0, 0, 1, 90], "scale": [2, 3, 4]}}]})";
  const SceneDesc s = loadSceneDesc(dir.write("rot.json", text));
  const Vec3f p = s.meshes[0].transform.apply({1, 0, 0});  // scale -> (2,0,0), rotate -> (0,2,0)
  EXPECT_NEAR(p.x, 10, 1e-5);
  EXPECT_NEAR(p.y, 2, 1e-5);
  EXPECT_NEAR(p.z, 0, 1e-5);
}

TEST_F(FullSceneFixture, UnknownKeysNameTheirPath) {
  EXPECT_NE(
      errorFor("\"albedo\": [0.1", "\"albedoo\": [0.1").find("meshes[0].albedoo: unknown key"),
      std::string::npos);
  EXPECT_NE(errorFor("\"fov_deg\": 35", "\"fov\": 35").find("camera.fov: unknown key"),
            std::string::npos);
  EXPECT_NE(errorFor("\"method\": \"hull\"", "\"methd\": \"hull\"")
                .find("meshes[0].proxies[0].methd: unknown key"),
            std::string::npos);
  EXPECT_NE(errorFor("\"description\"", "\"descr\"").find("descr: unknown key"), std::string::npos);
  EXPECT_NE(errorFor("\"edge_v\": [0, 0, 2],", "\"edge_v\": [0, 0, 2], \"x\": 1,")
                .find("lights[0].x: unknown key"),
            std::string::npos);
}

TEST_F(FullSceneFixture, WrongTypesAndValuesNameTheirPath) {
  EXPECT_NE(errorFor("\"albedo\": [0.1, 0.2, 0.3]", "\"albedo\": [0.1, 0.2]")
                .find("meshes[0].albedo: expected an array of 3 numbers"),
            std::string::npos);
  EXPECT_NE(errorFor("\"albedo\": [0.1, 0.2, 0.3]", "\"albedo\": [0.1, \"x\", 0.3]")
                .find("meshes[0].albedo[1]: expected a number"),
            std::string::npos);
  EXPECT_NE(errorFor("\"albedo\": [0.1, 0.2, 0.3]", "\"albedo\": [1.5, 0.2, 0.3]")
                .find("meshes[0].albedo"),
            std::string::npos);
  EXPECT_NE(errorFor("\"resolution\": [64, 48]", "\"resolution\": [64.5, 48]")
                .find("camera.resolution[0]: expected an integer"),
            std::string::npos);
  EXPECT_NE(
      errorFor("\"resolution\": [64, 48]", "\"resolution\": [0, 48]").find("camera.resolution"),
      std::string::npos);
  EXPECT_NE(errorFor("\"fov_deg\": 35", "\"fov_deg\": 180").find("camera.fov_deg"),
            std::string::npos);
  EXPECT_NE(errorFor("\"fov_deg\": 35", "\"fov_deg\": 1e999").find("invalid JSON"),
            std::string::npos);
  EXPECT_NE(
      errorFor("\"place\": false", "\"place\": 0").find("meshes[1].place: expected true or false"),
      std::string::npos);
  EXPECT_NE(
      errorFor("\"radiance\": [4, 5, 6]", "\"radiance\": [-4, 5, 6]").find("lights[0].radiance"),
      std::string::npos);
  EXPECT_NE(errorFor("\"proxy_max_faces\": 96", "\"proxy_max_faces\": -1")
                .find("meshes[1].proxy_max_faces"),
            std::string::npos);
  EXPECT_NE(errorFor("\"proxy_max_faces\": 96", "\"proxy_max_faces\": 96.5")
                .find("meshes[1].proxy_max_faces"),
            std::string::npos);
  EXPECT_NE(errorFor("\"proxy_max_faces\": 96", "\"proxy_max_faces\": 2000000000")
                .find("meshes[1].proxy_max_faces: a face budget above 10^9"),
            std::string::npos);
  EXPECT_NE(errorFor("\"type\": \"quad\"", "\"type\": \"disk\"")
                .find("lights[0].type: unknown light type"),
            std::string::npos);
  EXPECT_NE(errorFor("\"class\": \"outside\"", "\"class\": \"outsid\"")
                .find("meshes[0].proxies[0].class: unknown class"),
            std::string::npos);
  EXPECT_NE(
      errorFor("\"scale\": 2", "\"scale\": 0").find("meshes[0].transform: singular transform"),
      std::string::npos);
  EXPECT_NE(
      errorFor("0, 0, 1, 7, 0, 0, 0, 1]", "0, 0, 1, 7, 0, 0, 1, 1]").find("meshes[1].transform"),
      std::string::npos);
  EXPECT_NE(errorFor("{\"name\": \"b\"", "{\"name\": \"a\"").find("duplicate mesh name"),
            std::string::npos);
  EXPECT_NE(errorFor("\"name\": \"b\"", "\"name\": \"b c\"").find("meshes[1].name"),
            std::string::npos);
  EXPECT_NE(errorFor("\"eye\": [1, 2, 3], ", "").find("camera.eye: missing"), std::string::npos);
  EXPECT_NE(errorFor("\"up\": [0, 0, 1]", "\"up\": [1, 1.5, 3]").find("parallel"),
            std::string::npos);
  EXPECT_NE(errorFor("\"inst.txt\"}\n}", "\"inst.txt\"}\n").find("invalid JSON"),
            std::string::npos);
}

TEST_F(FullSceneFixture, MissingFilesAreNamed) {
  const std::string msg = errorFor("meshes/a.qem.obj", "meshes/nope.obj");
  EXPECT_NE(msg.find("meshes[0].proxies[1].file: file not found"), std::string::npos) << msg;
  EXPECT_NE(msg.find("nope.obj"), std::string::npos) << msg;
  EXPECT_NE(errorFor("inst.txt", "none.txt").find("instances.file: file not found"),
            std::string::npos);
  EXPECT_THROW(loadSceneDesc(dir.path() / "absent.json"), Error);
}

TEST_F(FullSceneFixture, SaveThenLoadRoundTrips) {
  const SceneDesc s = loadSceneDesc(scene_path);
  const auto out = dir.path() / "sub" / "copy.json";
  std::filesystem::create_directories(out.parent_path());
  saveSceneDesc(s, out);
  const SceneDesc t = loadSceneDesc(out);
  EXPECT_EQ(t.description, s.description);
  EXPECT_EQ(t.camera.eye, s.camera.eye);
  EXPECT_EQ(t.camera.up, s.camera.up);
  EXPECT_EQ(t.camera.fov_deg, s.camera.fov_deg);
  EXPECT_EQ(t.camera.width, s.camera.width);
  ASSERT_EQ(t.lights.size(), s.lights.size());
  for (size_t i = 0; i < s.lights.size(); ++i) {
    EXPECT_EQ(t.lights[i].radiance, s.lights[i].radiance);
    ASSERT_EQ(t.lights[i].triangles.size(), s.lights[i].triangles.size());
    for (size_t k = 0; k < s.lights[i].triangles.size(); ++k)
      for (int v = 0; v < 3; ++v)
        EXPECT_EQ(t.lights[i].triangles[k][v], s.lights[i].triangles[k][v]);
  }
  ASSERT_EQ(t.meshes.size(), s.meshes.size());
  for (size_t i = 0; i < s.meshes.size(); ++i) {
    EXPECT_EQ(t.meshes[i].name, s.meshes[i].name);
    EXPECT_EQ(t.meshes[i].file, s.meshes[i].file);  // absolute paths survive the relative write
    EXPECT_EQ(t.meshes[i].albedo, s.meshes[i].albedo);
    EXPECT_TRUE(t.meshes[i].transform == s.meshes[i].transform);
    EXPECT_EQ(t.meshes[i].place, s.meshes[i].place);
    EXPECT_EQ(t.meshes[i].proxy_max_faces, s.meshes[i].proxy_max_faces);
    ASSERT_EQ(t.meshes[i].proxies.size(), s.meshes[i].proxies.size());
    for (size_t k = 0; k < s.meshes[i].proxies.size(); ++k) {
      EXPECT_EQ(t.meshes[i].proxies[k].file, s.meshes[i].proxies[k].file);
      EXPECT_EQ(t.meshes[i].proxies[k].kind, s.meshes[i].proxies[k].kind);
      EXPECT_EQ(t.meshes[i].proxies[k].method, s.meshes[i].proxies[k].method);
      EXPECT_EQ(t.meshes[i].proxies[k].verified_class, s.meshes[i].proxies[k].verified_class);
    }
  }
  EXPECT_EQ(t.instances_file, s.instances_file);
  ASSERT_EQ(t.instances.size(), s.instances.size());
  EXPECT_TRUE(t.instances[1].transform == s.instances[1].transform);
}

TEST_F(FullSceneFixture, SavedFileReadsLikeAHandWrittenScene) {
  SceneDesc s = loadSceneDesc(scene_path);
  s.meshes[0].albedo = {0.8f, 1.0f / 3.0f, 1e-5f};
  s.meshes[0].transform = rotation({1, 2, 3}, 33);  // 16 numbers with full float digits
  const auto out = dir.path() / "layout.json";
  saveSceneDesc(s, out);
  std::ifstream in(out);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  auto lineWith = [&](const std::string& key) -> std::string {
    for (const std::string& l : lines)
      if (l.find(key) != std::string::npos) return l;
    ADD_FAILURE() << key << " not found";
    return {};
  };
  // Numbers arrays whole on one line, floats in their shortest form.
  EXPECT_EQ(lineWith("\"eye\""), "    \"eye\": [1, 2, 3],");
  EXPECT_EQ(lineWith("\"albedo\""), "      \"albedo\": [0.8, 0.33333334, 1e-05],");
  EXPECT_NE(lineWith("[[-1, 5, -1], [1, 5, -1], [1, 5, 1]]"), "");  // a light triangle's corners
  const std::string transform = lineWith("\"transform\"");
  EXPECT_EQ(std::count(transform.begin(), transform.end(), ','), 16) << transform;  // + trailing
  EXPECT_TRUE(transform.ends_with("0, 0, 0, 1],")) << transform;
  for (const std::string& l : lines)  // no line holds a lone number
    EXPECT_FALSE(l.find_first_not_of(" -0123456789.e+,") == std::string::npos) << l;
  // And the values read back exactly.
  const SceneDesc t = loadSceneDesc(out);
  EXPECT_EQ(t.meshes[0].albedo, s.meshes[0].albedo);
  EXPECT_TRUE(t.meshes[0].transform == s.meshes[0].transform);
  EXPECT_EQ(t.lights[0].triangles[1][2], s.lights[0].triangles[1][2]);
}

TEST_F(FullSceneFixture, SaveWritesInMemoryInstancesBesideTheScene) {
  SceneDesc s = loadSceneDesc(scene_path);
  s.instances_file.clear();
  s.instances[0].transform = rotation({0, 1, 0}, 33);  // not representable as a translation
  const auto out = dir.path() / "mem.json";
  saveSceneDesc(s, out);
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "mem.instances.txt"));
  const SceneDesc t = loadSceneDesc(out);
  ASSERT_EQ(t.instances.size(), 2u);
  EXPECT_TRUE(t.instances[0].transform == s.instances[0].transform);  // shortest round-trip digits
}

TEST_F(FullSceneFixture, HashChangesWithReferencedFileContents) {
  const SceneDesc s = loadSceneDesc(scene_path);
  const std::string h0 = sceneHash(s);
  EXPECT_EQ(h0.size(), 16u);
  EXPECT_EQ(sceneHash(loadSceneDesc(scene_path)), h0);
  dir.write("meshes/a.hull.obj", std::string(kTinyObj) + "v 0 0 1\n");
  EXPECT_NE(sceneHash(s), h0);
  dir.write("meshes/a.hull.obj", kTinyObj);
  EXPECT_EQ(sceneHash(s), h0);
  SceneDesc moved = s;
  moved.meshes[0].albedo.x = 0.2f;
  EXPECT_NE(sceneHash(moved), h0);
}

// The "name" titles reports: the file's stem without it, kept by a derived scene, not hashed.
TEST_F(FullSceneFixture, NameTitlesTheSceneAndSurvivesSaving) {
  SceneDesc s = loadSceneDesc(scene_path);
  EXPECT_EQ(s.name, "");
  EXPECT_EQ(s.displayName(), "scene");
  const std::string hash = sceneHash(s);
  const auto derived = dir.path() / "out" / "derived.json";
  std::filesystem::create_directories(derived.parent_path());
  saveSceneDesc(s, derived);  // like proxy-gen's DIR/scene.json: the source's title
  EXPECT_EQ(loadSceneDesc(derived).name, "scene");
  s.name = "a garden at dusk";
  EXPECT_EQ(s.displayName(), "a garden at dusk");
  EXPECT_EQ(sceneHash(s), hash);
  const auto named = dir.path() / "out" / "named.json";  // a loaded file is an input: not rewritten
  saveSceneDesc(s, named);
  EXPECT_EQ(loadSceneDesc(named).displayName(), "a garden at dusk");
  std::string text = kFullScene;
  text.insert(text.find('{') + 1, "\"name\": \"bell\\u0007\",");
  const auto bad = dir.write("bad_name.json", text);
  try {
    loadSceneDesc(bad);
    ADD_FAILURE() << "a name with a control character loaded";
  } catch (const Error& e) {
    EXPECT_NE(
        std::string(e.what()).find("bad_name.json: name: the name must be 1 to 200 printable"),
        std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace proxyvis
