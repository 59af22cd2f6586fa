// Scene file parsing (format: scenes/FORMAT.md). Every problem is reported with the scene file
// and the JSON path of the value, e.g. "scenes/x.json: meshes[2].albedoo: unknown key".
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <set>

#include "mesh/io/mesh_io.h"
#include "scene/internal/value_ranges.h"
#include "scene/scene_desc.h"
#include "scene/transform.h"
#include "util/atomic_write.h"
#include "util/error.h"
#include "util/input_file.h"
#include "util/json_field.h"
#include "util/quoted_text.h"

namespace proxyvis {

using Field = JsonField;
using json = nlohmann::json;
using detail::numberText;
using detail::positionProblem;
using detail::RangeProblem;
using detail::transformProblem;
namespace fs = std::filesystem;

namespace {

fs::path resolveFile(const Field& f, const fs::path& scene_dir) {
  const std::string s = f.asString();
  if (s.empty()) f.fail("empty file name");
  fs::path p = fs::path(s).is_absolute() ? fs::path(s) : scene_dir / s;
  p = p.lexically_normal();
  std::error_code ec;
  if (!fs::is_regular_file(p, ec))
    f.fail("file not found: " + p.string(), "paths are relative to the scene file");
  return p;
}

// Reports a range problem at `f`'s JSON path.
void check(const Field& f, const std::optional<RangeProblem>& problem) {
  if (problem) f.fail(problem->what, problem->why, problem->todo);
}

Vec3f parsePosition(const Field& f, const std::string& what) {
  const Vec3f p = f.asVec3();
  check(f, positionProblem(p, what));
  return p;
}

CameraDesc parseCamera(const Field& f) {
  f.expectObject({"eye", "look_at", "up", "fov_deg", "resolution"});
  CameraDesc c;
  c.eye = parsePosition(f["eye"], "eye");
  c.look_at = parsePosition(f["look_at"], "look_at");
  if (f.has("up")) c.up = f["up"].asVec3();
  if (f.has("fov_deg")) c.fov_deg = f["fov_deg"].asFloat();
  if (!(c.fov_deg >= kMinFovDeg && c.fov_deg <= kMaxFovDeg))
    f["fov_deg"].fail("field of view " + numberText(c.fov_deg) + " out of range",
                      "fov_deg is the vertical angle in degrees, in [" + numberText(kMinFovDeg) +
                          ", " + numberText(kMaxFovDeg) + "]",
                      "40 is a usual value");
  if (f.has("resolution")) {
    const Field r = f["resolution"];
    if (r.arraySize() != 2) r.fail("expected [width, height]");
    c.width = r[size_t(0)].asInt();
    c.height = r[1].asInt();
    if (c.width < 1 || c.height < 1 || c.width > kMaxImageSide || c.height > kMaxImageSide)
      r.fail("width and height must be in [1, " + std::to_string(kMaxImageSide) + "]");
  }
  // Eye and look_at are within kMaxSceneCoordinate, so these lengths are finite.
  const Vec3f view = c.look_at - c.eye;
  if (!(length(view) > 1e-6f))
    f.fail("eye and look_at coincide", "the view direction is look_at - eye",
           "move look_at to the point the camera looks at");
  // In double: a float length of [0, 1e-30, 0] underflows to 0.
  const double up_length =
      std::sqrt(double(c.up.x) * c.up.x + double(c.up.y) * c.up.y + double(c.up.z) * c.up.z);
  // Without "up" the problem is reported at "camera", naming the default.
  const bool has_up = f.has("up");
  const Field up_field = has_up ? f["up"] : f;
  const std::string up_name = has_up ? "up" : "the default up [0, 1, 0]";
  if (!(up_length >= kMinUpLength && up_length <= 1 / kMinUpLength))
    up_field.fail("length " + numberText(up_length) + " out of range",
                  "up must be a direction of length in [" + numberText(kMinUpLength) + ", " +
                      numberText(1 / kMinUpLength) + "]",
                  "e.g. [0, 1, 0] for y up");
  const Vec3f dir = normalize(view), up_dir = c.up / float(up_length);
  if (!(length(cross(dir, up_dir)) > 1e-6f))
    up_field.fail(up_name + " is parallel to the view direction (look_at - eye)",
                  "the image's vertical axis would be undefined",
                  "choose an up vector that is not along the view, e.g. [0, 0, 1] when looking "
                  "along y");
  return c;
}

Vec3f parseRadiance(const Field& f) {
  const Vec3f r = f.asVec3();
  for (int i = 0; i < 3; ++i)
    if (!(r[i] >= 0 && r[i] <= kMaxRadiance))
      f.fail("radiance " + numberText(r[i]) + " out of range",
             "each component must be in [0, " + numberText(kMaxRadiance) +
                 "] so that the renderer's float arithmetic stays finite",
             "express the radiances in a larger unit (their ratios are what matters)");
  return r;
}

AreaLightDesc parseLight(const Field& f) {
  if (!f.value().is_object()) f.fail("expected an object");
  const std::string type = f["type"].asString();
  AreaLightDesc light;
  if (type == "quad") {
    f.expectObject({"type", "corner", "edge_u", "edge_v", "radiance"});
    const Vec3f c = parsePosition(f["corner"], "corner");
    const Vec3f u = f["edge_u"].asVec3(), v = f["edge_v"].asVec3();
    light.triangles.push_back({c, c + u, c + u + v});
    light.triangles.push_back({c, c + u + v, c + v});
  } else if (type == "triangle") {
    f.expectObject({"type", "vertices", "radiance"});
    const Field vs = f["vertices"];
    if (vs.arraySize() != 3) vs.fail("expected 3 vertices");
    light.triangles.push_back({parsePosition(vs[size_t(0)], "vertex"),
                               parsePosition(vs[1], "vertex"), parsePosition(vs[2], "vertex")});
  } else if (type == "triangles") {
    f.expectObject({"type", "triangles", "radiance"});
    const Field ts = f["triangles"];
    for (size_t i = 0, n = ts.arraySize(); i < n; ++i) {
      const Field t = ts[i];
      if (t.arraySize() != 3) t.fail("expected 3 vertices");
      light.triangles.push_back({parsePosition(t[size_t(0)], "vertex"),
                                 parsePosition(t[1], "vertex"), parsePosition(t[2], "vertex")});
    }
    if (light.triangles.empty()) ts.fail("no triangles");
  } else {
    f["type"].fail("unknown light type " + quoteInput(type),
                   "known types: quad, triangle, triangles");
  }
  for (const auto& t : light.triangles) {
    for (const Vec3f& p : t) check(f, positionProblem(p, "light vertex"));  // corner + edges
    const float area = 0.5f * length(cross(t[1] - t[0], t[2] - t[0]));
    if (!(area >= kMinLightArea))
      f.fail("light triangle of area " + numberText(area) + " (below " + numberText(kMinLightArea) +
                 ")",
             "area sampling divides by the area", "make the light larger or remove it");
  }
  light.radiance = parseRadiance(f["radiance"]);
  return light;
}

Affine3f parseMatrix(const Field& f) {
  const std::vector<float> v = f.asFloats();
  if (v.size() != 12 && v.size() != 16) f.fail("expected 12 or 16 numbers (row-major)");
  if (v.size() == 16 && (v[12] != 0 || v[13] != 0 || v[14] != 0 || v[15] != 1))
    f.fail("the last row of a 4x4 transform must be 0 0 0 1", "only affine transforms are allowed");
  Affine3f a;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) a.m[i][j] = v[size_t(i * 4 + j)];
  return a;
}

Affine3f parseTransform(const Field& f) {
  Affine3f a;
  if (f.value().is_array()) {
    a = parseMatrix(f);
  } else {
    f.expectObject({"translate", "rotate", "scale"});
    Affine3f s, r, t;
    if (f.has("scale")) {
      const Field sf = f["scale"];
      if (sf.value().is_number()) {
        const float k = sf.asFloat();
        s = Affine3f::scaling({k, k, k});
      } else {
        s = Affine3f::scaling(sf.asVec3());
      }
    }
    if (f.has("rotate")) {
      const Field rf = f["rotate"];
      const std::vector<float> v = rf.asFloats();
      if (v.size() != 4) rf.fail("expected [axis_x, axis_y, axis_z, degrees]");
      if (!(length(Vec3f(v[0], v[1], v[2])) > 0)) rf.fail("zero rotation axis");
      r = rotation({v[0], v[1], v[2]}, v[3]);
    }
    if (f.has("translate")) t = Affine3f::translation(f["translate"].asVec3());
    a = compose(t, compose(r, s));
  }
  check(f, transformProblem(a));
  return a;
}

ProxyRef parseProxy(const Field& f, const fs::path& dir) {
  f.expectObject({"kind", "method", "file", "class", "sha256"});
  ProxyRef p;
  p.kind = f["kind"].asString();
  if (!parseProxyClass(p.kind))
    f["kind"].fail("unknown kind " + quoteInput(p.kind), "known: outside, inside, general");
  if (f.has("method")) p.method = f["method"].asString();
  p.file = resolveFile(f["file"], dir);
  if (f.has("class")) {
    const std::string c = f["class"].asString();
    p.verified_class = parseProxyClass(c);
    if (!p.verified_class)
      f["class"].fail("unknown class " + quoteInput(c), "known: outside, inside, general");
  }
  if (f.has("sha256")) {
    p.sha256 = f["sha256"].asString();
    const bool hex = p.sha256.size() == 64 &&
                     p.sha256.find_first_not_of("0123456789abcdef") == std::string::npos;
    if (!hex) f["sha256"].fail("expected 64 lowercase hex digits", "as sha256sum prints them");
  }
  return p;
}

SceneMeshDesc parseMesh(const Field& f, const fs::path& dir) {
  f.expectObject({"name", "file", "gltf_mesh", "albedo", "transform", "place", "make_proxy",
                  "proxy_max_faces", "proxies"});
  SceneMeshDesc m;
  m.name = f["name"].asString();
  if (m.name.empty() || m.name.find_first_of(" \t\r\n#") != std::string::npos)
    f["name"].fail("mesh names must be non-empty, without spaces or '#'",
                   "the instance list refers to meshes by name");
  m.file = resolveFile(f["file"], dir);
  if (f.has("gltf_mesh")) {
    m.gltf_mesh = f["gltf_mesh"].asInt();
    if (m.gltf_mesh < 0) f["gltf_mesh"].fail("expected a mesh index >= 0", "meshes[i] of the file");
    if (!isGltfPath(m.file))
      f["gltf_mesh"].fail("gltf_mesh needs a .gltf or .glb file", "it picks one mesh of it");
  }
  if (f.has("albedo")) {
    m.albedo = f["albedo"].asVec3();
    for (int i = 0; i < 3; ++i)
      if (m.albedo[i] < 0 || m.albedo[i] > 1)
        f["albedo"].fail("albedo must be in [0, 1]",
                         "a larger albedo reflects more than it receives");
  }
  if (f.has("transform")) m.transform = parseTransform(f["transform"]);
  if (f.has("place")) m.place = f["place"].asBool();
  if (f.has("make_proxy")) m.make_proxy = f["make_proxy"].asBool();
  if (f.has("proxy_max_faces")) {
    m.proxy_max_faces = f["proxy_max_faces"].asUint32();
    if (*m.proxy_max_faces > kMaxFacesLimit)
      f["proxy_max_faces"].fail("a face budget above 10^9",
                                "proxy-gen's --max-faces allows at most that");
  }
  if (f.has("proxies")) {
    const Field ps = f["proxies"];
    for (size_t i = 0, n = ps.arraySize(); i < n; ++i) m.proxies.push_back(parseProxy(ps[i], dir));
  }
  return m;
}

}  // namespace

