#pragma once
// Every pixel's shading point: one primary ray per pixel (primaryRay), traced against the scene's
// originals. The single-process renderer's first step, and what a bench that draws the renderer's
// own shadow segments starts from (bench/ecosys).
#include <vector>

#include "render/integrator_steps.h"
#include "render/render_scene.h"

namespace proxyvis {

// One ShadingPoint per pixel of `tiling` (invalid where the ray misses). Parallel over tiles.
std::vector<ShadingPoint> shadingPoints(const RenderScene& scene, const Tiling& tiling);

}  // namespace proxyvis
