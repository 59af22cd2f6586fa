#include "proxies/scene/scene_mesh.h"

#include <fmt/core.h>

#include "mesh/io/mesh_io.h"
#include "mesh/io/sha256_sidecar.h"
#include "proxies/shared/parity_solid.h"
#include "util/error.h"
#include "util/input_file.h"
#include "util/output_set.h"
#include "util/sha256.h"
#include "util/stopwatch.h"

namespace fs = std::filesystem;

namespace proxyvis {

namespace {

// A generated proxy, or why the mesh gets none.
struct Generated {
  ProxyReport report;
  TriMesh proxy;
  std::string skipped;
  uint64_t input_faces = 0;  // when skipped
};

Generated generate(const std::string& bytes, const SceneMeshDesc& mesh, ProxyGenOptions o) {
  const Stopwatch load_clock;
  const TriMesh input = parseSceneMeshBytes(bytes, mesh);
  const double load_seconds = load_clock.seconds();
  Generated g;
  // A proxy only pays if it has fewer faces than its original; no closed mesh has fewer than 4,
  // so a smaller original (a ground quad) is skipped without trying.
  if (input.numTriangles() < 4) {
    g.skipped = fmt::format("{} faces: no closed proxy can have fewer", input.numTriangles());
    g.input_faces = input.numTriangles();
    return g;
  }
  const bool open = !parityVolume(input).has_value();
  if (open && o.kind == ProxyClass::kInside && !o.fill_holes) {
    // In a scene this is a property of the mesh (foliage), not a mistake: the others go on.
    g.skipped =
        "open: it bounds no volume, so it has no inside proxy (--fill-holes makes a "
        "general one)";
    g.input_faces = input.numTriangles();
    return g;
  }
  const bool wrap = o.method.empty() || o.method == "wrap";
  if (open && o.kind == ProxyClass::kOutside && wrap && !o.alpha && !o.offset) {
    o.alpha = kOpenMeshWrapAlpha;
    o.offset = kOpenMeshWrapOffset;
  }
  // The proof also holds for the file read in double (a text file's decimals; a glTF mesh of
  // the file stores floats).
  std::vector<Vec3d> input_double;
  if (mesh.gltf_mesh < 0) addDoubleReading(o, mesh.file, input, input_double);
  ProxyGenResult r = generateProxy(input, o);
  addLoadSeconds(r.report, load_seconds);
  if (r.proxy.numTriangles() >= input.numTriangles()) {
    g.skipped = fmt::format("its {} proxy has {} faces, the original {}: not cheaper",
                            proxyClassName(o.kind), r.proxy.numTriangles(), input.numTriangles());
    g.input_faces = input.numTriangles();
    return g;
  }
  g.report = std::move(r.report);
  g.proxy = std::move(r.proxy);
  return g;
}

}  // namespace

ProxyRef proxyRefFor(const ProxyReport& report, ProxyClass kind, const fs::path& out,
                     const std::string& proxy_bytes) {
  ProxyRef ref;
  ref.kind = proxyClassName(kind);
  ref.method = report.method;
  ref.file = fs::absolute(out);
  // The class the report writes (general when proven only for a stand-in of the input); the
  // hash says which file content it was proven for: the bytes written.
  if (const std::optional<ProxyClass> c = report.written_class) {
    ref.verified_class = c;
    ref.sha256 = sha256Hex(proxy_bytes);
  }
  return ref;
}

namespace {

// The scene's own budget for a mesh ("proxy_max_faces") replaces the run's --max-faces and
// --ratio; everything else is the run's.
ProxyGenOptions meshOptions(const SceneMeshDesc& mesh, const ProxyGenOptions& run) {
  ProxyGenOptions o = run;
  if (mesh.proxy_max_faces) {
    o.max_faces = *mesh.proxy_max_faces;
    o.ratio.reset();
  }
  return o;
}

}  // namespace

SceneMeshProxy proxyForSceneMesh(const SceneMeshDesc& mesh, const ProxyGenOptions& run_options,
                                 const fs::path& out, const ProxyCache* cache) {
  const ProxyGenOptions options = meshOptions(mesh, run_options);
  SceneMeshProxy result;
  if (!mesh.make_proxy) {
    result.skipped = "\"make_proxy\": false in the scene";
    result.report.name = mesh.name;
    result.report.skipped = result.skipped;
    return result;
  }
  // The bytes are hashed for the cache key and parsed from memory on a miss: read once.
  const std::string bytes = readTextFile(mesh.file);
  verifySidecar(mesh.file, bytes);
  std::string key;
  std::optional<CachedProxy> entry;
  if (cache) {
    key = proxyCacheKey(sceneMeshContentKey(sha256Hex(bytes), mesh), proxyCacheSettings(options));
    std::string damage;
    entry = cache->find(key, &damage);
    if (!damage.empty())
      result.cache_note = fmt::format("cache entry {} was damaged ({}): generated again",
                                      key.substr(0, 12), damage);
  }
  std::string state = cache ? "cached" : "off";
  if (!entry) {
    Generated g = generate(bytes, mesh, options);
    entry.emplace();
    if (!g.skipped.empty()) {
      entry->report.faces = g.input_faces;
      entry->report.skipped = g.skipped;
    } else {
      saveMesh(g.proxy, out);
      const std::optional<std::string> written = readOwnFileBytes(out);
      if (!written) throw WriteError(out.string(), "cannot read back the proxy just written");
      entry->report.proxy = std::move(g.report);
      entry->proxy_bytes = *written;
    }
    if (cache) {
      state = "generated";
      try {
        cache->store(key, *entry);
      } catch (const Error& e) {
        // The proxy is written and good; only the next run will have to build it again.
        result.cache_note = fmt::format("not stored in the cache: {}", e.what());
      }
    }
  } else if (!entry->report.skipped) {
    OutputSet outputs;
    addEncodedMeshOutput(outputs, entry->proxy_bytes, out);
    outputs.commit();
  }
  result.report = std::move(entry->report);
  result.report.name = mesh.name;
  result.report.cache = state;
  if (result.report.skipped) {
    result.skipped = *result.report.skipped;
    return result;
  }
  ProxyReport& proxy = *result.report.proxy;
  // An entry made from the same bytes elsewhere: the report names this scene's file.
  proxy.input.path = mesh.file.string();
  proxy.output = out.string();
  result.ref = proxyRefFor(proxy, options.kind, out, entry->proxy_bytes);
  return result;
}

}  // namespace proxyvis
