#pragma once
// Which rank owns which object: spatial domains balanced by weight (recursive bisection of the
// objects' centres along the longest axis, the way a k-d tree splits, with the rank count split
// in two at each level so that any count works, 3 included). Pure: no MPI, no files.
#include <cstdint>
#include <vector>

#include "util/vec3.h"

namespace proxyvis {

struct PartitionItem {
  Bounds3f bounds;    // world box (any box that locates the object; only its centre is used)
  double weight = 1;  // work and memory the object brings (its original's bytes or triangles)
};

// owner[i] in [0, ranks) for every item. Deterministic: ties in position are broken by index.
// Each rank's summed weight is as close to total / ranks as whole items allow.
std::vector<int> partitionByDomains(const std::vector<PartitionItem>& items, int ranks);

}  // namespace proxyvis
