// Re-verification of claimed proxy classes (see class_trust.h).
#include "proxies/check/class_trust.h"

#include <fmt/core.h>

#include <cstdio>
#include <optional>

#include "mesh/io/mesh_io.h"
#include "proxies/check/scene_segments.h"
#include "render/render_scene.h"
#include "render/scene_assembly.h"
#include "scene/scene_desc.h"
#include "util/sha256.h"

namespace proxyvis {

const char* classStatusName(ClassStatus s) {
  switch (s) {
    case ClassStatus::kUnverified:
      return "unverified";
    case ClassStatus::kGeneral:
      return "general";
    case ClassStatus::kVerifiedByHash:
      return "verified-by-hash";
    case ClassStatus::kReVerified:
      return "re-verified";
    case ClassStatus::kDowngraded:
      return "downgraded";
  }
  return "unverified";
}

ClassTrust decideClassTrust(std::optional<ProxyClass> claimed, std::string_view recorded_hash,
                            std::string_view file_hash,
                            const std::function<ContainmentResult()>& check) {
  if (!claimed) return {ClassStatus::kUnverified, ProxyClass::kGeneral, "no class claimed"};
  if (*claimed == ProxyClass::kGeneral) return {ClassStatus::kGeneral, ProxyClass::kGeneral, {}};
  if (!recorded_hash.empty() && recorded_hash == file_hash)
    return {ClassStatus::kVerifiedByHash, *claimed, {}};
  const std::string why = recorded_hash.empty()
                              ? "no recorded sha256"
                              : "the file changed since its class was verified (sha256 differs)";
  const ContainmentVerdict needed = *claimed == ProxyClass::kOutside
                                        ? ContainmentVerdict::kContains
                                        : ContainmentVerdict::kContained;
  const ContainmentResult r = check();
  const std::string found = fmt::format("exact check: {}{}{}", containmentName(r.verdict),
                                        r.detail.empty() ? "" : ", ", r.detail);
  if (r.verdict == needed) return {ClassStatus::kReVerified, *claimed, why + "; " + found};
  return {ClassStatus::kDowngraded, ProxyClass::kGeneral,
          fmt::format("{}; {} (an {} proxy must give '{}')", why, found, proxyClassName(*claimed),
                      containmentName(needed))};
}

ClassTrust decideProxyTrust(const ProxyRef& ref, const std::function<ContainmentResult()>& check) {
  const bool claims_guarantee = ref.verified_class && *ref.verified_class != ProxyClass::kGeneral;
  // Only a claim of a guarantee needs the file's hash (reading a large proxy is not free).
  const std::string file_hash = claims_guarantee ? sha256OfFile(ref.file) : std::string();
  return decideClassTrust(ref.verified_class, ref.sha256, file_hash, check);
}

namespace {

// A trusted outside/inside class of a mesh placed with a transform, checked again on the placed
// float copies the renderer traces; downgraded when it does not hold there.
void verifyPlaced(const Affine3f& transform, const TriMesh& original, const TriMesh& proxy,
                  ProxyTrust& t) {
  const ProxyClass claimed = t.trust.trusted;
  // transformedMesh maps the vertices in float as the tracer's addMesh does.
  const ContainmentResult r =
      checkContainment(transformedMesh(original, transform), transformedMesh(proxy, transform));
  t.verified_on = "placed float copies";
  const std::string found = fmt::format("exact check on the placed float copies: {}, {}",
                                        containmentName(r.verdict), r.detail);
  if (r.verdict == expectedVerdict(claimed)) {
    t.trust.reason += (t.trust.reason.empty() ? "" : "; ") + found;
    return;
  }
  t.trust = {ClassStatus::kDowngraded, ProxyClass::kGeneral,
             fmt::format("{} in object space, but {} (an {} proxy must give '{}')",
                         classStatusName(t.trust.status), found, proxyClassName(claimed),
                         containmentName(expectedVerdict(claimed)))};
}

}  // namespace

std::vector<ProxyTrust> establishProxyClasses(SceneDesc& scene, const RenderSceneOptions& options) {
  std::vector<bool> used(scene.meshes.size(), false);
  for (size_t m = 0; m < scene.meshes.size(); ++m) used[m] = scene.meshes[m].place;
  for (const SceneInstanceDesc& i : scene.instances) used[i.mesh] = true;
  std::vector<ProxyTrust> out;
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    SceneMeshDesc& mesh = scene.meshes[m];
    const int chosen = requestedProxy(mesh, options);
    if (!used[m] || chosen < 0) continue;
    ProxyRef& ref = mesh.proxies[size_t(chosen)];
    ProxyTrust t{mesh.name, ref.file, ref.verified_class, {}};
    // Exactly, the containment relation does not change under an affine invertible transform,
    // so the check runs on the files as they are, in object space. An instance is traced through
    // its transform (the ray is mapped, not the mesh); a placed mesh is traced as float copies of
    // its placed vertices, rounded again, so a class that stands is checked on those as well.
    std::optional<TriMesh> original, proxy;  // read when a check needs them, once
    auto load = [&] {
      if (original) return;
      original = loadSceneMesh(mesh);
      proxy = loadMesh(ref.file);
    };
    t.trust = decideProxyTrust(ref, [&] {
      load();
      return checkContainment(*original, *proxy);
    });
    if (t.trust.trusted != ProxyClass::kGeneral && mesh.place && !mesh.transform.isIdentity()) {
      load();
      verifyPlaced(mesh.transform, *original, *proxy, t);
    }
    if (ref.verified_class) ref.verified_class = t.trust.trusted;
    out.push_back(std::move(t));
  }
  return out;
}

