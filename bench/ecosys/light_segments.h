#pragma once
// Shadow segments for the ecosys ceiling bench, drawn per light: the renderer picks a light per
// sample (by area today, which gives the small sun almost no samples), so the bench instead draws,
// for every shading point and pass, one sample on EACH light. Statistics per light then have the
// same number of segments whatever the light selection, and any selection rule can be applied
// afterwards as light weights (ceiling_table.h).
#include <cstdint>
#include <vector>

#include "render/render_scene.h"
#include "util/segment.h"

namespace proxyvis::ecosys {

struct LightSegment {
  Segment segment;
  uint32_t object = 0;  // RenderObject index of the shading point
  uint32_t pixel = 0;   // y * width + x
  uint32_t light = 0;   // index into SceneDesc::lights
};

// Pass `pass` of the segments: the renderer's shading points (primary hits, jittered per pixel),
// one sample on each light per point, back-facing samples dropped. Deterministic in (seed, pass).
std::vector<LightSegment> lightSegments(const RenderScene& scene, uint64_t seed, int pass);

}  // namespace proxyvis::ecosys
