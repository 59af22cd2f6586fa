#pragma once
// The converged reference: `exact` at many samples, as the mean of independent partial renders
// (so its own error can be estimated from their spread), cached in the output directory under a
// key of the scene's content hash and the resolution; a cached reference with at least the
// samples asked for is reused.
#include <filesystem>
#include <string>

#include "compare_options.h"
#include "render/image_io.h"
#include "render/render_scene.h"
#include "render/renderer.h"

namespace proxyvis {

struct Reference {
  Image radiance;
  int spp = 0;       // total samples per pixel
  int partials = 0;  // independent renders averaged
  // Mean over pixels and channels of the estimated variance of the reference's mean: its own
  // expected MSE against the true image.
  double variance_of_mean = 0;
  double seconds = 0;  // render time (of the run that produced the cache)
  bool cached = false;
  std::string key;
  std::filesystem::path file;  // the EXR
};

// The cache is looked up in options.out (the previous report folder) and the reference is
// written to `write_dir` (the report folder being staged), copied there when it came from the
// cache, so that the new folder keeps it.
Reference loadOrRenderReference(const RenderScene& scene, const CompareOptions& options, int spp,
                                const std::filesystem::path& write_dir);

// The reference's image metadata (render/image_metadata.h); `content` says what the file shows.
std::vector<ImageAttribute> referenceAttributes(const SceneDesc& scene, const Reference& ref,
                                                const std::string& content);

}  // namespace proxyvis
