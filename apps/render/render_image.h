#pragma once
// What `render` writes: the image (EXR: linear RGB plus the AOV layers; PNG: tone-mapped RGB),
// each with the render's metadata, and the run's JSON summary.
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "image/image_io.h"
#include "render/renderer.h"
#include "scene/scene_desc.h"

namespace proxyvis {

// The image file formats `render` writes, by extension: ".exr" or ".png" (any case).
enum class RenderImageFormat { kExr, kPng };
// Throws Error naming `path` for any other extension.
RenderImageFormat renderImageFormat(const std::filesystem::path& path);

// The EXR's pixels: R, G, B then the AOV layers (render/image_metadata.h), 32-bit float.
Image exrWithAovs(const RenderResult& result);
// The channel names of exrWithAovs().
std::vector<std::string> exrWithAovsChannelNames();

// What `render` writes and how: for EXR, exr() with 32-bit float channels named `channels`; for
// PNG, the radiance tone-mapped at its automatic exposure (recorded as proxyvis:exposure). Both
// carry `attributes`.
struct RenderImageFile {
  Image image;
  ImageWriteOptions write;
};
RenderImageFile renderImageFile(RenderImageFormat format, const Image& radiance,
                                const std::function<Image()>& exr,
                                std::vector<std::string> channels,
                                std::vector<ImageAttribute> attributes);

struct RenderRun {
  std::string estimator;
  uint64_t seed = 0;       // --seed
  double time_budget = 0;  // --time (0 = none)
  int threads = 0;
  std::string scene_build;         // "flat" or "instanced" (RenderScene::buildChoice())
  std::string scene_build_reason;  // why
};

// The --json summary: what was rendered, how long it took, how many rays it traced.
nlohmann::json renderSummary(const SceneDesc& scene, const RenderRun& run,
                             const RenderResult& result, const std::filesystem::path& output);

}  // namespace proxyvis
