// Throughput of the ray-sampled classification: segments traced against an original and a proxy
// (occlusion, batches of 64 k), at 1 and 2 threads. Prints a table; never fails on speed.
//
//   bench_proxy_check [ORIGINAL [PROXY ...]] [--rays N]
// Without arguments: the bundled dragon (data/dragon.drc) against its bounding box and the proxies
// proxy-gen makes by default (outside hull and wrap, inside wrap, general QEM at 2 %), plus every
// PROXY given.
#include <fmt/core.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "mesh/io/mesh_io.h"
#include "mesh/primitives.h"
#include "proxies/check/ray_classify.h"
#include "proxies/pipeline/proxy_pipeline.h"
#include "util/error.h"

using namespace proxyvis;

namespace {

TriMesh boundingBox(const Bounds3f& b) {
  const Vec3f e = b.extent() * 0.01f;
  return makeBoxMesh(b.lo - e, b.hi + e, "bounding box (12 faces)");
}

// UV sphere circumscribing the box (its faces stay outside a sphere of radius r cos(pi/n)).
TriMesh enclosingSphereMesh(const Bounds3f& b, int slices = 45, int stacks = 23) {
  const float pi = std::numbers::pi_v<float>;
  const float r =
      0.5f * b.diagonal() / (std::cos(pi / float(slices)) * std::cos(pi / float(stacks)));
  TriMesh m = makeUvSphere(b.center(), r, slices, stacks);
  m.source = fmt::format("enclosing sphere ({} faces)", m.triangles.size());
  return m;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    uint64_t rays = 2'000'000;
    std::vector<std::string> paths;
    for (int i = 1; i < argc; ++i) {
      if (std::strcmp(argv[i], "--rays") == 0 && i + 1 < argc)
        rays = std::stoull(argv[++i]);
      else
        paths.push_back(argv[i]);
    }
    const std::string original_path =
        paths.empty() ? std::string(PROXYVIS_DATA_DIR) + "/dragon.drc" : paths[0];
    const TriMesh original = loadMesh(original_path);
    std::vector<TriMesh> proxies;
    proxies.push_back(boundingBox(original.bounds()));
    proxies.push_back(enclosingSphereMesh(original.bounds()));
    if (paths.empty()) {
      const std::pair<ProxyClass, const char*> made[] = {{ProxyClass::kOutside, "hull"},
                                                         {ProxyClass::kOutside, "wrap"},
                                                         {ProxyClass::kInside, "wrap"},
                                                         {ProxyClass::kGeneral, "qem"}};
      for (const auto& [kind, method] : made) {
        ProxyGenOptions o;
        o.kind = kind;
        o.method = method;
        TriMesh p = generateProxy(original, o).proxy;
        p.source = fmt::format("{} {}", proxyClassName(kind), method);
        proxies.push_back(std::move(p));
      }
    }
    for (size_t i = 1; i < paths.size(); ++i) proxies.push_back(loadMesh(paths[i]));

    TraceDevice device;
    auto build = [&](const TriMesh& m) {
      TraceSceneBuilder b(device);
      b.addMesh(m);
      return b.build();
    };
    auto original_scene = build(original);
    fmt::print("original: {} ({} faces), {} segments per run, sphere distribution\n\n",
               original_path, original.numTriangles(), rays);
    fmt::print(
        "| proxy | faces | threads | M segments/s | ns/seg proxy | ns/seg original | c_p/c_o | HM' "
        "| MH' |\n");
    fmt::print("|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const TriMesh& proxy : proxies) {
      auto proxy_scene = build(proxy);
      const Sphere sphere = enclosingSphere(original.bounds(), proxy.bounds());
      for (int threads : {1, 2}) {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
        ClassifyOptions o;
        o.segments = rays;
        o.quiet = true;
        classifySegments(*original_scene, *proxy_scene, sphereSegments(sphere, 99),
                         ClassifyOptions{.segments = 65536, .quiet = true});  // warm-up
        const Classification c =
            classifySegments(*original_scene, *proxy_scene, sphereSegments(sphere, 0), o);
        const double n = double(c.counts.total());
        fmt::print("| {} | {} | {} | {:.2f} | {:.1f} | {:.1f} | {:.3f} | {} | {} |\n", proxy.source,
                   proxy.numTriangles(), threads, n / c.seconds / 1e6, 1e9 * c.seconds_proxy / n,
                   1e9 * c.seconds_original / n, c.costRatio(), c.counts.hm, c.counts.mh);
      }
    }
    return 0;
  } catch (const Error& e) {
    fmt::print(stderr, "bench_proxy_check: error: {}\n", e.what());
    return 2;
  }
}
