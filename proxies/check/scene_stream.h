#pragma once
// proxy-check --distribution scene on many meshes at once: the scene distribution's world draws
// (a primary ray into the whole scene each, the expensive part) are made once per index and shared
// by every mesh, instead of once per mesh. Each mesh takes from draw i what segmentForMesh gives,
// so its counts are exactly those classifySegments gives with that mesh's own generator.
#include <vector>

#include "proxies/check/ray_classify.h"
#include "proxies/check/scene_segments.h"

namespace proxyvis {

struct StreamTarget {
  const TraceScene* original = nullptr;  // in the space segmentForMesh maps into
  const TraceScene* proxy = nullptr;
  const MeshPlacements* placements = nullptr;
};

// One Classification per target, each with options.segments classified segments (the lowest
// indices that give one) or, after max(options.max_attempts, options.segments) indices, what it
// has. The same at any thread count and batch size.
std::vector<Classification> classifySceneStream(const WorldSegmentSource& world,
                                                const std::vector<StreamTarget>& targets,
                                                const ClassifyOptions& options);

}  // namespace proxyvis
