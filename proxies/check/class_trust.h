#pragma once
// Whether the class a scene claims for a proxy may be relied on by the estimators. A class is
// trusted as recorded only while the proxy file still has the SHA-256 it was verified for;
// otherwise the exact containment check (containment.h) decides again, in object space, and a
// class it does not prove is downgraded to general. An estimator told "outside" drops the
// correction branch for HM' segments: a mislabelled proxy would bias it silently.
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "proxies/check/containment.h"
#include "util/proxy_class.h"

namespace proxyvis {

struct SceneDesc;
struct SceneMeshDesc;
struct ProxyRef;
struct RenderSceneOptions;
class RenderScene;

enum class ClassStatus {
  kUnverified,      // the scene claims no class: general
  kGeneral,         // the scene claims general: nothing to verify
  kVerifiedByHash,  // the recorded hash matches the file: the claim stands unchecked
  kReVerified,      // no or another hash; the exact check proves the claim again
  kDowngraded       // no or another hash; the exact check does not prove the claim: general
};

// "unverified", "general", "verified-by-hash", "re-verified", "downgraded".
const char* classStatusName(ClassStatus s);

struct ClassTrust {
  ClassStatus status = ClassStatus::kUnverified;
  ProxyClass trusted = ProxyClass::kGeneral;  // what the estimators may use
  std::string reason;                         // why, for re-verified and downgraded
};

// The decision. `recorded_hash` is the scene's (empty = none), `file_hash` the proxy file's;
// `check` runs the exact containment check and is called only when the hash does not vouch for
// an outside or inside claim.
ClassTrust decideClassTrust(std::optional<ProxyClass> claimed, std::string_view recorded_hash,
                            std::string_view file_hash,
                            const std::function<ContainmentResult()>& check);

// The trust of a scene's proxy entry: decideClassTrust() with the claim and hash recorded in
// `ref` and the file's own hash (read only for an outside or inside claim). Both renderers decide
// by it; they differ in `check`. The single-process one passes the exact containment check of the
// original and the proxy (establishProxyClasses), so a class the hash no longer vouches for is
// re-verified or downgraded. The data-parallel one cannot run it: a rank holds only its own
// originals and the decision must be the same on every rank; its check refuses the scene
// (lib/distributed/distributed_scene.cpp), and proxy-check --write-scene records the hash again.
ClassTrust decideProxyTrust(const ProxyRef& ref, const std::function<ContainmentResult()>& check);

// For the renderers that cannot re-verify a class (the data-parallel one: a rank holds only its
// own originals, and every rank must trust the same proxies; the out-of-core one: the originals
// are on disk): the proxy must have the class `expected`, trusted by decideProxyTrust on its
// recorded hash alone. Otherwise throws Error naming the file, with `relies` (what decides by the
// class) as the reason and how to prove it.
void requireProvedClass(const SceneMeshDesc& mesh, const ProxyRef& ref, ProxyClass expected,
                        const std::string& relies);

struct ProxyTrust {
  std::string mesh;             // the mesh's name
  std::filesystem::path proxy;  // the proxy file
  std::optional<ProxyClass> claimed;
  ClassTrust trust;
  // Where the trusted class was verified: "object space" (the files as they are; an instance
  // traced through its transform), or "placed float copies" (a mesh placed with a transform is
  // traced as its vertices mapped to world space in float, which rounds both meshes again: the
  // class is checked on exactly those copies).
  std::string verified_on = "object space";
};

// For every proxy the renderer will use under `options` (one per mesh that is placed or
// instanced): decides its trust, loading the original and the proxy only when the exact check
// must run, and sets the scene's verified_class to the trusted class (general when downgraded).
// Throws Error for unreadable files.
std::vector<ProxyTrust> establishProxyClasses(SceneDesc& scene, const RenderSceneOptions& options);

// One line for a log or a report: "mesh 'box': proxy box.outside.off, claimed outside:
// downgraded to general (no recorded sha256; exact check: intersecting, ...)".
std::string describeProxyTrust(const ProxyTrust& t);

// What the rendering programs (render, render-compare) load: the classes established as above,
// every downgrade said on stderr as "<program>: warning: <scene>: ..." (always: the images would
// hide the bias), then the render scene.
struct TrustedRenderScene {
  std::vector<ProxyTrust> trust;
  std::unique_ptr<RenderScene> scene;
};
TrustedRenderScene loadTrustedRenderScene(SceneDesc& scene, const RenderSceneOptions& options,
                                          std::string_view program);

}  // namespace proxyvis
