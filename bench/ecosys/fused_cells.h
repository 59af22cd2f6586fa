#pragma once
// One Embree top-level scene per terrain cell for the fused variant of the cluster proxies: the
// cell's V' scene (terrain, the other cells' proxies, the originals of its own cell and of cells
// without a proxy) as instances of leaf BVHs built ONCE and shared by every cell, so that V' is
// a single traversal with nothing to ignore, and the cells do not each carry a copy of the
// terrain (copies would also spoil the cache between neighbouring pixels). The project's
// TraceSceneBuilder builds a prototype per builder; sharing leaves across top-level scenes needs
// raw Embree instancing of TraceScene::handle(), done here.
#include <memory>
#include <vector>

#include "mesh/tri_mesh.h"
#include "trace/trace_scene.h"
#include "util/affine3.h"
#include "util/segment.h"

struct RTCSceneTy;

namespace proxyvis::ecosys {

class FusedCellScenes {
 public:
  struct Placement {
    uint32_t leaf;  // index returned by addLeaf
    Affine3f to_world;
  };
  explicit FusedCellScenes(TraceDevice& device) : device_(device) {}
  ~FusedCellScenes();
  FusedCellScenes(const FusedCellScenes&) = delete;
  FusedCellScenes& operator=(const FusedCellScenes&) = delete;

  // A shared leaf BVH (object space).
  uint32_t addLeaf(const TriMesh& mesh);
  // Builds top-level scene `cell` from these placements of leaves (grows the table as needed).
  void buildCell(uint32_t cell, const std::vector<Placement>& placements);
  bool built(uint32_t cell) const { return cell < cells_.size() && cells_[cell] != nullptr; }
  bool occluded(uint32_t cell, const Segment& s) const;

 private:
  TraceDevice& device_;
  std::vector<std::unique_ptr<TraceScene>> leaves_;
  std::vector<RTCSceneTy*> cells_;
};

}  // namespace proxyvis::ecosys
