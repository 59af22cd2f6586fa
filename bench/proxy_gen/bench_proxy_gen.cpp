// bench_proxy_gen: every proxy-gen kind and method on the bundled meshes (data/) and the hard set
// (data/hard), without a face budget and at 2 %
// of the input's faces; prints a Markdown table of faces, volume ratio, sampled Hausdorff
// distances both ways (fractions of the diagonal), seconds, peak RSS and the class written, or
// why the case failed. Each row runs in its own child process (this program with --row), so that
// its peak RSS is its own and a crash or hang ends only that row. Targets from the project (2
// cores): qem <= 1 s, outside wrap + 2 % budget <= 5 s, inside <= 15 s per 100 k faces. Never
// fails on speed.
#include <fmt/core.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "child_process.h"
#include "mesh/io/mesh_io.h"
#include "mesh/validation.h"
#include "proxies/pipeline/proxy_pipeline.h"
#include "util/app_main.h"
#include "util/error.h"
#include "util/stopwatch.h"

namespace fs = std::filesystem;
using json = nlohmann::json;
using namespace proxyvis;

namespace {

struct Case {
  std::string kind, method;
  double ratio;  // fraction of the input faces; 0 = no budget
};

// General proxies have no unbudgeted mode (proxy-gen's default is --ratio 0.02): they run at 2 %
// and 1 %; outside and inside without a budget and at 2 %.
std::vector<Case> cases(bool quick) {
  std::vector<Case> all;
  for (const char* kind : {"outside", "inside"})
    for (const std::string& method :
         proxyMethods(std::string(kind) == "outside" ? ProxyClass::kOutside : ProxyClass::kInside))
      for (double ratio : {0.0, 0.02})
        if (!quick || ratio > 0) all.push_back({kind, method, ratio});
  for (const std::string& method : proxyMethods(ProxyClass::kGeneral))
    for (double ratio : {0.02, 0.01})
      if (!quick || ratio == 0.02) all.push_back({"general", method, ratio});
  return all;
}

ProxyClass kindOf(const std::string& name) {
  return name == "outside"  ? ProxyClass::kOutside
         : name == "inside" ? ProxyClass::kInside
                            : ProxyClass::kGeneral;
}

// Every triangle with its own three vertices (unwelded, as plant meshes come).
TriMesh unwelded(const TriMesh& m) {
  TriMesh soup;
  soup.source = m.source + " (soup)";
  for (const Triangle& t : m.triangles) {
    const uint32_t base = uint32_t(soup.vertices.size());
    for (uint32_t i : t) soup.vertices.push_back(m.vertices[i]);
    soup.triangles.push_back({base, base + 1, base + 2});
  }
  return soup;
}

// Child mode: one proxy, one JSON line on stdout.
int runRow(const std::string& path, bool soup, const Case& c, double max_seconds) {
  json out;
  try {
    const Stopwatch loading;
    TriMesh input = loadMesh(path);
    if (soup) input = unwelded(input);
    out["load_seconds"] = loading.seconds();
    ProxyGenOptions o;
    o.kind = kindOf(c.kind);
    o.method = c.method;
    if (c.ratio > 0) o.ratio = c.ratio;
    // An open mesh has no inside of its own: the inside methods fill its holes first.
    if (o.kind == ProxyClass::kInside) o.fill_holes = !validateMesh(input).closed;
    o.max_seconds = max_seconds;
    const ProxyGenResult r = generateProxy(input, o);
    const nlohmann::json report = r.report;
    out["faces"] = r.proxy.numTriangles();
    out["fill_holes"] = o.fill_holes;
    for (const char* key : {"volume_ratio", "hausdorff_proxy_to_original",
                            "hausdorff_original_to_proxy", "class", "verified", "budget_reached"})
      if (report.contains(key)) out[key] = report[key];
    out["seconds"] = report["seconds"]["total"];
  } catch (const std::exception& e) {
    out["error"] = e.what();
  }
  fmt::print("{}\n", out.dump());
  return 0;
}

std::string cell(const json& j, const char* key, const char* f) {
  return j.contains(key) && j[key].is_number() ? fmt::format(fmt::runtime(f), j[key].get<double>())
                                               : "-";
}

struct Mesh {
  fs::path path;
  bool soup = false;
  std::string name;
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"bench_proxy_gen: quality, time and memory of every proxy-gen method",
               "bench_proxy_gen"};
  CommonOptions common;
  bool quick = false;
  std::vector<std::string> only;
  double max_seconds = 300;
  std::vector<std::string> row;
  app.add_flag(
      "--quick", quick,
      "Only the meshes under 20 k faces, only at 2 % (a few minutes; docs/proxy_gen_bench.md)");
  app.add_option("--mesh", only, "Only meshes whose file name contains one of these");
  app.add_option("--max-seconds", max_seconds, "Time budget of one row (proxy-gen --max-seconds)")
      ->check(numberIn(1, 3600))
      ->capture_default_str();
  app.add_option("--row", row, "(internal) run one row: PATH SOUP KIND METHOD RATIO")->expected(5);
  addCommonOptions(app, common);
  return runApp(app, argc, argv, common, [&] {
    if (!row.empty())
      return runRow(row[0], row[1] == "1", {row[2], row[3], std::stod(row[4])}, max_seconds);

    std::vector<Mesh> meshes;
    const fs::path data(PROXYVIS_DATA_DIR);
    for (const char* name :
         {"bunny.off", "spot_triangulated.obj", "teapot.obj", "bun_zipper.ply", "dragon.drc"})
      if (fs::exists(data / name)) meshes.push_back({data / name, false, name});
    if (fs::exists(data / "bun_zipper.ply"))
      meshes.push_back({data / "bun_zipper.ply", true, "bun_zipper.ply (soup)"});
    const fs::path hard = data / "hard";
    std::vector<std::string> notes;
    if (fs::is_directory(hard)) {
      std::vector<fs::path> files;
      for (const auto& e : fs::directory_iterator(hard))
        if (e.path().extension() != ".md") files.push_back(e.path());
      std::sort(files.begin(), files.end());
      for (const fs::path& p : files) meshes.push_back({p, false, "hard/" + p.filename().string()});
    } else {
      notes.push_back(fmt::format("hard set skipped: {} not found", hard.string()));
    }
    if (!only.empty())
      std::erase_if(meshes, [&](const Mesh& m) {
        return std::none_of(only.begin(), only.end(), [&](const std::string& s) {
          return m.name.find(s) != std::string::npos;
        });
      });

    const std::string self = fs::read_symlink("/proc/self/exe").string();
    const Stopwatch table;
    fmt::print(
        "Each row is one child process that loads the mesh and builds one proxy: seconds = "
        "generateProxy's total (build, budget, verify, metrics; not loading), peak RSS = the "
        "child's ru_maxrss (loading included). Hausdorff distances are fractions of the "
        "diagonal. Inside proxies of open meshes are built with --fill-holes.\n\n");
    for (const std::string& n : notes) fmt::print("Note: {}\n\n", n);
    fmt::print(
        "| mesh | faces | kind | method | budget | proxy faces | volume ratio | H(proxy→orig) | "
        "H(orig→proxy) | seconds | peak RSS MB | class (verified) |\n");
    fmt::print("|---|---:|---|---|---:|---:|---:|---:|---:|---:|---:|---|\n");
    for (const Mesh& m : meshes) {
      size_t faces = 0;
      try {
        faces = loadMesh(m.path).numTriangles();
      } catch (const Error& e) {
        fmt::print("| {} | - | all | - | - | FAILED to load: {} |\n", m.name, e.what());
        continue;
      }
      if (quick && faces > 20000) continue;
      for (const Case& c : cases(quick)) {
        const std::string budget =
            c.ratio > 0 ? fmt::format("{:g} %", c.ratio * 100) : std::string("none");
        const bench::ChildResult r = bench::runChild(
            {self, "--row", m.path.string(), m.soup ? "1" : "0", c.kind, c.method,
             fmt::format("{}", c.ratio), "--max-seconds", fmt::format("{}", max_seconds),
             "--threads", fmt::format("{}", common.threads)},
            max_seconds + 60);
        const std::string head =
            fmt::format("| {} | {} | {} | {} | {} |", m.name, faces, c.kind, c.method, budget);
        const double rss = double(r.peak_rss_kb) / 1024;
        json j;
        try {
          j = json::parse(r.output);
        } catch (const std::exception&) {
          const std::string why = r.timed_out ? fmt::format("killed after {:.0f} s", r.seconds)
                                  : r.signal  ? fmt::format("crashed (signal {})", r.signal)
                                              : fmt::format("exit code {}", r.exit_code);
          fmt::print("{} FAILED: {} | | | | {:.1f} | {:.0f} | - |\n", head, why, r.seconds, rss);
          continue;
        }
        if (j.contains("error")) {
          std::string e = j["error"].get<std::string>();
          std::replace(e.begin(), e.end(), '|', '/');
          fmt::print("{} FAILED: {} | | | | {:.1f} | {:.0f} | - |\n", head, e, r.seconds, rss);
          continue;
        }
        const std::string cls =
            j.value("class", json()).is_string() ? j["class"].get<std::string>() : std::string("-");
        // Over the budget: the report's budget_reached (outside/inside), else the count itself
        // (general; the simplifiers aim at max(4, ratio x faces)).
        const size_t got = j["faces"].get<size_t>();
        const size_t target = std::max<size_t>(c.kind == "general" ? 4 : 12,
                                               size_t(std::llround(c.ratio * double(faces))));
        const bool over = c.ratio > 0 && (!j.value("budget_reached", true) || got > target);
        fmt::print("{} {}{} | {} | {} | {} | {} | {:.0f} | {} ({}) |\n", head, got,
                   over ? fmt::format(" (over budget {})", target) : std::string(),
                   cell(j, "volume_ratio", "{:.3f}"),
                   cell(j, "hausdorff_proxy_to_original", "{:.4f}"),
                   cell(j, "hausdorff_original_to_proxy", "{:.4f}"), cell(j, "seconds", "{:.2f}"),
                   rss, cls, j.value("verified", false) ? "yes" : "no");
        std::fflush(stdout);
      }
    }
    fmt::print("\nTable time: {:.0f} s\n", table.seconds());
    return 0;
  });
}
