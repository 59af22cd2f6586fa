#pragma once
// The measurement behind the oracle ceiling (estimate/ceiling.h): the renderer's own shadow
// segments, one light sample per pixel per pass, each traced against the proxies (with the
// self-shadowing rule of render/scene_tracer.h) and against the originals, every ray timed with
// the CPU's tick counter. Counts, errors and MSE-weighted variances are collected per learning
// region of the renderer (renderer.h: screen tile x light x self).
#include <nlohmann/json_fwd.hpp>
#include <vector>

#include "estimate/ceiling.h"
#include "render/renderer.h"

namespace proxyvis {

struct CeilingMeasurement {
  std::vector<CeilingRegionStats> regions;  // index = the renderer's learning region
  uint32_t num_lights = 1;
  int passes = 0;           // passes traced (each one light sample per pixel)
  double seconds = 0;       // wall time of the measurement
  double ticks_per_ns = 1;  // the tick counter's rate, calibrated over the measurement
  // Process CPU seconds per wall second while tracing: the cores this process actually got
  // (below the thread count on a shared machine, where wall time x threads overstates CPU time).
  double cpu_per_wall = 1;
  uint64_t segments = 0;  // shadow segments traced (each against proxy and original)

  bool operator==(const CeilingMeasurement&) const = default;
};

// The measurement in a unit result's header (lib/study), every number exactly: "num_lights",
// "passes", "measurement_seconds", "ticks_per_ns", "cpu_per_wall", "segments" and "regions", one
// array of 13 numbers per region in CeilingRegionStats' order (a 512x512 image has 2 k regions
// per light).
void to_json(nlohmann::json& j, const CeilingMeasurement& m);
void from_json(const nlohmann::json& j, CeilingMeasurement& m);

// Traces passes 0, 1, ... of settings.seed (settings.tile_size sets the regions) until
// max_passes, or earlier once max_seconds are spent and at least 2 passes are done (a pixel's
// variance needs two samples). The segments are those render() draws for that seed; the counts
// are deterministic, the costs are timings. Ray costs are in ns. Parallel over tiles.
CeilingMeasurement measureCeilingStats(const RenderScene& scene, const RenderSettings& settings,
                                       int max_passes, double max_seconds);

// c_s in ns per shadow segment (the unit of the measured ray costs), from exact renders of the
// same scene (at least one): their shading time (primary rays, light sampling) priced at what
// their visibility time bought, c_s = c_o x shading_seconds / visibility_seconds, with c_o the
// measured mean original-ray cost. A ratio of two phases of the same renders, it holds on a
// loaded machine where wall time x threads would not be CPU time. The visibility phase is taken
// as its rays alone, so its accumulation is not in c_s (c_s a little low, the ceiling a little
// high).
double shadingNsPerSegment(const std::vector<const RenderResult*>& exact_renders,
                           const CeilingMeasurement& m);

// The ceiling's input from a measurement, the scene's verified proxy class and c_s.
CeilingInput ceilingInput(const RenderScene& scene, const CeilingMeasurement& m,
                          double per_sample_ns, double q_min);

}  // namespace proxyvis
