// Scene values the renderer's float arithmetic cannot take are refused at load, each with its own
// message naming the file, the JSON path, the value and the allowed range. Expected texts are
// written out here, not produced by the loader's formatting code.
#include <gtest/gtest.h>

#include <initializer_list>
#include <string>

#include "scene/scene_desc.h"
#include "tests/support/scratch_dir.h"
#include "util/error.h"

namespace proxyvis {
namespace {

using test::ScratchDir;

constexpr const char* kScene = R"({
  "camera": {"eye": [0, 1, 5], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov_deg": 40,
             "resolution": [32, 24]},
  "lights": [{"type": "quad", "corner": [-1, 4, -1], "edge_u": [2, 0, 0], "edge_v": [0, 0, 2],
              "radiance": [5, 5, 5]}],
  "meshes": [{"name": "a", "file": "a.obj", "transform": {"translate": [0, 0, 0], "scale": 1}}]
})";

struct SceneRanges : ::testing::Test {
  ScratchDir dir;
  void SetUp() override { dir.write("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"); }

  std::filesystem::path sceneWith(const std::string& from, const std::string& to) {
    std::string text = kScene;
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return dir.write("ranges.json", text);
  }
  // The message of loading the scene with `from` replaced by `to` ("" if it loads).
  std::string errorFor(const std::string& from, const std::string& to) {
    const auto path = sceneWith(from, to);
    try {
      loadSceneDesc(path);
    } catch (const Error& e) {
      EXPECT_EQ(e.file(), path.string());
      return e.what();
    }
    return {};
  }
  bool loads(const std::string& from, const std::string& to) { return errorFor(from, to).empty(); }
};

#define EXPECT_CONTAINS(text, part) EXPECT_NE((text).find(part), std::string::npos) << (text)

// The error message holds every one of `parts`.
void expectContainsAll(const std::string& error, std::initializer_list<const char*> parts) {
  for (const char* part : parts) EXPECT_CONTAINS(error, part);
}

// An edit of the scene (`from` replaced by `to`) and what its error says.
struct Refusal {
  const char* from;
  const char* to;
  const char* message;
};

TEST_F(SceneRanges, TheUnchangedSceneLoads) {
  EXPECT_TRUE(loads("", ""));
}

TEST_F(SceneRanges, HugeRadianceIsRefusedWithItsRange) {
  expectContainsAll(errorFor("\"radiance\": [5, 5, 5]", "\"radiance\": [5, 1e38, 5]"),
                    {"ranges.json: lights[0].radiance: radiance 1e+38 out of range", "[0, 1e+06]",
                     "(express the radiances in a larger unit"});
  EXPECT_TRUE(loads("\"radiance\": [5, 5, 5]", "\"radiance\": [1000000, 0, 5]"));
  EXPECT_CONTAINS(errorFor("\"radiance\": [5, 5, 5]", "\"radiance\": [5, -0.5, 5]"),
                  "radiance -0.5 out of range");
}

TEST_F(SceneRanges, FarEyeIsOutOfRangeNotParallelUp) {
  const std::string e = errorFor("\"eye\": [0, 1, 5]", "\"eye\": [0, 1, 1e30]");
  EXPECT_CONTAINS(e, "ranges.json: camera.eye: eye coordinate 1e+30 out of range");
  EXPECT_CONTAINS(e, "[-1e+06, 1e+06]");
  EXPECT_EQ(e.find("parallel"), std::string::npos) << e;
  EXPECT_CONTAINS(errorFor("\"look_at\": [0, 0, 0]", "\"look_at\": [-2e6, 0, 0]"),
                  "camera.look_at: look_at coordinate -2e+06 out of range");
  EXPECT_TRUE(loads("\"eye\": [0, 1, 5]", "\"eye\": [0, 1, 1000000]"));
}

TEST_F(SceneRanges, EachCameraProblemHasItsOwnMessage) {
  const Refusal refused[] = {
      {"\"look_at\": [0, 0, 0]", "\"look_at\": [0, 1, 5]",
       "ranges.json: camera: eye and look_at coincide"},
      {"\"up\": [0, 1, 0]", "\"up\": [0, 0, 0]", "camera.up: length 0 out of range"},
      {"\"up\": [0, 1, 0]", "\"up\": [0, 1e-30, 0]", "camera.up: length 1e-30 out of range"},
      {"\"up\": [0, 1, 0]", "\"up\": [0, 2, 10]",
       "camera.up: up is parallel to the view direction"}};
  for (const Refusal& r : refused) EXPECT_CONTAINS(errorFor(r.from, r.to), r.message);
  EXPECT_TRUE(loads("\"up\": [0, 1, 0]", "\"up\": [0, 1e-3, 0]"));
  // Looking straight down with the default up: reported at "camera", not as a missing "up".
  EXPECT_CONTAINS(
      errorFor("\"eye\": [0, 1, 5], \"look_at\": [0, 0, 0], \"up\": [0, 1, 0],",
               "\"eye\": [0, 5, 0], \"look_at\": [0, 0, 0],"),
      "ranges.json: camera: the default up [0, 1, 0] is parallel to the view direction");
}

