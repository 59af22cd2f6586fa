#pragma once
// The steps of render() (RenderSession) that only the single-process renderer takes: settings
// checks, learning regions and pass budgets. The steps it shares with the data-parallel renderer
// are public (render/integrator_steps.h), and so is every pixel's shading point
// (render/shading_points.h), which bench/ecosys draws its segments from.
#include <vector>

#include "render/integrator_steps.h"
#include "render/render_scene.h"
#include "render/renderer.h"
#include "render/shading_points.h"

namespace proxyvis::detail {

// The shared steps under their former names here (benches and tests name them detail::).
using proxyvis::makeSegment;
using proxyvis::PreparedSample;
using proxyvis::prepareSamples;
using proxyvis::primaryRay;
using proxyvis::ShadingPoint;
using proxyvis::shadingPointOf;
using proxyvis::shadingPoints;
using proxyvis::Tiling;

// The learning region of a query: screen tile x light x whether the shading point's own object
// uses a proxy. Points on such an object trace their own original in both V and V' (the
// self-shadowing rule), so their proxy rays cost more and they must not share a cost model with
// the points beside them (the ground under the dragon).
inline uint32_t learningRegion(const RenderScene& scene, uint32_t object, uint32_t tile,
                               uint32_t light) {
  const uint32_t self = scene.objects()[object].proxy >= 0 ? 1u : 0u;
  return (tile * uint32_t(scene.lights().numLights()) + light) * 2u + self;
}

// Throws Error for settings no render can run with (tile size, nothing to render, budget).
void validateRenderSettings(const RenderSettings& settings);

// Under a time budget, the samples per pixel of the next pass when passes hold several (estimators
// with probes): the first pass is whole (nothing is measured yet; a smaller one would pay the
// probes for fewer samples); later ones take as many samples as the time left allows at the last
// pass's rate, so that the render does not overshoot its budget by a whole pass. A pass costs
// about (2 x probes + samples) ray units: probes are drawn per pixel and pass, traced against
// proxy and original. 0 = stop (even one sample would overshoot by more than half its own time).
int passSamplesWithinBudget(double seconds_left, int full_pass, int pass, double last_seconds,
                            int last_count, int probes);

}  // namespace proxyvis::detail
