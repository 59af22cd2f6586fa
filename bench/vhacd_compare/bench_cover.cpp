// How much of a mesh's volume a set of convex hulls (V-HACD's output) or a proxy covers, by Monte
// Carlo: the same seeded points, uniform in the box around both, located against the input by
// ray parity and against every hull by its face planes. Prints one JSON object. Used by
// bench_convex_parts.py to compare unproved decompositions with our proved proxies.
//
//   bench_cover INPUT --hulls HULLS.obj [--samples N] [--seed S]
//   bench_cover INPUT --solid PROXY [--samples N] [--seed S]
#include <fmt/core.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <cmath>
#include <memory>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

#include "mesh/io/mesh_io.h"
#include "proxies/shared/cgal/parity_solid_mesh.h"
#include "util/error.h"
#include "util/rng.h"

using namespace proxyvis;

namespace {

struct HalfSpace {
  Vec3d n;
  double d;  // inside when dot(n, p) <= d
};

// Connected pieces of a triangle soup (shared vertex indices), each a convex hull given as its
// face planes, oriented so that the piece's vertex centroid is inside.
std::vector<std::vector<HalfSpace>> convexPieces(const TriMesh& m) {
  std::vector<uint32_t> parent(m.vertices.size());
  std::iota(parent.begin(), parent.end(), 0u);
  auto find = [&](uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const Triangle& t : m.triangles)
    for (int k = 1; k < 3; ++k) parent[find(t[k])] = find(t[0]);
  std::vector<int> piece_of(m.vertices.size(), -1);
  std::vector<std::vector<HalfSpace>> pieces;
  std::vector<Vec3d> centroid;
  std::vector<size_t> count;
  std::vector<std::vector<const Triangle*>> faces;
  for (const Triangle& t : m.triangles) {
    const uint32_t root = find(t[0]);
    if (piece_of[root] < 0) {
      piece_of[root] = int(faces.size());
      faces.emplace_back();
    }
    faces[piece_of[root]].push_back(&t);
  }
  for (const auto& list : faces) {
    Vec3d c(0, 0, 0);
    for (const Triangle* t : list)
      for (uint32_t i : *t) c += Vec3d(m.vertices[i]);
    c = c / double(3 * list.size());
    std::vector<HalfSpace> planes;
    for (const Triangle* t : list) {
      const Vec3d a(m.vertices[(*t)[0]]), b(m.vertices[(*t)[1]]), e(m.vertices[(*t)[2]]);
      Vec3d n = cross(b - a, e - a);
      const double len = length(n);
      if (!(len > 0)) continue;
      n = n / len;
      HalfSpace h{n, dot(n, a)};
      if (dot(n, c) > h.d) h = {-n, -h.d};  // the centroid is inside a convex piece
      planes.push_back(h);
    }
    pieces.push_back(std::move(planes));
  }
  return pieces;
}

bool insideConvex(const std::vector<HalfSpace>& planes, const Vec3d& p) {
  for (const HalfSpace& h : planes)
    if (dot(h.n, p) > h.d) return false;
  return true;
}

int run(int argc, char** argv) {
  if (argc < 4)
    throw Error("",
                "usage: bench_cover INPUT (--hulls HULLS.obj | --solid PROXY) [--samples N] "
                "[--seed S]");
  const TriMesh input = loadMesh(argv[1]);
  const std::string mode = argv[2];
  const TriMesh other = loadMesh(argv[3]);
  uint64_t samples = 1'000'000, seed = 1;
  for (int i = 4; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    if (flag == "--samples")
      samples = std::stoull(argv[i + 1]);
    else if (flag == "--seed")
      seed = std::stoull(argv[i + 1]);
    else
      throw Error("", fmt::format("unknown flag {}", flag));
  }
  if (mode != "--hulls" && mode != "--solid") throw Error("", "give --hulls or --solid");

  const cgal::ParitySolid input_solid = cgal::makeParitySolid(input);
  if (!input_solid.watertight())
    throw Error(input.source, "the input bounds no volume", "its volume cannot be covered");
  const cgal::ParityLocator in_input(input_solid.mesh);
  std::vector<std::vector<HalfSpace>> hulls;
  std::optional<cgal::ParitySolid> other_solid;
  std::unique_ptr<cgal::ParityLocator> in_other;
  if (mode == "--hulls") {
    hulls = convexPieces(other);
  } else {
    other_solid = cgal::makeParitySolid(other);
    in_other = std::make_unique<cgal::ParityLocator>(other_solid->mesh);
  }
  Bounds3d box;
  for (const Vec3f& v : input.vertices) box.extend(Vec3d(v));
  for (const Vec3f& v : other.vertices) box.extend(Vec3d(v));
  const Vec3d lo = box.lo, ext = box.extent();

  std::atomic<uint64_t> n_input{0}, n_cover{0}, n_uncovered{0};
  const uint64_t chunk = 4096;
  tbb::parallel_for(uint64_t(0), (samples + chunk - 1) / chunk, [&](uint64_t c) {
    Rng rng(seed, c);
    uint64_t a = 0, b = 0, u = 0;
    for (uint64_t i = c * chunk; i < std::min(samples, (c + 1) * chunk); ++i) {
      const Vec3d p =
          lo + ext * Vec3d(rng.uniformDouble(), rng.uniformDouble(), rng.uniformDouble());
      const bool inside = in_input(cgal::Point3(p.x, p.y, p.z)) == CGAL::ON_BOUNDED_SIDE;
      bool covered = false;
      if (in_other) {
        covered = (*in_other)(cgal::Point3(p.x, p.y, p.z)) == CGAL::ON_BOUNDED_SIDE;
      } else {
        for (const auto& h : hulls)
          if (insideConvex(h, p)) {
            covered = true;
            break;
          }
      }
      a += inside;
      b += covered;
      u += inside && !covered;
    }
    n_input += a;
    n_cover += b;
    n_uncovered += u;
  });
  const double box_volume = ext.x * ext.y * ext.z;
  const double share = n_input ? double(n_uncovered) / double(n_input) : 0;
  fmt::print(
      "{{\"input\": \"{}\", \"samples\": {}, \"seed\": {}, \"pieces\": {}, "
      "\"input_volume\": {:.6g}, \"cover_volume\": {:.6g}, \"volume_ratio\": {:.5f}, "
      "\"uncovered_share\": {:.6f}, \"uncovered_share_stderr\": {:.6f}, \"uncovered_samples\": "
      "{}}}\n",
      input.source, samples, seed, in_other ? 1 : hulls.size(),
      box_volume * double(n_input) / double(samples),
      box_volume * double(n_cover) / double(samples),
      n_input ? double(n_cover) / double(n_input) : 0.0, share,
      n_input ? std::sqrt(share * (1 - share) / double(n_input)) : 0.0, n_uncovered.load());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const Error& e) {
    fmt::print(stderr, "bench_cover: {}\n", e.what());
    return 2;
  }
}
