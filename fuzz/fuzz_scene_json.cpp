// libFuzzer target: the scene JSON parse-and-validate stage (parseSceneDesc) on arbitrary text.
// Whatever it accepts must keep the loader's promises: every number the renderer uses is finite
// and within the documented ranges, every transform invertible, names unique.
// fuzz-libraries: pv_scene pv_util
#include <cmath>
#include <set>

#include "fuzz_scene_files.h"
#include "fuzz_support.h"
#include "scene/scene_desc.h"
#include "scene/transform.h"

namespace proxyvis::fuzz {
namespace {

void checkFinite(const Vec3f& v, const char* what) {
  if (!isFinite(v)) finding(std::string("accepted a non-finite ") + what);
}

void checkScene(const SceneDesc& s) {
  const CameraDesc& c = s.camera;
  checkFinite(c.eye, "camera eye");
  checkFinite(c.look_at, "camera look_at");
  checkFinite(c.up, "camera up");
  if (!(c.fov_deg > 0 && c.fov_deg < 180)) finding("accepted a field of view out of (0, 180)");
  if (c.width < 1 || c.height < 1 || c.width > kMaxImageSide || c.height > kMaxImageSide)
    finding("accepted a resolution out of range");
  if (s.lights.empty()) finding("accepted a scene without lights");
  for (const AreaLightDesc& l : s.lights) {
    checkFinite(l.radiance, "radiance");
    if (l.radiance.x < 0 || l.radiance.y < 0 || l.radiance.z < 0)
      finding("accepted a negative radiance");
    if (l.triangles.empty()) finding("accepted a light without triangles");
    for (const auto& t : l.triangles)
      for (const Vec3f& p : t) checkFinite(p, "light vertex");
  }
  if (s.meshes.empty()) finding("accepted a scene without meshes");
  std::set<std::string> names;
  for (const SceneMeshDesc& m : s.meshes) {
    if (!names.insert(m.name).second) finding("accepted a duplicate mesh name");
    checkFinite(m.albedo, "albedo");
    for (int i = 0; i < 3; ++i)
      if (m.albedo[i] < 0 || m.albedo[i] > 1) finding("accepted an albedo out of [0, 1]");
    for (const auto& row : m.transform.m)
      for (float x : row)
        if (!std::isfinite(x)) finding("accepted a non-finite transform");
    if (!inverse(m.transform)) finding("accepted a singular transform");
  }
}

}  // namespace
}  // namespace proxyvis::fuzz

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace proxyvis;
  static const std::filesystem::path scene_file = fuzz::sceneFolder() / "scene.json";
  fuzz::parsedOrRefused(
      [&] { fuzz::checkScene(parseSceneDesc(fuzz::bytesOf(data, size), scene_file)); });
  return 0;
}