std::string SceneDesc::displayName() const {
  return name.empty() ? path.stem().string() : name;
}

int SceneDesc::findMesh(const std::string& name) const {
  for (size_t i = 0; i < meshes.size(); ++i)
    if (meshes[i].name == name) return int(i);
  return -1;
}

SceneDesc loadSceneDesc(const fs::path& path) {
  std::error_code ec;
  const fs::path absolute = fs::absolute(path, ec).lexically_normal();
  if (isGltfPath(absolute)) return sceneFromGltf(absolute);
  SceneDesc scene = parseSceneDesc(readTextFile(absolute), absolute);
  if (!scene.instances_file.empty())
    scene.instances = loadInstanceList(scene.instances_file, scene.meshes);
  return scene;
}

SceneDesc parseSceneDesc(const std::string& text, const fs::path& path) {
  SceneDesc scene;
  std::error_code ec;
  scene.path = fs::absolute(path, ec).lexically_normal();
  json root;
  try {
    root = json::parse(text, nullptr, true, /*ignore_comments=*/true);
  } catch (const json::exception& e) {  // parse_error, or out_of_range for 1e999
    throw Error(scene.path.string(), "invalid JSON", e.what(), "fix the syntax");
  }
  const fs::path dir = scene.path.parent_path();
  const Field top(root, "", scene.path);
  top.expectObject({"name", "description", "camera", "lights", "meshes", "instances"});
  if (top.has("name")) {
    scene.name = top["name"].asString();
    const bool printable = std::all_of(scene.name.begin(), scene.name.end(),
                                       [](unsigned char c) { return c >= 0x20 && c != 0x7f; });
    if (scene.name.empty() || scene.name.size() > kMaxSceneNameLength || !printable)
      top["name"].fail(fmt::format("the name must be 1 to {} printable characters on one line",
                                   kMaxSceneNameLength),
                       "it titles reports and terminal lines");
  }
  if (top.has("description")) scene.description = top["description"].asString();
  scene.camera = parseCamera(top["camera"]);

  const Field lights = top["lights"];
  for (size_t i = 0, n = lights.arraySize(); i < n; ++i)
    scene.lights.push_back(parseLight(lights[i]));
  if (scene.lights.empty())
    lights.fail("no lights", "direct illumination needs at least one light");

  const Field meshes = top["meshes"];
  std::set<std::string> names;
  for (size_t i = 0, n = meshes.arraySize(); i < n; ++i) {
    scene.meshes.push_back(parseMesh(meshes[i], dir));
    if (!names.insert(scene.meshes.back().name).second)
      meshes[i]["name"].fail("duplicate mesh name " + quoteInput(scene.meshes.back().name));
  }
  if (scene.meshes.empty()) meshes.fail("no meshes");

  if (top.has("instances")) {
    const Field inst = top["instances"];
    inst.expectObject({"file"});
    scene.instances_file = resolveFile(inst["file"], dir);
  }
  return scene;
}

}  // namespace proxyvis
