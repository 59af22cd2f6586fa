// libFuzzer target: the instance list parser (parseInstanceList) on arbitrary text, for the
// meshes of the bundled foliage scene. Whatever it accepts must name one of those meshes and
// carry an invertible transform within the ranges of scene_desc.h.
// fuzz-libraries: pv_scene pv_util
#include <cmath>

#include "fuzz_scene_checks.h"
#include "scene/scene_desc.h"
#include "scene/transform.h"

namespace proxyvis::fuzz {
namespace {

std::vector<SceneMeshDesc> foliageMeshes() {
  std::vector<SceneMeshDesc> meshes;
  for (const char* name : {"ground", "BUSH11", "URTICADIOICA1", "GRASS1", "YELLOWFLOWER1"}) {
    meshes.emplace_back();
    meshes.back().name = name;
  }
  return meshes;
}

void checkInstances(const std::vector<SceneInstanceDesc>& instances, size_t n_meshes) {
  for (const SceneInstanceDesc& inst : instances) {
    if (inst.mesh >= n_meshes) finding("accepted an instance of a mesh that does not exist");
    checkTransform(inst.transform);
  }
}

}  // namespace
}  // namespace proxyvis::fuzz

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace proxyvis;
  static const std::vector<SceneMeshDesc> meshes = fuzz::foliageMeshes();
  fuzz::parsedOrRefused([&] {
    fuzz::checkInstances(parseInstanceList(fuzz::bytesOf(data, size), "fuzz.instances.txt", meshes),
                         meshes.size());
  });
  return 0;
}
