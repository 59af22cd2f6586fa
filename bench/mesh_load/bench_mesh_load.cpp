// How long loadMesh takes per file format: every round loads each file once, in an order rotated
// from round to round, so that what the machine does meanwhile falls on all of them alike. Prints
// a table (median and range over the rounds, triangles per second, and the median of the
// per-round ratios to the first file); never fails on speed.
//
//   bench_mesh_load FILE... [--rounds N]      (bench/mesh_load/prepare.sh writes a set)
#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "mesh/io/mesh_io.h"
#include "util/error.h"

using namespace proxyvis;

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

int main(int argc, char** argv) {
  try {
    int rounds = 7;
    std::vector<std::string> files;
    for (int i = 1; i < argc; ++i) {
      if (std::strcmp(argv[i], "--rounds") == 0 && i + 1 < argc)
        rounds = std::max(1, std::atoi(argv[++i]));
      else
        files.push_back(argv[i]);
    }
    if (files.empty()) {
      std::fprintf(stderr, "usage: bench_mesh_load FILE... [--rounds N]\n");
      return 2;
    }
    const size_t n = files.size();
    std::vector<std::vector<double>> seconds(n);
    std::vector<size_t> triangles(n);
    for (int r = 0; r < rounds; ++r)
      for (size_t k = 0; k < n; ++k) {
        const size_t f = (k + size_t(r)) % n;
        const auto start = std::chrono::steady_clock::now();
        const TriMesh mesh = loadMesh(files[f]);
        seconds[f].push_back(
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        triangles[f] = mesh.numTriangles();
      }
    fmt::print("{} rounds, interleaved\n\n", rounds);
    fmt::print(
        "| file | MB | triangles | load ms (median) | range ms | M triangles/s | vs first |\n");
    fmt::print("|---|---:|---:|---:|---:|---:|---:|\n");
    for (size_t f = 0; f < n; ++f) {
      std::vector<double> ratios;
      for (int r = 0; r < rounds; ++r)
        ratios.push_back(seconds[f][size_t(r)] / seconds[0][size_t(r)]);
      const auto [lo, hi] = std::minmax_element(seconds[f].begin(), seconds[f].end());
      const double m = median(seconds[f]);
      fmt::print("| {} | {:.1f} | {} | {:.0f} | {:.0f}-{:.0f} | {:.1f} | {:.2f}x |\n",
                 std::filesystem::path(files[f]).filename().string(),
                 double(std::filesystem::file_size(files[f])) / 1e6, triangles[f], m * 1e3,
                 *lo * 1e3, *hi * 1e3, double(triangles[f]) / m / 1e6, median(ratios));
    }
    return 0;
  } catch (const Error& e) {
    std::fprintf(stderr, "bench_mesh_load: error: %s\n", e.what());
    return e.exitCode();
  }
}
