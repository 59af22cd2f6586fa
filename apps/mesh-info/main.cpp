// mesh-info FILE... [--self-intersections] [--json OUT]: loads each mesh and prints its
// validation report (vertices, faces, bounds, closedness, manifoldness, genus, volume, ...).
// With --save OUT (one input) it also converts: this is how data/dragon.drc was made.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "mesh/mesh_io.h"
#include "mesh/validation.h"
#include "util/app_main.h"
#include "util/atomic_write.h"
#include "util/error.h"

int main(int argc, char** argv) {
  using namespace proxyvis;
  CLI::App app{"mesh-info: load meshes (OBJ, PLY, OFF, Draco) and print their validation report",
               "mesh-info"};
  CommonOptions common;
  addCommonOptions(app, common);
  std::vector<std::string> files;
  ValidationOptions validation;
  app.add_option("files", files, "mesh files (.obj .ply .off .drc)")->required();
  app.add_flag("--self-intersections", validation.self_intersections,
               "also count self-intersecting triangle pairs (CGAL; slow on large meshes)");
  std::string save_path;
  SaveOptions save;
  app.add_option("--save", save_path,
                 "write the (single) input mesh to this file (format by extension)");
  app.add_option("--draco-bits", save.draco_quantization,
                 "with --save *.drc: position quantization bits (0 = lossless)")
      ->check(CLI::Range(0, 30));
  app.add_option("--draco-speed", save.draco_speed,
                 "with --save *.drc: encoder speed 0 (smallest) .. 10 (sequential connectivity)")
      ->check(CLI::Range(0, 10));
  app.add_flag("!--ascii", save.binary, "with --save *.ply: write ASCII instead of binary");
  return runApp(app, argc, argv, common, [&] {
    if (!save_path.empty() && files.size() != 1)
      throw Error({}, "--save needs exactly one input mesh",
                  std::to_string(files.size()) + " given");
    nlohmann::json all = nlohmann::json::array();
    for (const std::string& file : files) {
      const TriMesh mesh = loadMesh(file);
      if (!save_path.empty()) saveMesh(mesh, save_path, save);
      const MeshReport report = validateMesh(mesh, validation);
      if (!common.quiet) std::fputs(formatReport(report, file).c_str(), stdout);
      nlohmann::json j = toJson(report);
      j["file"] = file;
      all.push_back(std::move(j));
    }
    if (!common.json_path.empty()) writeTextAtomically(common.json_path, all.dump(2) + "\n");
    return kExitOk;
  });
}
