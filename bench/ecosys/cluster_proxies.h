#pragma once
// Scene-level proxies prototyped for the ecosys bench: one outside proxy per square terrain cell
// for all plant instances whose base lies in that cell (the convex hull, or an alpha wrap, of
// their union), traced with the self-shadowing rule generalized from objects to cells:
//     V' = [segment misses the terrain and every OTHER cell's proxy]
//          and [segment misses the originals of the shading point's own cell],
// where the shading point's cell is its instance's cell (a plant) or the cell under the point
// (the terrain). With outside cell proxies, V' = 1 still implies V = 1 (no HM'), as for the
// per-object rule (ClusterOptions::fused traces the same V' in one scene per cell, fused_cells.h).
// Cells farther than `margin` from every shading point are never built: their
// instances' originals stand in the proxy scene (exact, only dearer), so the answer stays right.
#include <memory>
#include <string>
#include <vector>

#include "fused_cells.h"
#include "mesh/tri_mesh.h"
#include "render/render_scene.h"
#include "trace/trace_scene.h"

namespace proxyvis::ecosys {

struct ClusterOptions {
  float cell = 10;              // cell side, scene units
  std::string method = "hull";  // "hull" or "wrap"
  float alpha = 0.5f;           // wrap: alpha, scene units
  float offset = 0.05f;         // wrap: offset, scene units
  float margin = 10;            // build cells within this distance (cells) of a shading point
  // Build each cell's proxy from the instances' own proxies (the scene's chosen proxy, when it
  // has one) instead of their originals: far fewer triangles for the wrap, still outside.
  bool from_proxies = true;
  // One Embree scene per cell holding the terrain, the OTHER cells' proxies and the cell's own
  // originals as instances of shared BVHs, so that V' is one traversal with nothing to ignore
  // (instead of the proxy scene under an ignore filter plus the own cell's originals).
  bool fused = false;
};

struct ClusterSummary {
  int cells = 0, built = 0, failed = 0;
  uint64_t proxy_triangles = 0;  // triangles of the built cell proxies
  double build_seconds = 0;
  std::string first_failure;
};

class ClusterTracer {
 public:
  // `focus`: shading points (world) that decide which cells get a proxy.
  ClusterTracer(const RenderScene& scene, const ClusterOptions& options,
                const std::vector<Vec3f>& focus);
  ~ClusterTracer();

  // The cell whose originals a shading point on `object` at `p` traces itself.
  uint32_t cellOf(uint32_t object, const Vec3f& p) const;
  // Builds that cell's own-originals scene (fused: its whole V' scene) if not yet built (outside
  // any timed section).
  void prepare(uint32_t cell);
  bool proxyVisible(const Segment& s, uint32_t cell) const;
  bool originalVisible(const Segment& s) const { return !scene_.originals().occluded(s); }
  const ClusterSummary& summary() const { return summary_; }

 private:
  const RenderScene& scene_;
  ClusterOptions options_;
  float x0_ = 0, y0_ = 0;
  int nx_ = 1, ny_ = 1;
  std::vector<uint32_t> cell_of_object_;  // plants: the instance's cell; placed meshes: ~0u
  std::vector<TriMesh> originals_;        // per mesh (plants only), object space
  std::unique_ptr<TraceDevice> device_;
  std::unique_ptr<TraceScene> proxies_;
  std::vector<std::unique_ptr<TraceScene>> own_;  // per cell, lazily
  std::vector<std::vector<uint32_t>> members_;    // per cell: its instances' object indices
  TriMesh terrain_;                               // placed meshes, world space
  std::vector<TriMesh> cell_proxy_;               // per cell; empty if not built
  ClusterSummary summary_;

  std::unique_ptr<FusedCellScenes> fused_;
  uint32_t fused_terrain_ = 0;
  std::vector<uint32_t> fused_leaf_mesh_, fused_leaf_cell_;  // leaf per mesh / per cell proxy

  uint32_t cellAt(const Vec3f& p) const;
  std::vector<FusedCellScenes::Placement> fusedPlacements(uint32_t cell);
};

}  // namespace proxyvis::ecosys
