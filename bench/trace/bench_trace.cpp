// Shadow-segment throughput of the lib/trace wrapper next to a bare Embree rtcOccluded1 loop on the
// same segments with the same tbb::parallel_for structure. Endpoints are uniform in a
// box around the scene: incoherent rays, the distribution of the reference numbers
// (dragon 6.7 Mrays/s, dragon x1000 instanced 3.9 Mrays/s, 2 threads, Embree 3.13.5).
//
// Columns: bare = own Embree scene (default flags and build quality) traced by rtcOccluded1;
// bare on wrapper's BVH = the same loop on TraceScene::handle() (isolates the call overhead from
// the wrapper's build flags); ratios are against the faster of the two bare loops;
// batch = TraceScene::occluded(span); single = TraceScene::occluded(Segment) once per segment
// inside the same parallel_for; ignore = batch with an ignore_user_id that matches nothing, with
// the scene's default strategy (kAuto: kFilter for the flattened dragon, kMaskThenFilter for the
// instances). Then self-shadowing tables compare the ignore strategies on segments that start on
// an object's surface.
#include <embree3/rtcore.h>
#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <string>
#include <vector>

#include "bench_trace_scenes.h"
#include "mesh/io/mesh_io.h"
#include "trace/internal/embree_ray.h"
#include "trace/trace_scene.h"
#include "util/app_main.h"
#include "util/error.h"
#include "util/rng.h"
#include "util/stopwatch.h"

namespace pv = proxyvis;

