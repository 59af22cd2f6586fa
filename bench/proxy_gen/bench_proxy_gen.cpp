// bench_proxy_gen: every proxy-gen method on bunny, dragon and spot; prints a Markdown table of
// faces, volume ratio, sampled Hausdorff distances (fractions of the diagonal), whether the
// guarantee was verified, and seconds to generate (build + budget) and to verify. Targets from
// the project (dragon, 2 threads): outside wrap + 2 % budget ratio <= 1.25 in <= 5 s, inside wrap
// at 2 % ratio >= 0.75 in <= 15 s, hull <= 0.3 s, QEM to 1 % <= 1 s. Never fails on speed.
#include <fmt/core.h>
#include <CLI/CLI.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "mesh/mesh_io.h"
#include "proxies/general/proxy_pipeline.h"
#include "util/app_main.h"
#include "util/error.h"

namespace fs = std::filesystem;
using namespace proxyvis;

namespace {

struct Row {
  ProxyClass kind;
  const char* method;
  double budget;  // fraction of the input faces; 0 = none
};

// data/ first (dragon.drc is the 16-bit Draco dragon), else the shared data folder.
fs::path findMesh(const std::string& name) {
  const fs::path data(PROXYVIS_DATA_DIR), shared = fs::path(PROXYVIS_SHARED_DATA_DIR) / "meshes";
  for (const fs::path& p :
       {data / name, shared / name, shared / fs::path(name).replace_extension(".ply")})
    if (fs::exists(p)) return p;
  throw Error(name, "mesh not found", "looked in data/ and the shared data folder");
}

std::string cell(const nlohmann::json& v, const char* f) {
  return v.is_number() ? fmt::format(fmt::runtime(f), v.get<double>()) : "-";
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"bench_proxy_gen: quality and time of every proxy-gen method", "bench_proxy_gen"};
  CommonOptions common;
  std::vector<std::string> meshes{"bunny.off", "spot_triangulated.obj", "dragon.drc"};
  app.add_option("--mesh", meshes, "Meshes (file names in data/)")->capture_default_str();
  addCommonOptions(app, common);
  return runApp(app, argc, argv, common, [&] {
    const std::vector<Row> rows{
        {ProxyClass::kOutside, "hull", 0},        {ProxyClass::kOutside, "hull", 0.02},
        {ProxyClass::kOutside, "wrap", 0},        {ProxyClass::kOutside, "wrap", 0.02},
        {ProxyClass::kInside, "wrap", 0},         {ProxyClass::kInside, "wrap", 0.02},
        {ProxyClass::kInside, "erode", 0.02},     {ProxyClass::kGeneral, "qem", 0.01},
        {ProxyClass::kGeneral, "cgal-sms", 0.01}, {ProxyClass::kGeneral, "meshopt", 0.01},
        {ProxyClass::kGeneral, "qem", 0.02}};
    fmt::print(
        "| mesh | kind | method | budget | faces | volume ratio | H(proxy→orig) | H(orig→proxy) | "
        "verified | generate s | verify s |\n");
    fmt::print("|---|---|---|---:|---:|---:|---:|---:|---|---:|---:|\n");
    for (const std::string& name : meshes) {
      const TriMesh input = loadMesh(findMesh(name));
      for (const Row& row : rows) {
        ProxyGenOptions o;
        o.kind = row.kind;
        o.method = row.method;
        o.seed = common.seed;
        const size_t budget = size_t(row.budget * double(input.numTriangles()));
        if (row.kind == ProxyClass::kGeneral)
          o.ratio = row.budget;
        else
          o.max_faces = budget;
        const std::string budget_text =
            row.budget > 0 ? fmt::format("{} ({:.0f} %)", budget, row.budget * 100) : "-";
        try {
          const ProxyGenResult r = generateProxy(input, o);
          const auto& s = r.report["seconds"];
          const double generate =
              s.value("build", 0.0) + s.value("simplify", 0.0) + s.value("fill_holes", 0.0);
          fmt::print("| {} | {} | {} | {} | {} | {} | {} | {} | {} | {:.3f} | {:.3f} |\n", name,
                     proxyClassName(row.kind), row.method, budget_text, r.proxy.numTriangles(),
                     cell(r.report["volume_ratio"], "{:.3f}"),
                     cell(r.report["hausdorff_proxy_to_original"], "{:.4f}"),
                     cell(r.report["hausdorff_original_to_proxy"], "{:.4f}"),
                     r.verified ? "yes" : "no", generate, s.value("verify", 0.0));
        } catch (const Error& e) {
          fmt::print("| {} | {} | {} | {} | FAILED: {} |\n", name, proxyClassName(row.kind),
                     row.method, budget_text, e.what());
        }
        std::fflush(stdout);
      }
    }
    return 0;
  });
}
