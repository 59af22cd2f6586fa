#include "instance_variants.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace proxyvis::bench {

namespace {

std::vector<bool> instancedMeshes(const SceneDesc& scene) {
  std::vector<bool> used(scene.meshes.size(), false);
  for (const SceneInstanceDesc& i : scene.instances) used[i.mesh] = true;
  return used;
}

}  // namespace

int instancedMeshCount(const SceneDesc& scene) {
  const std::vector<bool> used = instancedMeshes(scene);
  return int(std::count(used.begin(), used.end(), true));
}

SceneDesc withPrototypeCopies(const SceneDesc& scene, int copies) {
  SceneDesc out = scene;
  if (copies <= 1) return out;
  const std::vector<bool> used = instancedMeshes(scene);
  // first_copy[m]: index of mesh m's copy 1; copies 1..copies-1 are consecutive.
  std::vector<uint32_t> first_copy(scene.meshes.size(), 0);
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    if (!used[m]) continue;
    first_copy[m] = uint32_t(out.meshes.size());
    for (int c = 1; c < copies; ++c) {
      out.meshes.push_back(scene.meshes[m]);
      out.meshes.back().name += "_copy" + std::to_string(c);
    }
  }
  std::vector<uint64_t> seen(scene.meshes.size(), 0);
  for (SceneInstanceDesc& i : out.instances) {
    const uint64_t c = seen[i.mesh]++ % uint64_t(copies);
    if (c > 0) i.mesh = first_copy[i.mesh] + uint32_t(c - 1);
  }
  return out;
}

SceneDesc withInstanceCopies(const SceneDesc& scene, int copies) {
  SceneDesc out = scene;
  if (copies <= 1 || scene.instances.empty()) return out;
  float lo[2] = {1e30f, 1e30f}, hi[2] = {-1e30f, -1e30f};
  for (const SceneInstanceDesc& i : scene.instances)
    for (int a = 0; a < 2; ++a) {
      lo[a] = std::min(lo[a], i.transform.m[a][3]);
      hi[a] = std::max(hi[a], i.transform.m[a][3]);
    }
  const float step[2] = {1.01f * (hi[0] - lo[0]) + 1e-3f, 1.01f * (hi[1] - lo[1]) + 1e-3f};
  // Tiles of a square big enough for `copies`, nearest to the origin tile first.
  const int half = int(std::ceil(std::sqrt(double(copies)) / 2)) + 1;
  std::vector<std::pair<int, int>> tiles;
  for (int y = -half; y <= half; ++y)
    for (int x = -half; x <= half; ++x) tiles.emplace_back(x, y);
  std::stable_sort(tiles.begin(), tiles.end(), [](const auto& a, const auto& b) {
    return a.first * a.first + a.second * a.second < b.first * b.first + b.second * b.second;
  });
  out.instances.reserve(scene.instances.size() * size_t(copies));
  for (int c = 1; c < copies; ++c)
    for (const SceneInstanceDesc& i : scene.instances) {
      SceneInstanceDesc moved = i;
      moved.transform.m[0][3] += step[0] * float(tiles[size_t(c)].first);
      moved.transform.m[1][3] += step[1] * float(tiles[size_t(c)].second);
      out.instances.push_back(moved);
    }
  return out;
}

}  // namespace proxyvis::bench
