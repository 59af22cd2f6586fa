#pragma once
// The node graph of a glTF scene: where each mesh is placed in the world.
#include <array>
#include <string>
#include <vector>

#include "mesh/io/mesh_io.h"
#include "util/vec3.h"

namespace tinygltf {
class Model;
}

namespace proxyvis::detail {

class GltfAccessors;

using Mat4 = std::array<double, 16>;  // column-major, as glTF stores it

Mat4 identity();
double determinant3(const Mat4& m);  // of the linear part: negative for a mirror
Vec3f transformPoint(const Mat4& m, const Vec3f& p);

// A mesh (or camera) placed in the world by a node (or by one of its GPU instances).
struct Placement {
  int mesh;  // or the camera's index
  Mat4 world;
  int node;  // -1 when no node placed it (pick.mesh, a file without nodes)
};

// The placements of the default scene, walked from its roots (transforms composed in double
// precision, EXT_mesh_gpu_instancing expanded), restricted to pick.node's subtree when given;
// pick.mesh: that one mesh, untransformed; a file without scenes or nodes: every mesh once,
// untransformed. `cameras`, when given, gets the nodes with a camera in the same walk. Throws Error
// for cycles, nodes with two parents, indices out of range, and names that match no node or
// mesh, or several.
std::vector<Placement> placements(const tinygltf::Model& model, GltfAccessors& data,
                                  const GltfPick& pick, const std::string& file,
                                  std::vector<Placement>* cameras = nullptr);

}  // namespace proxyvis::detail
