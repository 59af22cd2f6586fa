#include "mesh/io/mesh_io.h"

#include <algorithm>
#include <cctype>
#include <sstream>
#include <system_error>

#include "mesh/io/gltf_document.h"
#include "mesh/io/internal/draco_io.h"
#include "mesh/io/internal/gltf_io.h"
#include "mesh/io/internal/header_check.h"
#include "mesh/io/internal/mesh_file.h"
#include "mesh/io/internal/openmesh_formats.h"
#include "mesh/io/sha256_sidecar.h"
#include "util/atomic_write.h"
#include "util/error.h"
#include "util/input_file.h"
#include "util/lower_case.h"
#include "util/output_path.h"
#include "util/output_set.h"

namespace proxyvis {
namespace fs = std::filesystem;

namespace {

// "obj", "ply", "off", "drc", "gltf", "glb" or "" for anything else.
std::string formatOf(const fs::path& path) {
  std::string ext = lowerExtension(path);
  if (!ext.empty()) ext.erase(0, 1);
  for (const char* known : {"obj", "ply", "off", "drc", "gltf", "glb"})
    if (ext == known) return ext;
  return {};
}

Error unknownExtension(const fs::path& path) {
  return Error(path.string(), "unknown mesh file extension '" + path.extension().string() + "'",
               "the format is chosen by the extension",
               "use .obj, .ply, .off, .drc, .gltf or .glb");
}

}  // namespace

namespace detail {

std::string readMeshFile(const fs::path& path) {
  std::string bytes = readTextFile(path);  // missing, directory, unreadable -> Error
  verifySidecar(path, bytes);
  return bytes;
}

fs::path folderOf(const fs::path& path) {
  return path.parent_path().empty() ? fs::path(".") : path.parent_path();
}

}  // namespace detail

bool isGltfPath(const fs::path& path) {
  const std::string format = formatOf(path);
  return format == "gltf" || format == "glb";
}

bool isSupportedMeshExtension(const fs::path& path) {
  return !formatOf(path).empty();
}

void checkMeshContent(const TriMesh& mesh, const std::string& file) {
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    if (!isFinite(mesh.vertices[i]))
      throw Error(file, "vertex " + std::to_string(i) + " has a NaN or infinite coordinate",
                  "positions must be finite numbers", "fix or re-export the mesh");
  }
  const size_t n = mesh.vertices.size();
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    for (uint32_t i : mesh.triangles[f]) {
      if (i >= n)
        throw Error(file, "vertex index out of range",
                    "triangle " + std::to_string(f) + " references vertex " + std::to_string(i) +
                        " but there are " + std::to_string(n),
                    "the file is corrupt; re-export it");
    }
  }
  if (mesh.triangles.empty())
    throw Error(file, "no triangles",
                "the file holds " + std::to_string(n) + " vertices and no faces",
                "a mesh file with at least one face is needed");
}

TriMesh loadMesh(const fs::path& path, const GltfPick& pick) {
  std::error_code ec;
  if (formatOf(path).empty() && fs::is_regular_file(path, ec)) throw unknownExtension(path);
  return parseMeshBytesIn(detail::readMeshFile(path), path, detail::folderOf(path), pick);
}

TriMesh parseMeshBytes(std::string bytes, const fs::path& path) {
  return parseMeshBytesIn(std::move(bytes), path, {});
}

TriMesh parseMeshBytesIn(std::string bytes, const fs::path& path, const fs::path& folder,
                         const GltfPick& pick) {
  const std::string file = path.string();
  const std::string format = formatOf(path);
  if (format.empty()) throw unknownExtension(path);
  if (bytes.empty())
    throw Error(file, "empty file", "0 bytes", "the file was not written completely; re-export it");

  TriMesh mesh;
  mesh.source = file;
  if (format == "drc") {
    detail::decodeDraco(bytes, file, mesh);
  } else if (format == "gltf" || format == "glb") {
    detail::decodeGltf(bytes, format == "glb", folder, pick, file, mesh);
  } else {
    detail::checkDeclaredCounts(bytes, format, file);
    if (format == "off") detail::blankOffComments(bytes);
    detail::readWithOpenMesh(bytes, format, file, mesh);
  }
  checkMeshContent(mesh, file);
  return mesh;
}

GltfCompression parseGltfCompression(const std::string& text, const fs::path& output) {
  if (text == "none" || text.empty()) return GltfCompression::kNone;
  if (!isGltfPath(output))
    throw Error(output.string(), "--compress " + text + " needs a .gltf or .glb output",
                "compression here is the glTF extensions' (Draco files are always compressed)",
                "write .glb, or drop --compress");
  if (text == "draco") return GltfCompression::kDraco;
  if (text == "meshopt") return GltfCompression::kMeshopt;
  throw Error("", "unknown --compress '" + text + "'", "", "use none, draco or meshopt");
}

bool movesVertices(const fs::path& path, const SaveOptions& options) {
  const std::string format = formatOf(path);
  const bool draco =
      format == "drc" || (isGltfPath(path) && options.gltf_compression == GltfCompression::kDraco);
  return draco && options.draco_quantization > 0;
}

std::string encodeMesh(const TriMesh& mesh, const fs::path& path, const SaveOptions& options) {
  const std::string file = path.string();
  const std::string format = formatOf(path);
  if (format.empty()) throw unknownExtension(path);
  if (format == "drc")
    return detail::encodeDraco(mesh, options.draco_quantization, options.draco_speed, file);
  if (format == "gltf" || format == "glb") {
    GltfDocumentOut doc;
    const std::string name = options.gltf_name.empty() ? path.stem().string() : options.gltf_name;
    doc.meshes.push_back({&mesh, name, -1, nullptr});
    GltfNodeOut node;
    node.name = name;
    node.mesh = 0;
    node.extras = options.gltf_extras;
    node.hidden = options.gltf_hidden;
    doc.nodes.push_back(node);
    return encodeGltfDocument(doc, format == "glb", options.gltf_compression,
                              options.draco_quantization, options.draco_speed, file);
  }
  std::ostringstream encoded(std::ios::out | std::ios::binary);
  if (!detail::writeWithOpenMesh(mesh, format, encoded, options.binary))
    throw WriteError(file, "cannot write output", "OpenMesh's " + format + " writer failed");
  return std::move(encoded).str();
}

void addEncodedMeshOutput(OutputSet& outputs, const std::string& bytes, const fs::path& path) {
  // The sidecar is put in place after the mesh: a mesh beside a stale sidecar would be refused.
  // A stream or device target (/dev/null, a FIFO) is no file to verify later: no sidecar.
  outputs.addText(path, bytes);
  if (resolveOutputTarget(path).kind == OutputTarget::Kind::kFile)
    outputs.addText(sidecarPathOf(path), sidecarLine(path, bytes));
}

void addMeshOutput(OutputSet& outputs, const TriMesh& mesh, const fs::path& path,
                   const SaveOptions& options) {
  addEncodedMeshOutput(outputs, encodeMesh(mesh, path, options), path);
}

void saveMesh(const TriMesh& mesh, const fs::path& path, const SaveOptions& options) {
  OutputSet outputs;
  addMeshOutput(outputs, mesh, path, options);
  outputs.commit();
}

}  // namespace proxyvis
