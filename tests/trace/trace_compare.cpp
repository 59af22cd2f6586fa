#include "trace_compare.h"

#include <tbb/parallel_for.h>

#include "test_meshes.h"

namespace proxyvis::test {

OcclusionAgreement compareOcclusion(const TraceScene& scene, const BruteForceMesh& reference,
                                    const std::vector<Segment>& segs, double eps) {
  std::vector<uint8_t> embree(segs.size()), brute(segs.size());
  scene.occluded(segs, embree);
  tbb::parallel_for(size_t(0), segs.size(),
                    [&](size_t i) { brute[i] = reference.occluded(segs[i]) ? 1 : 0; });
  OcclusionAgreement a;
  a.segments = segs.size();
  for (size_t i = 0; i < segs.size(); ++i) {
    a.occluded += brute[i];
    if (embree[i] == brute[i]) continue;
    ++a.disagreements;
    if (!reference.nearBoundary(segs[i], eps)) {
      ++a.unexplained;
      a.unexplained_indices.push_back(i);
    }
  }
  return a;
}

std::vector<Segment> randomSegments(const Bounds3f& box, uint64_t seed, size_t n) {
  std::vector<Segment> segs(n);
  tbb::parallel_for(size_t(0), n, [&](size_t i) { segs[i] = randomSegment(box, seed, i); });
  return segs;
}

}  // namespace proxyvis::test
