#pragma once
// One glTF primitive's triangles, and what its material says about it (albedo, emission).
#include <optional>
#include <string>

#include "mesh/tri_mesh.h"
#include "util/vec3.h"

namespace tinygltf {
class Model;
struct Primitive;
}  // namespace tinygltf

namespace proxyvis::detail {

class GltfAccessors;

// The triangles of meshes[mesh_index].primitives[prim_index] in the mesh's space, appended to
// `local` (positions after the ones already there). Strips and fans become triangle lists;
// points and lines are refused; Draco, meshopt and quantized data are decoded.
void appendPrimitive(const tinygltf::Model& model, GltfAccessors& data, size_t mesh_index,
                     size_t prim_index, const std::string& file, TriMesh& local);

// The radiance a primitive's material emits (emissiveFactor times
// KHR_materials_emissive_strength); nullopt when it emits nothing.
std::optional<Vec3f> emittedRadiance(const tinygltf::Model& model, const tinygltf::Primitive& prim);
inline bool isEmissive(const tinygltf::Model& model, const tinygltf::Primitive& prim) {
  return emittedRadiance(model, prim).has_value();
}

// The material's baseColorFactor (RGB), or `fallback` without a material.
Vec3f baseColor(const tinygltf::Model& model, const tinygltf::Primitive& prim, Vec3f fallback);

}  // namespace proxyvis::detail
