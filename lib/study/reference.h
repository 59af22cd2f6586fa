#pragma once
// The converged reference: `exact` at many samples, as the mean of independent partial renders
// (so its own error can be estimated from their spread), cached in the output directory under a
// key of the scene's content hash and the resolution; a cached reference with at least the
// samples asked for is reused. Its partial renders are work units of the study (plan.h).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "image/image_io.h"
#include "metrics/image_variance.h"
#include "render/renderer.h"
#include "scene/scene_desc.h"

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

// Partial renders averaged into the reference: enough for a stable variance estimate (the
// relative s.e. of s² is sqrt(2/(R−1)) per pixel, far less once averaged over the image).
inline constexpr int kReferencePartials = 16;

// The cache key of a reference of `desc` traced flattened or instanced.
std::string referenceKey(const SceneDesc& desc, bool flattened);

// An earlier run's reference of at least `min_spp` samples, looked up in `out` (the previous
// report folder) and copied to `write_dir` (the report folder being staged) so that the new
// folder keeps it; nullopt when there is none (a damaged one is never trusted).
std::optional<Reference> loadCachedReference(const SceneDesc& desc, bool flattened,
                                             const std::filesystem::path& out, int min_spp,
                                             const std::filesystem::path& write_dir);

// The settings of partial render `partial` of `per_partial` samples (its seed does not depend on
// --seed, so one cached reference serves every seed).
RenderSettings referencePartialSettings(int partial, int per_partial);

// The reference as the mean of its partial renders (added to `partials` in partial order, each
// dropped once added), written to `write_dir` (EXR and its settings as JSON). `seconds` is the
// partials' summed render time.
Reference finishReference(const SceneDesc& desc, bool flattened,
                          const ImageVarianceAccumulator& partials, int per_partial, double seconds,
                          const std::filesystem::path& write_dir);
// The reference's image metadata (render/image_metadata.h); `content` says what the file shows.
std::vector<ImageAttribute> referenceAttributes(const SceneDesc& scene, const Reference& ref,
                                                const std::string& content);

}  // namespace proxyvis
