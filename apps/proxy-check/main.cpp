// proxy-check: classifies a proxy against its original by sampled segments and by an exact
// containment test, and reports both (docs/design.md).
//
//   proxy-check ORIGINAL PROXY [--rays N] [--seed S] [--expect outside|inside|general]
//               [--json OUT] [--dump-errors FILE.ply] [--html REPORT.html]
//   proxy-check SCENE.json [--write-scene OUT.json]
//               (every proxy of every mesh; instanced meshes: their prototype)
#include <fmt/core.h>

#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "mesh/io/double_reading.h"
#include "mesh/io/mesh_io.h"
#include "proxies/check/check_report.h"
#include "proxies/check/check_view3d.h"
#include "proxies/check/pair_check.h"
#include "proxies/check/proxy_check_settings.h"
#include "proxies/check/scene_pairs.h"
#include "scene/scene_desc.h"
#include "util/app_main.h"
#include "util/error.h"
#include "util/output_path.h"
#include "util/output_set.h"
#include "util/sha256.h"

namespace fs = std::filesystem;
using namespace proxyvis;

namespace {

struct Options {
  GltfPick original_pick, proxy_pick;  // --mesh/--node, --proxy-mesh/--proxy-node (glTF pair)
  CommonOptions common;
  std::vector<std::string> inputs;
  ProxyCheckSettings check;  // --rays, --distribution, --expect, --precision (seed, quiet: common)
  std::string dump_errors;
  std::string write_scene;
  std::string html;
};

// Error segments kept for --html alone (the page draws a few thousand of each class; keeping the
// first of a larger number leaves enough of the rarer class).
constexpr uint64_t kHtmlErrorSegments = 200'000;

// The human report goes to stdout unless the JSON does; then to stderr (unless --quiet).
void printHuman(const Options& o, const std::string& text) {
  printHumanReport(o.common, text);
}

// The error segments, the HTML page and the JSON that describes them (with their hashes) as one
// unit: the JSON is put in place last.
void writeOutputs(const Options& o, const std::vector<ErrorSegment>& errors, nlohmann::json json,
                  const std::string& html = {}) {
  OutputSet outputs(MissingFolders::kCreate);
  if (!o.dump_errors.empty()) {
    outputs.add(o.dump_errors,
                [&](const std::filesystem::path& tmp) { writeErrorSegmentsPly(errors, tmp); });
    json["dump_errors"] = {{"file", o.dump_errors},
                           {"segments", errors.size()},
                           {"sha256", outputs.sha256Of(o.dump_errors)}};
  }
  if (!o.html.empty()) {
    outputs.addText(o.html, html);
    json["html"] = {{"file", o.html}, {"sha256", outputs.sha256Of(o.html)}};
  }
  if (!o.common.json_path.empty()) outputs.addText(o.common.json_path, json.dump(2) + "\n");
  outputs.commit();
}

void printMismatch(const PairCheckReport& r) {
  if (r.mismatch)
    std::fprintf(stderr, "proxy-check: MISMATCH between sampled and exact verdicts%s%s: %s\n",
                 r.label.empty() ? "" : " for ", r.label.c_str(), r.mismatch->c_str());
}

ProxyCheckSettings checkSettings(const Options& o) {
  ProxyCheckSettings s = o.check;
  s.seed = o.common.seed;
  s.quiet = o.common.quiet;
  if (!o.html.empty()) s.max_error_segments = kHtmlErrorSegments;
  if (!o.dump_errors.empty()) s.max_error_segments = 1'000'000;
  return s;
}

PairCheckOptions pairOptions(const Options& o) {
  return pairCheckOptions(checkSettings(o));
}

int runPair(const Options& o) {
  const ProxyCheckSettings settings = checkSettings(o);
  requireSphereDistribution(settings);
  if (!o.write_scene.empty())
    throw Error("", "--write-scene needs a scene", "a mesh pair has no scene to record into",
                "run proxy-check SCENE.json --write-scene OUT.json");
  const TriMesh original = loadMesh(o.inputs[0], o.original_pick);
  const TriMesh proxy = loadMesh(o.inputs[1], o.proxy_pick);
  // The original's file read again in double (text formats; binary ones store the floats).
  std::vector<Vec3d> in_double;
  if (needsDoubleReading(settings)) in_double = readDoublePositions(o.inputs[0], original);
  PairCheckReport r = checkMeshPair(original, &in_double, proxy, settings);
  printHuman(o, formatHumanReport(r));
  printMismatch(r);
  const std::string html = o.html.empty() ? std::string() : checkReportHtml(original, proxy, r);
  writeOutputs(o, r.sampled.errors, toJson(r), html);
  return r.failed() ? kExitCheckFailed : kExitOk;
}

int runScene(const Options& o) {
  const SceneDesc scene = loadSceneDesc(o.inputs[0]);
  SceneDesc proven = scene;  // --write-scene: the classes the checks prove, with their hashes
  std::vector<ScenePair> checked =
      checkScenePairs(scene, pairOptions(o), o.check.distribution == "scene");
  const size_t pairs = checked.size();
  SceneCheckReport report{scene.path.string(), o.common.seed, o.check.rays, {}};
  std::vector<ErrorSegment> all_errors;
  for (ScenePair& c : checked) {
    const PairCheckReport& r = c.report;
    printHuman(o, formatHumanReport(r) + "\n");
    printMismatch(r);
    if (r.shortfall)
      std::fprintf(stderr, "proxy-check: warning: %s: %s\n", r.label.c_str(), r.shortfall->c_str());
    const ProxyRef& ref = scene.meshes[c.mesh].proxies[c.proxy];
    ProxyRef& record = proven.meshes[c.mesh].proxies[c.proxy];
    record.verified_class = provenClass(r);
    record.sha256 = sha256OfFile(ref.file);
    report.checks.push_back(&r);
    all_errors.insert(all_errors.end(), r.sampled.errors.begin(), r.sampled.errors.end());
  }
  if (pairs == 0)
    throw Error(o.inputs[0], "the scene lists no proxies", "there is nothing to check",
                "generate them with proxy-gen SCENE.json");
  if (!o.write_scene.empty()) saveSceneDesc(proven, o.write_scene);
  writeOutputs(o, all_errors, toJson(report));
  return report.ok() ? kExitOk : kExitCheckFailed;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  CLI::App app{
      "proxy-check: classifies a proxy (outside / inside / general) against its original by "
      "sampled segments (counts HH', HM', MH', MM' with 95 % intervals) and by an exact "
      "containment test (CGAL), and reports both. Exit 1 if they disagree or --expect is "
      "contradicted.",
      "proxy-check"};
  addCommonOptions(app, o.common);
  app.add_option(
         "inputs", o.inputs,
         "ORIGINAL PROXY (meshes: .obj .ply .off .drc .gltf .glb) or SCENE (.json, .gltf, .glb)")
      ->required()
      ->expected(1, 2);
  app.add_option("--rays", o.check.rays, proxyCheckHelp("--rays"))
      ->check(integerIn(1, kMaxCheckRays))
      ->capture_default_str();
  app.add_option("--distribution", o.check.distribution, proxyCheckHelp("--distribution"))
      ->check(CLI::IsMember({"sphere", "scene"}))
      ->capture_default_str();
  app.add_option("--expect", o.check.expect, proxyCheckHelp("--expect"))
      ->check(CLI::IsMember({"outside", "inside", "general"}));
  app.add_option("--precision", o.check.precision, proxyCheckHelp("--precision"))
      ->check(CLI::IsMember({"float", "double", "both"}))
      ->capture_default_str();
  app.add_option("--dump-errors", o.dump_errors,
                 "Write the error segments as a PLY of edges (red HM', blue MH')");
  addGltfPickOptions(app, o.original_pick.mesh, o.original_pick.node);
  CLI::Option* proxy_mesh = app.add_option(
      "--proxy-mesh", o.proxy_pick.mesh,
      "glTF proxy: take only the mesh with this name (as --mesh does for the original)");
  app.add_option("--proxy-node", o.proxy_pick.node,
                 "glTF proxy: take only the node with this name and its children, in world "
                 "coordinates (as --node does for the original); e.g. the NAME-occludee node "
                 "proxy-gen --gltf writes")
      ->excludes(proxy_mesh);
  app.add_option("--html", o.html,
                 "Mesh pair: write an HTML page with the classification and an interactive 3D "
                 "view of original, proxy and the error segments (three.js embedded: one file "
                 "that works offline; docs/report_3d.md)");
  app.add_option("--write-scene", o.write_scene,
                 "Scene input: write a copy of the scene (paths relative to OUT.json) in which "
                 "each proxy's class is the one the exact check proved (outside: contains; "
                 "inside: contained; otherwise general) with the SHA-256 of its file, so "
                 "render-compare relies on it without checking again. Written also when a check "
                 "fails (exit 1): it then records what holds.");
  return runApp(app, argc, argv, o.common, [&] {
    checkOutputs(o.inputs, {{"--json", o.common.json_path},
                            {"--dump-errors", o.dump_errors},
                            {"--write-scene", o.write_scene},
                            {"--html", o.html}});
    if (o.inputs.size() == 1) {
      if (fs::path(o.inputs[0]).extension() != ".json")
        throw Error(o.inputs[0], "one input must be a scene (.json)",
                    "a mesh needs its proxy beside it", "proxy-check ORIGINAL PROXY");
      const auto picks = [](const GltfPick& p) { return !p.mesh.empty() || !p.node.empty(); };
      if (picks(o.original_pick) || picks(o.proxy_pick))
        throw Error("", "--mesh, --node, --proxy-mesh and --proxy-node pick from a mesh pair",
                    "a scene names its meshes itself", "give ORIGINAL PROXY");
      if (!o.html.empty())
        throw Error("", "--html needs a mesh pair", "the page shows one original and its proxy",
                    "run proxy-check ORIGINAL PROXY --html REPORT.html");
      return runScene(o);
    }
    return runPair(o);
  });
}
