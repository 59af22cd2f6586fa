#pragma once
// Synthetic variants of an instanced scene for the film-scale benches: more prototypes (each
// instanced mesh listed k times, its instances dealt out among the copies: k times the prototype
// triangles at the same instance count) and more instances (the whole instance list copied onto
// a grid of tiles around the original, nearest tiles first, so the camera's view and the
// density of each tile stay those of the original).
#include <cstdint>

#include "scene/scene_desc.h"

namespace proxyvis::bench {

// Every mesh that has instances gets `copies` - 1 more entries (same files and proxies, names
// suffixed "_copyC"), which the renderer builds as separate BVHs; the i-th instance of a mesh
// goes to copy i mod `copies`. Placed meshes are left alone.
SceneDesc withPrototypeCopies(const SceneDesc& scene, int copies);

// The instance list repeated `copies` times: copy 0 is the original, copy c is translated by a
// grid step times the c-th tile offset (tiles ordered by distance from the origin tile). The step
// is the extent of the instances' translations plus 1 % in x and y.
SceneDesc withInstanceCopies(const SceneDesc& scene, int copies);

// Meshes referenced by at least one instance.
int instancedMeshCount(const SceneDesc& scene);

}  // namespace proxyvis::bench
