// libFuzzer target: the scene JSON parse-and-validate stage (parseSceneDesc) on arbitrary text.
// Whatever it accepts must keep the loader's promises: every number the renderer uses within the
// ranges of scene_desc.h, every transform invertible, names unique.
// fuzz-libraries: pv_scene pv_util
#include <cmath>
#include <optional>
#include <set>

#include "fuzz_scene_checks.h"
#include "fuzz_scene_files.h"
#include "fuzz_support.h"
#include "scene/scene_desc.h"
#include "scene/transform.h"

namespace proxyvis::fuzz {
namespace {

void checkScene(const SceneDesc& s) {
  const CameraDesc& c = s.camera;
  checkPosition(c.eye, "camera eye");
  checkPosition(c.look_at, "camera look_at");
  if (!isFinite(c.up) || !(length(c.look_at - c.eye) > 0)) finding("accepted a degenerate camera");
  if (!(c.fov_deg >= kMinFovDeg && c.fov_deg <= kMaxFovDeg))
    finding("accepted a field of view out of range");
  if (c.width < 1 || c.height < 1 || c.width > kMaxImageSide || c.height > kMaxImageSide)
    finding("accepted a resolution out of range");
  if (s.lights.empty()) finding("accepted a scene without lights");
  for (const AreaLightDesc& l : s.lights) {
    for (int i = 0; i < 3; ++i)
      if (!(l.radiance[i] >= 0 && l.radiance[i] <= kMaxRadiance))
        finding("accepted a radiance out of range");
    if (l.triangles.empty()) finding("accepted a light without triangles");
    for (const auto& t : l.triangles) {
      for (const Vec3f& p : t) checkPosition(p, "light vertex");
      if (!(0.5f * length(cross(t[1] - t[0], t[2] - t[0])) >= kMinLightArea))
        finding("accepted a light triangle below the minimum area");
    }
  }
  if (s.meshes.empty()) finding("accepted a scene without meshes");
  std::set<std::string> names;
  for (const SceneMeshDesc& m : s.meshes) {
    if (!names.insert(m.name).second) finding("accepted a duplicate mesh name");
    for (int i = 0; i < 3; ++i)
      if (!(m.albedo[i] >= 0 && m.albedo[i] <= 1)) finding("accepted an albedo out of [0, 1]");
    checkTransform(m.transform);
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