std::string describeProxyTrust(const ProxyTrust& t) {
  const std::string head = fmt::format(
      "mesh '{}': proxy {}, claimed {}: {}", t.mesh, t.proxy.filename().string(),
      t.claimed ? proxyClassName(*t.claimed) : "no class", classStatusName(t.trust.status));
  if (t.trust.status == ClassStatus::kDowngraded)
    return head + " to general (" + t.trust.reason + ")";
  if (t.verified_on != "object space")
    return head + ", on the " + t.verified_on + " (" + t.trust.reason + ")";
  return t.trust.reason.empty() || t.trust.status == ClassStatus::kUnverified
             ? head
             : head + " (" + t.trust.reason + ")";
}

TrustedRenderScene loadTrustedRenderScene(SceneDesc& scene, const RenderSceneOptions& options,
                                          std::string_view program) {
  TrustedRenderScene out;
  out.trust = establishProxyClasses(scene, options);
  for (const ProxyTrust& t : out.trust)
    if (t.trust.status == ClassStatus::kDowngraded)
      std::fprintf(stderr, "%.*s: warning: %s: %s\n", int(program.size()), program.data(),
                   scene.path.filename().string().c_str(), describeProxyTrust(t).c_str());
  out.scene = loadRenderScene(scene, options);
  return out;
}

void requireProvedClass(const SceneMeshDesc& mesh, const ProxyRef& ref, ProxyClass expected,
                        const std::string& relies) {
  const std::string file = ref.file.string();
  const ClassTrust trust = decideProxyTrust(ref, [&]() -> ContainmentResult {
    throw Error(file,
                fmt::format("the {} class of mesh '{}''s proxy was not proved for this file",
                            proxyClassName(expected), mesh.name),
                ref.sha256.empty() ? "the scene records no sha256 for it"
                                   : "the file's sha256 differs from the one recorded",
                "prove it again: proxy-check SCENE --write-scene OUT");
  });
  if (trust.trusted != expected)
    throw Error(file,
                fmt::format("{} proxy of mesh '{}' has no proved {} class in the scene", ref.kind,
                            mesh.name, proxyClassName(expected)),
                relies,
                "generate it with proxy-gen, or prove it with proxy-check SCENE --write-scene OUT");
}

}  // namespace proxyvis
