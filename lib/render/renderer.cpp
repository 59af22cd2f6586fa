// render() runs a RenderSession (render_session.cpp holds the pass loop) to its end;
// passSegments() draws one pass's light samples the same way for benches and tests.
#include "render/renderer.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "render/internal/integrator.h"
#include "render/render_scene.h"
#include "render/render_session.h"
#include "util/error.h"

namespace proxyvis {

using namespace detail;

namespace detail {

void validateRenderSettings(const RenderSettings& s) {
  if (s.tile_size < 1 || s.tile_size > 4096)
    throw Error("", "tile size must be in [1, 4096]", "got " + std::to_string(s.tile_size));
  if (s.spp <= 0 && !(s.time_budget > 0))
    throw Error("", "nothing to render", "spp must be positive unless a time budget is given");
  if (s.time_budget < 0 || !std::isfinite(s.time_budget))
    throw Error("", "time budget must be a finite number of seconds >= 0");
  if (s.samples_per_pass < 0) throw Error("", "samples per pass must be >= 0");
}

int passSamplesWithinBudget(double seconds_left, int full_pass, int pass, double last_seconds,
                            int last_count, int probes) {
  if (pass == 0) return full_pass;  // nothing measured yet
  const double fixed_units = 2.0 * probes;
  const double unit_seconds = last_seconds / (fixed_units + last_count);
  if (!(unit_seconds > 0)) return full_pass;
  const double fit = seconds_left / unit_seconds - fixed_units;
  if (fit >= full_pass) return full_pass;
  if (fit >= 1) return int(fit);
  const double one_sample_seconds = unit_seconds * (fixed_units + 1);
  return seconds_left >= 0.5 * one_sample_seconds ? 1 : 0;
}

}  // namespace detail

EstimatorSetup estimatorSetupFor(const RenderScene& scene, const RenderSettings& settings) {
  EstimatorSetup setup = settings.estimator;
  const detail::Tiling tiling(scene.camera().width(), scene.camera().height(),
                              std::max(1, settings.tile_size));
  setup.num_regions = uint32_t(tiling.count()) * uint32_t(scene.lights().numLights()) * 2u;
  setup.num_points = uint32_t(scene.camera().width()) * uint32_t(scene.camera().height()) *
                     uint32_t(scene.lights().numLights());
  setup.proxy_class = settings.force_general_proxies ? ProxyClass::kGeneral : scene.proxyClass();
  return setup;
}

RenderResult render(const RenderScene& scene, const RenderSettings& settings) {
  const auto estimator = makeEstimator(estimatorSetupFor(scene, settings));
  return render(scene, settings, *estimator);
}

RenderResult render(const RenderScene& scene, const RenderSettings& settings,
                    VisibilityEstimator& estimator) {
  RenderSession session(scene, settings, estimator);
  session.runToEnd();
  return session.result();
}

PassSegments passSegments(const RenderScene& scene, const RenderSettings& settings, int pass) {
  validateRenderSettings(settings);
  const int w = scene.camera().width(), h = scene.camera().height();
  const Tiling tiling(w, h, settings.tile_size);
  const int batch = settings.samples_per_pass > 0 ? settings.samples_per_pass : 1;
  const std::vector<ShadingPoint> points = shadingPoints(scene, tiling);
  std::vector<PreparedSample> samples(points.size() * size_t(batch));
  tbb::parallel_for(size_t(0), points.size(), [&](size_t pixel) {
    prepareSamples(scene, points[pixel], settings.seed, uint32_t(pixel), pass, batch,
                   &samples[pixel * batch]);
  });
  PassSegments out;
  for (size_t i = 0; i < samples.size(); ++i) {
    const Vec3f& wt = samples[i].weight;
    if (!(wt.x > 0 || wt.y > 0 || wt.z > 0)) continue;
    out.segments.push_back(samples[i].segment);
    out.pixels.push_back(uint32_t(i / size_t(batch)));
    out.objects.push_back(points[i / size_t(batch)].object);
  }
  return out;
}

}  // namespace proxyvis
