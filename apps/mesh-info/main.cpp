// mesh-info FILE... [--self-intersections] [--json OUT]: loads each mesh and prints its
// validation report (vertices, faces, bounds, closedness, manifoldness, genus, volume, ...).
// With --save OUT (one input) it also converts: this is how data/dragon.drc was made.
// With --expect-sha256 HEX (one input) the file's content hash is checked before it is loaded.
#include <CLI/CLI.hpp>
#include <cctype>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "mesh/io/mesh_io.h"
#include "mesh/validation.h"
#include "util/app_main.h"
#include "util/error.h"
#include "util/lower_case.h"
#include "util/output_path.h"
#include "util/output_set.h"
#include "util/sha256.h"

namespace {

// --expect-sha256: 64 hex digits, either case.
const CLI::Validator sha256Digits(
    [](const std::string& text) -> std::string {
      if (text.size() == 64 &&
          text.find_first_not_of("0123456789abcdefABCDEF") == std::string::npos)
        return {};
      return "expected 64 hex digits (as sha256sum prints them), got '" + text + "'";
    },
    "SHA256");

// An explicit hash check, before anything is parsed: a mesh format cannot tell a corrupted file
// from a different mesh (Draco decodes most flipped bytes without complaint).
void checkExpectedSha256(const std::string& file, std::string expected) {
  expected = proxyvis::lowerCase(expected);
  const std::string actual = proxyvis::sha256OfFile(file);
  if (actual != expected)
    throw proxyvis::Error(file, "content does not match --expect-sha256",
                          "its sha256 is " + actual + ", expected " + expected,
                          "the file is corrupt or not the one meant; restore a good copy");
}

}  // namespace

int main(int argc, char** argv) {
  using namespace proxyvis;
  CLI::App app{
      "mesh-info: load meshes (OBJ, PLY, OFF, Draco, glTF) and print their validation report",
      "mesh-info"};
  CommonOptions common;
  addCommonOptions(app, common);
  std::vector<std::string> files;
  ValidationOptions validation;
  app.add_option("files", files, "mesh files (.obj .ply .off .drc .gltf .glb)")->required();
  app.add_flag("--self-intersections", validation.self_intersections,
               "also count self-intersecting triangle pairs (CGAL; slow on large meshes)");
  std::string save_path;
  SaveOptions save;
  app.add_option("--save", save_path,
                 "write the (single) input mesh to this file (format by extension)");
  GltfPick pick;
  addGltfPickOptions(app, pick.mesh, pick.node);
  std::string compress = "none";
  addCompressionOptions(app, compress, save.draco_quantization, "(0 = lossless)");
  app.add_option("--draco-speed", save.draco_speed,
                 "with --save *.drc: encoder speed 0 (smallest) .. 10 (sequential connectivity)")
      ->check(integerIn(0, 10));  // with --save *.drc or --compress draco
  app.add_flag("!--ascii", save.binary, "with --save *.ply: write ASCII instead of binary");
  std::string expect_sha256;
  app.add_option("--expect-sha256", expect_sha256,
                 "refuse the (single) input unless its SHA-256 is this (64 hex digits)")
      ->check(sha256Digits);
  return runApp(app, argc, argv, common, [&] {
    checkOutputs(files, {{"--json", common.json_path}, {"--save", save_path}});
    if (!save_path.empty() && files.size() != 1)
      throw Error({}, "--save needs exactly one input mesh",
                  std::to_string(files.size()) + " given");
    if (!expect_sha256.empty()) {
      if (files.size() != 1)
        throw Error({}, "--expect-sha256 needs exactly one input mesh",
                    std::to_string(files.size()) + " given");
      checkExpectedSha256(files[0], expect_sha256);
    }
    if (!save_path.empty() && !isSupportedMeshExtension(save_path))
      throw Error(save_path, "unsupported output extension",
                  "mesh-info writes .obj, .ply, .off, .drc, .gltf or .glb");
    save.gltf_compression = parseGltfCompression(compress, save_path);
    // The converted mesh and the JSON that describes it (with its hash) are written as one unit.
    OutputSet outputs(MissingFolders::kCreate);
    nlohmann::json all = nlohmann::json::array();
    for (const std::string& file : files) {
      const TriMesh mesh = loadMesh(file, pick);
      nlohmann::json j;
      if (!save_path.empty()) {
        addMeshOutput(outputs, mesh, save_path, save);
        j["saved"] = {{"file", save_path}, {"sha256", outputs.sha256Of(save_path)}};
      }
      const MeshReport report = validateMesh(mesh, validation);
      if (!common.quiet) printHumanReport(common, formatReport(report, file));
      j.update(toJson(report));
      j["file"] = file;
      all.push_back(std::move(j));
    }
    if (!common.json_path.empty()) outputs.addText(common.json_path, all.dump(2) + "\n");
    outputs.commit();
    return kExitOk;
  });
}