TEST_F(SceneRanges, FieldOfViewMustKeepItsTangentFinite) {
  EXPECT_CONTAINS(errorFor("\"fov_deg\": 40", "\"fov_deg\": 179.9"),
                  "camera.fov_deg: field of view 179.9 out of range");
  EXPECT_CONTAINS(errorFor("\"fov_deg\": 40", "\"fov_deg\": 1e-5"), "in [0.01, 179]");
  EXPECT_TRUE(loads("\"fov_deg\": 40", "\"fov_deg\": 179"));
}

TEST_F(SceneRanges, ResolutionLimitIsTheNamedConstant) {
  EXPECT_EQ(kMaxImageSide, 16384);
  EXPECT_TRUE(loads("[32, 24]", "[16384, 1]"));
  EXPECT_CONTAINS(errorFor("[32, 24]", "[16385, 1]"),
                  "camera.resolution: width and height must be in [1, 16384]");
}

TEST_F(SceneRanges, TransformsMayNotScaleBeyondTheRange) {
  const Refusal refused[] = {
      {"\"scale\": 1", "\"scale\": 1e7",
       "meshes[0].transform: transform scales by 1e+07, more than 1e+06"},
      {"\"scale\": 1", "\"scale\": 1e-7",
       "meshes[0].transform: transform scales down by 1e+07, more than 1e+06"},
      {"\"translate\": [0, 0, 0]", "\"translate\": [0, 3e6, 0]",
       "meshes[0].transform: translation coordinate 3e+06 out of range"},
      {"{\"translate\": [0, 0, 0], \"scale\": 1}", "[1, 0, 0, 0, 0, 1e30, 0, 0, 0, 0, 1, 0]",
       "transform scales by 1e+30"},
      {"\"scale\": 1", "\"scale\": 0", "singular transform"}};
  for (const Refusal& r : refused) EXPECT_CONTAINS(errorFor(r.from, r.to), r.message);
  EXPECT_TRUE(loads("\"scale\": 1", "\"scale\": [1e6, 1e-6, 1]"));
}

TEST_F(SceneRanges, LightsMustStayInRangeAndHaveArea) {
  EXPECT_CONTAINS(errorFor("\"corner\": [-1, 4, -1]", "\"corner\": [-1, 4e30, -1]"),
                  "lights[0].corner: corner coordinate 4e+30 out of range");
  // Corner and edges in range, the far corner not.
  EXPECT_CONTAINS(errorFor("\"edge_u\": [2, 0, 0]", "\"edge_u\": [2e6, 0, 0]"),
                  "lights[0]: light vertex coordinate 2e+06 out of range");
  const std::string tiny = errorFor("\"edge_u\": [2, 0, 0], \"edge_v\": [0, 0, 2]",
                                    "\"edge_u\": [1e-7, 0, 0], \"edge_v\": [0, 0, 1e-7]");
  EXPECT_CONTAINS(tiny, "lights[0]: light triangle of area");
  EXPECT_CONTAINS(tiny, "below 1e-12");
  const std::string vertex = errorFor(
      R"({"type": "quad", "corner": [-1, 4, -1], "edge_u": [2, 0, 0], "edge_v": [0, 0, 2],)",
      R"({"type": "triangle", "vertices": [[0, 4, 0], [1, 4, 0], [0, 4, 1e9]],)");
  EXPECT_CONTAINS(vertex, "lights[0].vertices[2]: vertex coordinate 1e+09 out of range");
}

TEST_F(SceneRanges, UserTextInMessagesIsPrintableAndShort) {
  // A key with an escape sequence and a 200-character light type.
  const std::string key = errorFor("\"fov_deg\": 40", "\"fov_deg\": 40, \"\\u001b[31mx\": 1");
  EXPECT_CONTAINS(key, "camera.\\x1b[31mx: unknown key");
  EXPECT_EQ(key.find('\x1b'), std::string::npos);
  const std::string type =
      errorFor("\"type\": \"quad\"", "\"type\": \"" + std::string(200, 'q') + "\"");
  EXPECT_CONTAINS(type, "unknown light type '" + std::string(60, 'q') + "...'");
  EXPECT_EQ(type.find(std::string(61, 'q')), std::string::npos);
}

}  // namespace
}  // namespace proxyvis