namespace {

using namespace pv::trace_bench;

// Throughput of one traced batch by the wall clock and by the process's CPU time. The machine
// may be shared: other processes steal whole time slices, which the wall clock counts and CPU
// time does not, so ratios are also given from CPU time (rays per CPU-second).
struct Rate {
  double wall = 0, cpu = 0;  // Mrays/s, best so far
};

double cpuSeconds() {
  timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

template <typename F>
void measure(Rate& best, size_t n, F&& trace) {
  const pv::Stopwatch watch;
  double c0 = cpuSeconds();
  trace();
  double cpu = cpuSeconds() - c0;
  double wall = watch.seconds();
  best.wall = std::max(best.wall, double(n) / wall / 1e6);
  best.cpu = std::max(best.cpu, double(n) / cpu / 1e6);
}

// Self-shadowing: segments that leave the surface of instance k towards a random point, traced
// while ignoring k. Compared: the wrapper's two exact strategies (IgnoreStrategy::kFilter and
// kMaskThenFilter, on scenes with the same BVH settings); a bare loop with ray masks
// (bit k % 32 cleared: exact only with at most 32 objects, here it also hides every 32nd other
// instance); the classic origin offset (tnear = 1e-4 of the diagonal, no ignoring); and neither
// (the ray finds its own surface at t ~ 0).
// occluded(segs[i], owner[i]) for all i, single calls in the usual parallel_for.
void ignoring(const pv::TraceScene& scene, const std::vector<pv::Segment>& segs,
              const std::vector<uint32_t>& owner, std::vector<uint8_t>& out) {
  tbb::parallel_for(tbb::blocked_range<size_t>(0, segs.size(), kChunk), [&](const auto& r) {
    for (size_t i = r.begin(); i != r.end(); ++i) out[i] = scene.occluded(segs[i], owner[i]);
  });
}

// The renderer's case: the same segments (leaving dragon k's surface) traced against proxies,
// here each dragon's bounding box (12 triangles, a crude outside proxy), instanced or flattened,
// ignoring dragon k's proxy, which contains the segment's start.
void proxySelfShadowTable(const pv::TriMesh& mesh, const std::vector<pv::Affine3f>& xfs,
                          const std::vector<pv::Segment>& segs, const std::vector<uint32_t>& owner,
                          pv::TraceDevice& device, const Options& o) {
  const pv::Bounds3f b = mesh.bounds();
  pv::TriMesh box;
  for (int i = 0; i < 8; ++i)
    box.vertices.push_back(
        {(i & 1) ? b.hi.x : b.lo.x, (i & 2) ? b.hi.y : b.lo.y, (i & 4) ? b.hi.z : b.lo.z});
  box.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                   {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  box.source = "bounding box";
  std::printf(
      "\nSelf-shadowing against proxies (each dragon's bounding box), same segments\n\n"
      "| proxies | kFilter Mrays/s | kMaskThenFilter Mrays/s | CPU-time ratio mask / filter | "
      "answers differing |\n|---|---:|---:|---:|---:|\n");
  for (bool instanced : {true, false}) {
    auto build = [&](pv::IgnoreStrategy strategy) {
      pv::TraceSceneOptions options;
      options.ignore = strategy;
      pv::TraceSceneBuilder builder(device, options);
      uint32_t proto = builder.addPrototype(box);
      for (uint32_t i = 0; i < xfs.size(); ++i) {
        if (instanced) {
          builder.addInstance(proto, xfs[i], i);
        } else {
          pv::TriMesh placed = box;
          for (pv::Vec3f& v : placed.vertices) v = xfs[i].apply(v);
          builder.addMesh(placed, i);
        }
      }
      return builder.build();
    };
    auto filter_scene = build(pv::IgnoreStrategy::kFilter);
    auto mask_scene = build(pv::IgnoreStrategy::kMaskThenFilter);
    std::vector<uint8_t> filter_out(segs.size()), mask_out(segs.size());
    Rate filter, mask;
    for (int rep = 0; rep < o.reps; ++rep) {
      measure(filter, segs.size(), [&] { ignoring(*filter_scene, segs, owner, filter_out); });
      measure(mask, segs.size(), [&] { ignoring(*mask_scene, segs, owner, mask_out); });
    }
    size_t differ = 0;
    for (size_t i = 0; i < segs.size(); ++i) differ += filter_out[i] != mask_out[i];
    std::printf("| %zu boxes, %s | %.2f | %.2f | %.0f %% | %zu |\n", xfs.size(),
                instanced ? "instanced" : "flattened", filter.wall, mask.wall,
                100 * mask.cpu / filter.cpu, differ);
  }
}

void selfShadowTable(BenchScene& s, const pv::TriMesh& mesh, pv::TraceDevice& device,
                     const Options& o) {
  const pv::TraceScene& scene = *s.wrapped;
  const size_t n = std::max<size_t>(1, o.rays / 4);
  auto probes = makeSegments(scene.bounds(), n, 77);
  auto targets = makeSegments(scene.bounds(), n, 78);
  std::vector<pv::Segment> segs(n);
  std::vector<uint32_t> owner(n, pv::kIgnoreNone);
  tbb::parallel_for(size_t(0), n, [&](size_t i) {
    pv::Hit h = scene.intersect(probes[i]);
    if (!h.hit) return;
    pv::Vec3f p = probes[i].org + probes[i].dir * h.t;
    segs[i] = {p, 0.0f, targets[i].org - p, 1.0f};
    owner[i] = h.user_id;
  });
  size_t k = 0;  // keep the probes that hit something
  for (size_t i = 0; i < n; ++i)
    if (owner[i] != pv::kIgnoreNone) {
      segs[k] = segs[i];
      owner[k++] = owner[i];
    }
  segs.resize(k);
  owner.resize(k);
  const float offset = 1e-4f * scene.bounds().diagonal();
  // The same instanced scene, built once per strategy.
  const auto xfs = gridTransforms(mesh, o.instances);
  auto build = [&](pv::IgnoreStrategy strategy) {
    pv::TraceSceneOptions options;
    options.robust = o.robust;
    options.high_quality = o.high_quality;
    options.ignore = strategy;
    pv::TraceSceneBuilder builder(device, options);
    const uint32_t proto = builder.addPrototype(mesh);
    for (uint32_t i = 0; i < xfs.size(); ++i) builder.addInstance(proto, xfs[i], i);
    return builder.build();
  };
  auto filter_scene = build(pv::IgnoreStrategy::kFilter);
  auto two_pass_scene = build(pv::IgnoreStrategy::kMaskThenFilter);
  std::vector<uint8_t> filter_out(k), two_out(k), mask_out(k), offset_out(k), naive_out(k);
  Rate filter, two, mask, offs, naive;
  auto perSegment = [&](auto&& body) {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, k, kChunk), [&](const auto& r) {
      for (size_t i = r.begin(); i != r.end(); ++i) body(i);
    });
  };
  for (int rep = 0; rep < o.reps; ++rep) {
    measure(filter, k, [&] { ignoring(*filter_scene, segs, owner, filter_out); });
    measure(two, k, [&] { ignoring(*two_pass_scene, segs, owner, two_out); });
    measure(mask, k, [&] {
      tbb::parallel_for(tbb::blocked_range<size_t>(0, k, kChunk), [&](const auto& r) {
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        for (size_t i = r.begin(); i != r.end(); ++i) {
          RTCRay ray = pv::detail::toRtcRay(segs[i], ~(1u << (owner[i] % 32)));
          rtcOccluded1(s.bare, &ctx, &ray);
          mask_out[i] = ray.tfar < 0.0f;
        }
      });
    });
    measure(offs, k, [&] {
      perSegment([&](size_t i) {
        pv::Segment g = segs[i];
        g.tnear = offset / pv::length(g.dir);
        offset_out[i] = scene.occluded(g);
      });
    });
    measure(naive, k,
            [&] { perSegment([&](size_t i) { naive_out[i] = scene.occluded(segs[i]); }); });
  }
  auto count = [&](const std::vector<uint8_t>& v) {
    size_t c = 0;
    for (uint8_t x : v) c += x;
    return c;
  };
  auto differ = [&](const std::vector<uint8_t>& v) {
    size_t c = 0;
    for (size_t i = 0; i < k; ++i) c += v[i] != filter_out[i];
    return c;
  };
  std::printf(
      "\nSelf-shadowing on %s: %zu segments leaving instance k's surface, 2 threads\n\n"
      "| method | Mrays/s | CPU-time ratio to kFilter | occluded | answers differing from "
      "kFilter |\n|---|---:|---:|---:|---:|\n",
      s.name.c_str(), k);
  auto row = [&](const char* name, const Rate& r, const std::vector<uint8_t>& v) {
    std::printf("| %s | %.2f | %.0f %% | %.1f %% | %zu |\n", name, r.wall, 100 * r.cpu / filter.cpu,
                100.0 * double(count(v)) / double(k), differ(v));
  };
  row("ignore_user_id, kFilter (exact)", filter, filter_out);
  row("ignore_user_id, kMaskThenFilter (exact)", two, two_out);
  row("ray mask, bit k % 32 (bare Embree; not exact)", mask, mask_out);
  row("origin offset 1e-4 diag, no ignoring", offs, offset_out);
  row("no offset, no ignoring", naive, naive_out);
  proxySelfShadowTable(mesh, xfs, segs, owner, device, o);
}

int run(Options& o) {
  if (o.mesh.empty()) o.mesh = (std::filesystem::path(PROXYVIS_DATA_DIR) / "dragon.drc").string();
  pv::TriMesh mesh = pv::loadMesh(o.mesh);
  std::printf(
      "mesh %s: %zu triangles; %llu segments, best of %d; wrapper %s, %s quality\n"
      "Mrays/s by the wall clock; ratios by the wall clock / by CPU time against the "
      "faster bare loop\n\n",
      o.mesh.c_str(), mesh.numTriangles(), (unsigned long long)o.rays, o.reps,
      o.robust ? "robust" : "not robust", o.high_quality ? "high" : "medium");

  pv::TraceDevice device;
  std::vector<BenchScene> scenes;
  scenes.push_back(flatScene(device, mesh, o));
  scenes.push_back(instanceScene(device, mesh, o));
  device.throwIfError("building the benchmark scenes");

  std::printf(
      "| scene | threads | bare Mrays/s | bare on wrapper's BVH | wrapper batch Mrays/s | ratio "
      "wall / CPU | wrapper single Mrays/s | ratio | batch + ignore (kAuto) Mrays/s | ratio | "
      "occluded |\n"
      "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (BenchScene& s : scenes) {
    auto segs = makeSegments(s.wrapped->bounds(), o.rays, 2014);
    std::vector<uint8_t> bare_out(segs.size()), out(segs.size()), single_out(segs.size()),
        ignore_out(segs.size());
    for (int threads : {1, 2}) {
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
      // The variants take turns, repetition by repetition, so that load from other processes
      // hits them alike; the best repetition of each is reported.
      Rate bare, bare_same, batch, single, ignore;
      const size_t n = segs.size();
      for (int rep = 0; rep < o.reps; ++rep) {
        measure(bare, n, [&] { bareOccluded(s.bare, segs, bare_out); });
        measure(bare_same, n, [&] { bareOccluded(s.wrapped->handle(), segs, single_out); });
        measure(batch, n, [&] { s.wrapped->occluded(segs, out); });
        measure(single, n, [&] {
          tbb::parallel_for(tbb::blocked_range<size_t>(0, n, kChunk), [&](const auto& r) {
            for (size_t i = r.begin(); i != r.end(); ++i)
              single_out[i] = s.wrapped->occluded(segs[i]);
          });
        });
        measure(ignore, n, [&] { s.wrapped->occluded(segs, ignore_out, 123456789u); });
      }
      // Same answers expected; the wrapper's scene has other flags and build quality, so a
      // segment grazing an edge could differ: count rather than assume.
      size_t differ = 0, occluded = 0;
      for (size_t i = 0; i < segs.size(); ++i) {
        differ += (bare_out[i] != out[i]) + (out[i] != single_out[i]) + (out[i] != ignore_out[i]);
        occluded += out[i];
      }
      // Ratios against the faster of the two bare loops: the strictest reading of the target.
      const Rate ref{std::max(bare.wall, bare_same.wall), std::max(bare.cpu, bare_same.cpu)};
      auto ratio = [&](const Rate& r) {
        return std::to_string(int(std::lround(100 * r.wall / ref.wall))) + " / " +
               std::to_string(int(std::lround(100 * r.cpu / ref.cpu))) + " %";
      };
      std::printf("| %s | %d | %.2f | %.2f | %.2f | %s | %.2f | %s | %.2f | %s | %.1f %%%s |\n",
                  s.name.c_str(), threads, bare.wall, bare_same.wall, batch.wall,
                  ratio(batch).c_str(), single.wall, ratio(single).c_str(), ignore.wall,
                  ratio(ignore).c_str(), 100.0 * double(occluded) / double(n),
                  differ ? (" (" + std::to_string(differ) + " answers differ)").c_str() : "");
      std::fflush(stdout);
    }
  }
  selfShadowTable(scenes.back(), mesh, device, o);
  for (BenchScene& s : scenes) {
    rtcReleaseScene(s.bare);
    for (RTCScene p : s.bare_prototypes) rtcReleaseScene(p);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  pv::CommonOptions common;
  CLI::App app{"bench_trace: shadow-segment throughput, lib/trace wrapper vs bare Embree"};
  pv::addCommonOptions(app, common);
  app.add_option("--rays", o.rays, "segments per measurement")->capture_default_str();
  app.add_option("--instances", o.instances, "instances in the instanced scene")
      ->capture_default_str();
  app.add_option("--reps", o.reps, "repetitions; the best is reported")->capture_default_str();
  app.add_option("--mesh", o.mesh, "mesh (default: data/dragon.drc)");
  app.add_flag("--robust", o.robust, "wrapper scenes with RTC_SCENE_FLAG_ROBUST");
  app.add_flag("!--medium-quality", o.high_quality, "wrapper scenes with RTC_BUILD_QUALITY_MEDIUM");
  return pv::runApp(app, argc, argv, common, [&] { return run(o); });
}
