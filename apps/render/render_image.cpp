#include "render_image.h"

#include <algorithm>
#include <cctype>

#include "render/image_metadata.h"
#include "util/build_info.h"
#include "util/error.h"
#include "util/lower_case.h"

namespace proxyvis {

RenderImageFormat renderImageFormat(const std::filesystem::path& path) {
  const std::string ext = lowerExtension(path);
  if (ext == ".exr") return RenderImageFormat::kExr;
  if (ext == ".png") return RenderImageFormat::kPng;
  throw Error(path.string(), "unsupported image format '" + ext + "'",
              "-o writes OpenEXR (linear, with AOV layers) or PNG (tone-mapped)",
              "name the output *.exr or *.png");
}

std::vector<std::string> exrWithAovsChannelNames() {
  std::vector<std::string> names = {"R", "G", "B"};
  names.insert(names.end(), kAovChannelNames.begin(), kAovChannelNames.end());
  return names;
}

Image exrWithAovs(const RenderResult& result) {
  const Image aov = aovImage(result);
  const size_t n = size_t(result.radiance.width) * result.radiance.height;
  const int channels = 3 + aov.channels;
  Image out{result.radiance.width, result.radiance.height, channels,
            std::vector<float>(n * size_t(channels))};
  for (size_t i = 0; i < n; ++i) {
    float* px = &out.pixels[i * size_t(channels)];
    std::copy_n(&result.radiance.pixels[i * 3], 3, px);
    std::copy_n(&aov.pixels[i * size_t(aov.channels)], aov.channels, px + 3);
  }
  return out;
}

RenderImageFile renderImageFile(RenderImageFormat format, const Image& radiance,
                                const std::function<Image()>& exr,
                                std::vector<std::string> channels,
                                std::vector<ImageAttribute> attributes) {
  RenderImageFile f;
  f.write.attributes = std::move(attributes);
  if (format == RenderImageFormat::kExr) {
    f.image = exr();
    f.write.full_float = true;
    f.write.channel_names = std::move(channels);
  } else {
    f.image = radiance;
    f.write.exposure = autoExposure(radiance);
    f.write.attributes.push_back({"proxyvis:exposure", f.write.exposure});
  }
  return f;
}

nlohmann::json renderSummary(const SceneDesc& scene, const RenderRun& run, const RenderResult& r,
                             const std::filesystem::path& output) {
  return {{"program", "render"},
          {"scene", scene.path.string()},
          {"scene_name", scene.displayName()},
          {"output", output.string()},
          {"estimator", run.estimator},
          {"spp", r.spp},
          {"passes", r.passes},
          {"seconds", r.seconds},
          {"time_budget", run.time_budget > 0 ? nlohmann::json(run.time_budget) : nullptr},
          {"seed", run.seed},
          {"threads", run.threads},
          {"width", r.radiance.width},
          {"height", r.radiance.height},
          {"proxy_class", proxyClassName(r.proxy_class)},
          {"rays",
           {{"primary", r.primary_rays},
            {"proxy", r.rays.proxy},
            {"original", r.rays.original},
            {"probe", r.rays.probe}}},
          {"shading_seconds", r.shading_seconds},
          {"visibility_seconds", r.visibility_seconds},
          {"scene_build", run.scene_build},
          {"scene_build_reason", run.scene_build_reason},
          {"build", buildText()},
          {"version", versionText()}};
}

}  // namespace proxyvis
