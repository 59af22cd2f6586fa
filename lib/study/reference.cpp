#include "study/reference.h"

#include <fmt/format.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "image/image_io.h"
#include "metrics/image_variance.h"
#include "render/image_metadata.h"
#include "study/runs.h"
#include "util/atomic_write.h"
#include "util/error.h"
#include "util/fnv1a.h"
#include "util/input_file.h"
#include "util/json_field.h"
#include "util/rng.h"

namespace proxyvis {

namespace fs = std::filesystem;

namespace {

// Reference seeds do not depend on --seed, so one cached reference serves every seed.
constexpr uint64_t kReferenceSeed = 0x7265666572656e63ULL;  // "referenc"
// Bump when the reference's meaning changes (renderer conventions, partial scheme).
constexpr int kCacheVersion = 1;

bool loadCached(Reference& ref, const fs::path& json_file, int width, int height, int min_spp) {
  std::error_code ec;
  if (!fs::exists(ref.file, ec) || !fs::exists(json_file, ec)) return false;
  try {
    const nlohmann::json j = nlohmann::json::parse(readTextFile(json_file));
    const JsonField f(j, "", json_file);
    Image image = readImage(ref.file);
    if (f["key"].asString() != ref.key || f["spp"].asInt() < min_spp || image.width != width ||
        image.height != height || image.channels < 3)
      return false;
    for (float v : image.pixels)
      if (!std::isfinite(v)) return false;
    if (image.channels != 3) {  // keep RGB only
      Image rgb{width, height, 3, std::vector<float>(size_t(width) * height * 3)};
      for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
          for (int c = 0; c < 3; ++c) rgb.at(x, y, c) = image.at(x, y, c);
      image = std::move(rgb);
    }
    ref.radiance = std::move(image);
    ref.spp = f["spp"].asInt();
    ref.partials = f["partials"].asInt();
    ref.variance_of_mean = f["variance_of_mean"].asDouble();
    ref.seconds = f["seconds"].asDouble();
    ref.cached = true;
    return true;
  } catch (const std::exception&) {
    return false;  // a damaged cache is re-rendered, never trusted
  }
}

}  // namespace

// The build is part of the key: flattened and instanced tracing round differently, and a
// reference of one build would show the other's renders a small bias.
std::string referenceKey(const SceneDesc& desc, bool flattened) {
  std::string text =
      fmt::format("v{}|{}|{}x{}|{}{}", kCacheVersion, sceneHash(desc), desc.camera.width,
                  desc.camera.height, kReferencePartials, flattened ? "|flat" : "");
  return fmt::format("{:016x}", fnv1a(text));
}

std::vector<ImageAttribute> referenceAttributes(const SceneDesc& scene, const Reference& ref,
                                                const std::string& content) {
  // The seed of the first partial render; partial r uses hashKeys(seed, r).
  RenderMetadata meta{
      "render-compare", estimatorName(EstimatorKind::kExact),
      ref.spp,          ref.seconds,
      kReferenceSeed,   {{"proxyvis:content", content}, {"proxyvis:partials", ref.partials}}};
  return renderAttributes(scene, meta);
}

std::optional<Reference> loadCachedReference(const SceneDesc& desc, bool flattened,
                                             const fs::path& out, int min_spp,
                                             const fs::path& write_dir) {
  Reference ref;
  ref.key = referenceKey(desc, flattened);
  const std::string exr_name = "reference-" + ref.key + ".exr";
  const std::string json_name = "reference-" + ref.key + ".json";
  ref.file = out / exr_name;
  if (!loadCached(ref, out / json_name, desc.camera.width, desc.camera.height, min_spp))
    return std::nullopt;
  ref.file = write_dir / exr_name;
  for (const std::string& name : {exr_name, json_name}) {
    std::error_code ec;
    fs::copy_file(out / name, write_dir / name, fs::copy_options::overwrite_existing, ec);
    if (ec)
      throw WriteError((write_dir / name).string(), "cannot copy the cached reference",
                       ec.message());
  }
  return ref;
}

RenderSettings referencePartialSettings(int partial, int per_partial) {
  RenderSettings settings;
  settings.estimator.kind = EstimatorKind::kExact;
  settings.spp = per_partial;
  settings.seed = hashKeys(kReferenceSeed, uint64_t(partial));
  settings.quiet = true;
  return settings;
}

Reference finishReference(const SceneDesc& desc, bool flattened,
                          const ImageVarianceAccumulator& acc, int per_partial, double seconds,
                          const fs::path& write_dir) {
  Reference ref;
  ref.key = referenceKey(desc, flattened);
  ref.partials = acc.count();
  ref.spp = per_partial * ref.partials;
  ref.file = write_dir / ("reference-" + ref.key + ".exr");
  const fs::path json_file = write_dir / ("reference-" + ref.key + ".json");
  ref.seconds = seconds;
  ref.variance_of_mean = acc.meanVarianceOfMean();
  ref.radiance = Image{desc.camera.width, desc.camera.height, 3, acc.mean()};
  requireFinitePixels(ref.radiance, desc.path, "the exact reference");

  ImageWriteOptions exr;
  exr.full_float = true;
  exr.attributes = referenceAttributes(desc, ref, "radiance (linear RGB), the exact reference");
  writeImage(ref.radiance, ref.file, exr);
  nlohmann::json j = {{"key", ref.key},
                      {"scene", desc.path.string()},
                      {"scene_hash", sceneHash(desc)},
                      {"width", desc.camera.width},
                      {"height", desc.camera.height},
                      {"spp", ref.spp},
                      {"partials", ref.partials},
                      {"variance_of_mean", ref.variance_of_mean},
                      {"seconds", ref.seconds}};
  writeTextAtomically(json_file, j.dump(2) + "\n");
  return ref;
}

}  // namespace proxyvis
