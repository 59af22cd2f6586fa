#pragma once
// Loading and saving TriMesh: OBJ, PLY (ASCII and binary), OFF through OpenMesh; Draco .drc through
// the Draco library; glTF 2.0 (.gltf, .glb) through tinygltf (a whole file as one world-space
// mesh; mesh/io/internal/gltf_io.h). The format is chosen by the extension (case-insensitive).
//
// Loading never trusts a header: a PLY claiming 2^31 vertices in a 1 KB file is an Error, not an
// 8 GB allocation. Only regular files are read (never a FIFO or device). Every failure (missing,
// empty, truncated, corrupt file, unknown extension, NaN/inf or beyond-float coordinates, index
// out of range, no triangles) throws proxyvis::Error whose message names the file, what is wrong
// and why (and the line, for text formats).
//
// Integrity: saveMesh writes "<file>.sha256" (sha256sum format) after the mesh; loadMesh verifies
// it when present and refuses a file whose content does not match. Files without a sidecar load
// as before. docs/mesh-formats.md describes what each format can and cannot detect.
//
// OBJ/PLY/OFF are parsed by OpenMesh's readers into a polygon soup (not an OpenMesh half-edge
// mesh), so non-manifold faces (ecosys foliage, the teapot's pinched vertex) are kept and the
// file's vertex order is preserved. The syntax OpenMesh's readers cannot survive (they loop or
// assert on some corrupt files) is rejected before they run. Thread-safe: OpenMesh file access is
// serialized internally.
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "mesh/tri_mesh.h"

namespace proxyvis {

class OutputSet;

// How a .gltf/.glb stores its geometry: plain, KHR_draco_mesh_compression (positions quantized
// to draco_quantization bits, 0 = lossless floats) or EXT_meshopt_compression (exact).
enum class GltfCompression { kNone, kDraco, kMeshopt };

struct SaveOptions {
  bool binary = true;           // PLY only: binary_little_endian (true) or ASCII
  int draco_quantization = 16;  // .drc only: position quantization bits (0 = lossless float)
  int draco_speed = 5;          // .drc only: encoder speed 0 (best) .. 10 (fastest)
  // .gltf/.glb only: the node's and mesh's name (default: the file's stem), its extras (the
  // proof of a proxy, docs/gltf.md) and whether KHR_node_visibility hides it.
  std::string gltf_name = {};
  nlohmann::json gltf_extras = nullptr;
  bool gltf_hidden = false;
  GltfCompression gltf_compression = GltfCompression::kNone;
};

// What to take of a glTF file (docs/gltf.md): by default every mesh of the default scene placed
// by its nodes; `node`: one node's subtree, in world space; `mesh`: one mesh, in its own space.
// Names must match exactly one node or mesh. Ignored for the other formats.
struct GltfPick {
  std::string mesh, node;
  int mesh_index = -1;         // meshes[i], in its own space (scene meshes: names can repeat)
  bool surfaces_only = false;  // leave out emissive primitives (a glTF scene's lights)
};

// What every loaded mesh satisfies before anyone uses it (loadMesh checks it; so does whatever
// makes a TriMesh from other data, e.g. the Python module's arrays): finite positions, vertex
// indices in range, at least one triangle. Throws Error naming `file` otherwise.
void checkMeshContent(const TriMesh& mesh, const std::string& file);

// Loads a triangle mesh; polygons are fan-triangulated. Vertex order is kept.
TriMesh loadMesh(const std::filesystem::path& path, const GltfPick& pick = {});

// What loadMesh does once it has the file's bytes (and checked them against a .sha256 sidecar):
// `path` only chooses the format (extension) and names the file in errors; nothing is read from
// disk. For callers that hold the bytes (fuzzers).
TriMesh parseMeshBytes(std::string bytes, const std::filesystem::path& path);

// parseMeshBytes for a file in `folder`: a .gltf may read its external buffers from inside it.
TriMesh parseMeshBytesIn(std::string bytes, const std::filesystem::path& path,
                         const std::filesystem::path& folder, const GltfPick& pick = {});

// Saves atomically (temporary file + rename), then its "<file>.sha256" sidecar the same way.
// Throws WriteError when either cannot be written (and leaves neither), Error for an unknown
// extension.
void saveMesh(const TriMesh& mesh, const std::filesystem::path& path,
              const SaveOptions& options = {});

// --compress none|draco|meshopt for a mesh written to `output`: anything but "none" needs a
// .gltf/.glb output (Error naming the flag otherwise).
GltfCompression parseGltfCompression(const std::string& text, const std::filesystem::path& output);

// True when writing `mesh` to `path` with `options` changes its positions (Draco quantization,
// in a .drc or glTF Draco): what is written must then be checked again.
bool movesVertices(const std::filesystem::path& path, const SaveOptions& options);

// The bytes saveMesh would write for `mesh` at `path` (format by extension). Throws Error for an
// unknown extension, WriteError when an encoder refuses the mesh.
std::string encodeMesh(const TriMesh& mesh, const std::filesystem::path& path,
                       const SaveOptions& options = {});

// Stages already encoded mesh bytes and their sidecar in `outputs`, as addMeshOutput does.
void addEncodedMeshOutput(OutputSet& outputs, const std::string& bytes,
                          const std::filesystem::path& path);

// Stages `mesh` and its sidecar in `outputs` (saveMesh is this plus commit()), for programs that
// write a mesh together with the report describing it as one unit.
void addMeshOutput(OutputSet& outputs, const TriMesh& mesh, const std::filesystem::path& path,
                   const SaveOptions& options = {});

// True for .gltf and .glb (case-insensitive).
bool isGltfPath(const std::filesystem::path& path);

// True if the extension is one loadMesh/saveMesh understands (.obj .ply .off .drc .gltf .glb).
bool isSupportedMeshExtension(const std::filesystem::path& path);

}  // namespace proxyvis
