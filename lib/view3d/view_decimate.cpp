#include "view3d/view_decimate.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <utility>
#include <vector>

namespace proxyvis {

namespace {

constexpr uint32_t kMaxGrid = 1u << 20;  // three cell indices (0..grid) fit in 63 bits

// The grid cell of every vertex that a triangle references (UINT64_MAX for the others), for a
// grid of `grid` cells along the longest side of the box.
class CellKeys {
 public:
  explicit CellKeys(const TriMesh& mesh) : mesh_(mesh), used_(mesh.vertices.size(), false) {
    for (const Triangle& t : mesh.triangles)
      for (uint32_t v : t) used_[v] = true;
    const Bounds3f box = mesh.bounds();
    if (box.empty()) return;
    lo_ = Vec3d(box.lo);
    const Vec3d extent(box.extent());
    longest_ = std::max({extent.x, extent.y, extent.z});
  }

  std::vector<uint64_t> keys(uint32_t grid) const {
    const double scale = longest_ > 0 ? grid / longest_ : 0;
    std::vector<uint64_t> out(mesh_.vertices.size(), UINT64_MAX);
    for (size_t v = 0; v < out.size(); ++v) {
      if (!used_[v]) continue;
      uint64_t key = 0;
      for (int a = 0; a < 3; ++a) {
        const double c = std::floor((double(mesh_.vertices[v][a]) - lo_[a]) * scale);
        key = (key << 21) | uint64_t(std::clamp(c, 0.0, double(grid)));
      }
      out[v] = key;
    }
    return out;
  }

  // How many cells hold a used vertex.
  size_t occupied(uint32_t grid) const {
    std::vector<uint64_t> k = keys(grid);
    std::sort(k.begin(), k.end());
    k.erase(std::unique(k.begin(), k.end()), k.end());
    return k.size() - (!k.empty() && k.back() == UINT64_MAX ? 1 : 0);
  }

 private:
  const TriMesh& mesh_;
  std::vector<bool> used_;
  Vec3d lo_;
  double longest_ = 0;
};

TriMesh cluster(const TriMesh& mesh, const CellKeys& cells, uint32_t grid) {
  TriMesh out;
  out.source = mesh.source;
  const std::vector<uint64_t> keys = cells.keys(grid);
  // Vertices sorted by cell: one cluster per run of equal keys.
  std::vector<uint32_t> order(keys.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return keys[a] < keys[b]; });
  std::vector<uint32_t> cluster_of(keys.size(), UINT32_MAX);
  std::vector<Vec3d> sums;
  std::vector<uint32_t> members;
  for (size_t i = 0; i < order.size() && keys[order[i]] != UINT64_MAX; ++i) {
    if (i == 0 || keys[order[i]] != keys[order[i - 1]]) {
      sums.emplace_back();
      members.push_back(0);
    }
    cluster_of[order[i]] = uint32_t(sums.size() - 1);
    sums.back() += Vec3d(mesh.vertices[order[i]]);
    ++members.back();
  }
  // Triangles on three distinct clusters, each set of three kept once (the first one met).
  std::vector<Triangle> mapped;
  mapped.reserve(mesh.triangles.size());
  for (const Triangle& t : mesh.triangles) {
    const Triangle c{cluster_of[t[0]], cluster_of[t[1]], cluster_of[t[2]]};
    if (c[0] != c[1] && c[1] != c[2] && c[0] != c[2]) mapped.push_back(c);
  }
  std::vector<std::pair<Triangle, uint32_t>> sets(mapped.size());
  for (uint32_t i = 0; i < mapped.size(); ++i) {
    sets[i] = {mapped[i], i};
    std::sort(sets[i].first.begin(), sets[i].first.end());
  }
  std::sort(sets.begin(), sets.end());
  std::vector<bool> keep(mapped.size(), false);
  for (size_t i = 0; i < sets.size(); ++i)
    keep[sets[i].second] = i == 0 || sets[i].first != sets[i - 1].first;
  for (size_t i = 0; i < mapped.size(); ++i)
    if (keep[i]) out.triangles.push_back(mapped[i]);
  out.vertices.reserve(sums.size());
  for (size_t i = 0; i < sums.size(); ++i) out.vertices.push_back(Vec3f(sums[i] / members[i]));
  return out;
}

}  // namespace

TriMesh clusterVertices(const TriMesh& mesh, uint32_t grid) {
  if (grid < 1 || grid > kMaxGrid)
    throw std::invalid_argument("clusterVertices: grid out of range");
  return cluster(mesh, CellKeys(mesh), grid);
}

ViewMesh decimateForView(const TriMesh& mesh, size_t max_triangles) {
  if (max_triangles < 1) throw std::invalid_argument("decimateForView: max_triangles < 1");
  if (mesh.numTriangles() <= max_triangles) return {mesh, 0};
  const CellKeys cells(mesh);
  // A clustered surface keeps about two triangles per occupied cell: the finest grid with at
  // most max_triangles / 2 occupied cells (bisection on the grid's logarithm, to 2 %), counted
  // by sorting cell keys; then clustering, with a coarser grid while it keeps too many.
  const size_t target = std::max<size_t>(max_triangles / 2, 1);
  double lo = 1, hi = kMaxGrid;
  if (cells.occupied(kMaxGrid) <= target) lo = hi;
  while (hi / lo > 1.02) {
    const double mid = std::sqrt(lo * hi);
    (cells.occupied(uint32_t(mid)) <= target ? lo : hi) = mid;
  }
  uint32_t grid = uint32_t(lo);
  for (;;) {
    TriMesh clustered = cluster(mesh, cells, grid);
    const size_t n = clustered.numTriangles();
    if (n <= max_triangles) return {std::move(clustered), grid};
    if (grid == 1) {  // max_triangles below even that: the first triangles of the coarsest
      clustered.triangles.resize(max_triangles);
      return {std::move(clustered), grid};
    }
    grid = std::min(grid - 1, uint32_t(grid * std::sqrt(double(max_triangles) / double(n)) * 0.98));
    grid = std::max(grid, 1u);
  }
}

}  // namespace proxyvis
