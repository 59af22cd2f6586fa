// The out-of-core renderer's settings: from their flags' text, checked against a scene, and the
// memory they bound (contract in out_of_core_render.h).
#include <fmt/core.h>

#include <algorithm>
#include <optional>

#include "outofcore/out_of_core_render.h"
#include "outofcore/out_of_core_scene.h"
#include "render/integrator_steps.h"
#include "util/app_main.h"
#include "util/error.h"

namespace proxyvis {

const char* outOfCorePolicyName(OutOfCorePolicy p) {
  switch (p) {
    case OutOfCorePolicy::kExactBatched:
      return "exact-batched";
    case OutOfCorePolicy::kProxiesExact:
      return "proxies-exact";
    case OutOfCorePolicy::kProxiesRoulette:
      return "proxies-roulette";
  }
  return "?";
}

OutOfCorePolicy parseOutOfCorePolicy(const std::string& name) {
  for (OutOfCorePolicy p : {OutOfCorePolicy::kExactBatched, OutOfCorePolicy::kProxiesExact,
                            OutOfCorePolicy::kProxiesRoulette})
    if (name == outOfCorePolicyName(p)) return p;
  throw Error("", "--ooc-policy: unknown policy '" + name + "'", {},
              "use exact-batched, proxies-exact or proxies-roulette");
}

void applyLoadQ(const std::string& text, OutOfCoreSettings& settings) {
  settings.learn_q = text == "learned";
  if (settings.learn_q) return;
  const std::optional<double> q = parseNumber(text);
  if (!q || !(*q > 0 && *q <= 1))
    throw Error("", "--load-q " + text + " is not a probability in (0, 1] or 'learned'", {},
                "e.g. --load-q 0.5, or --load-q learned (per mesh, from earlier batches)");
  settings.load_q = *q;
}

std::string loadQText(const OutOfCoreSettings& settings) {
  return settings.learn_q ? "learned" : fmt::format("{:g}", settings.load_q);
}

uint64_t imageBytes(size_t pixels, const OutOfCoreSettings& settings) {
  const size_t own_bits = (size_t(std::max(settings.spp, 0)) + 63) / 64 * sizeof(uint64_t);
  return uint64_t(pixels) * (sizeof(ShadingPoint) + sizeof(SampleSums) + own_bits +
                             4 * sizeof(float) + (settings.learn_q ? sizeof(double) : 0));
}

OutOfCoreMemoryBound outOfCoreMemoryBound(uint64_t budget_bytes, uint64_t proxy_bytes,
                                          uint64_t image_bytes) {
  const double held = double(budget_bytes) + double(proxy_bytes) + double(image_bytes);
  OutOfCoreMemoryBound b;
  b.overhead_bytes = uint64_t(kOverheadShare * held);
  b.bound_bytes = uint64_t(held) + b.overhead_bytes;
  b.queue_cap_bytes = uint64_t(kQueueShare * held);
  return b;
}

void setMemoryBound(OutOfCoreStats& stats, size_t pixels, const OutOfCoreSettings& settings,
                    uint64_t proxy_bytes) {
  stats.image_bytes = imageBytes(pixels, settings);
  stats.proxy_bytes = proxy_bytes;
  const OutOfCoreMemoryBound bound =
      outOfCoreMemoryBound(settings.budget_bytes, proxy_bytes, stats.image_bytes);
  stats.overhead_bytes = bound.overhead_bytes;
  stats.rss_bound_bytes = bound.bound_bytes;
  stats.queue_cap_bytes =
      settings.queue_cap_bytes ? settings.queue_cap_bytes : bound.queue_cap_bytes;
}

void checkOutOfCoreSettings(const OutOfCoreScene& scene, const OutOfCoreSettings& settings) {
  if (settings.spp < 1) throw Error("", "--spp must be at least 1");
  if (settings.tile_size < 1 || settings.batch_passes < 0)
    throw Error("", "tile size must be at least 1 and passes per batch at least 0");
  if (!(settings.load_q > 0 && settings.load_q <= 1))
    throw Error("", fmt::format("--load-q {} is not in (0, 1]", settings.load_q));
  if (settings.policy != OutOfCorePolicy::kExactBatched && !scene.outsideProxies() &&
      !scene.insideProxies())
    throw Error(scene.desc().path.string(),
                fmt::format("--ooc-policy {} needs proxies", outOfCorePolicyName(settings.policy)),
                "no mesh of the scene has an outside or inside proxy with a proved class",
                "generate them with proxy-gen, or use --ooc-policy exact-batched");
  // A budget below one mesh's load could not hold that mesh while it is built and its queue
  // traced: the largest is named, with what it takes.
  size_t largest = 0;
  for (size_t m = 1; m < scene.meshes().size(); ++m)
    if (scene.meshes()[m].load_peak_bytes > scene.meshes()[largest].load_peak_bytes) largest = m;
  const uint64_t need = scene.meshes().empty() ? 0 : scene.meshes()[largest].load_peak_bytes;
  if (need > settings.budget_bytes)
    throw Error(
        "",
        fmt::format("--geometry-budget of {} bytes is smaller than mesh '{}' alone",
                    settings.budget_bytes, scene.desc().meshes[largest].name),
        fmt::format("its built scene takes {} bytes and {} while it is read and built; a mesh "
                    "is loaded whole",
                    scene.meshes()[largest].built_bytes, need),
        fmt::format("give at least {} bytes ({:.1f} MiB)", need, double(need) / double(1 << 20)));
}

}  // namespace proxyvis
