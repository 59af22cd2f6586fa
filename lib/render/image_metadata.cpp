#include "render/image_metadata.h"

#include <fmt/format.h>

#include "util/build_info.h"

namespace proxyvis {

namespace {

std::string vecText(const Vec3f& v) {
  return fmt::format("[{:g}, {:g}, {:g}]", v.x, v.y, v.z);
}

}  // namespace

const std::vector<std::string> kAovChannelNames = {"visibility.Y", "rays.proxy", "rays.original",
                                                   "rays.probe"};

Image aovImage(const RenderResult& r) {
  const size_t n = size_t(r.radiance.width) * r.radiance.height;
  Image aov{r.radiance.width, r.radiance.height, 4, std::vector<float>(n * 4)};
  for (size_t i = 0; i < n; ++i) {
    aov.pixels[i * 4] = r.visibility.pixels[i];
    for (int c = 0; c < 3; ++c) aov.pixels[i * 4 + 1 + c] = r.cost.pixels[i * 3 + c];
  }
  return aov;
}

std::string cameraText(const SceneDesc& scene) {
  const CameraDesc& c = scene.camera;
  return fmt::format("eye {} look_at {} up {} fov_deg {:g} resolution {}x{}", vecText(c.eye),
                     vecText(c.look_at), vecText(c.up), c.fov_deg, c.width, c.height);
}

std::vector<ImageAttribute> renderAttributes(const SceneDesc& scene, const RenderMetadata& m) {
  std::vector<ImageAttribute> a = {
      {"Software", fmt::format("proxyvis {} {}", versionText(), m.program)},
      {"proxyvis:estimator", m.estimator},
      {"proxyvis:spp", m.spp},
      {"proxyvis:seconds", float(m.seconds)},
      {"proxyvis:seed", std::to_string(m.seed)},
      {"proxyvis:scene", scene.path.string()},
      {"proxyvis:scene_name", scene.displayName()},
      {"proxyvis:camera", cameraText(scene)},
      {"proxyvis:build", buildText()},
      {"proxyvis:version", versionText()}};
  a.insert(a.end(), m.extra.begin(), m.extra.end());
  return a;
}

}  // namespace proxyvis
