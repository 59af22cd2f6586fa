// The trust of a proxy's claimed class (proxies/check/class_trust.h): the decision on its own with
// a stand-in containment check, then on files of a scene, and that a downgrade reaches the class
// the renderer gives its estimators.
#include "proxies/check/class_trust.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <optional>

#include "mesh/io/mesh_io.h"
#include "render/render_scene.h"
#include "scene/scene_desc.h"
#include "tests/proxies/check/check_shapes.h"
#include "util/sha256.h"

namespace proxyvis {
namespace {

namespace fs = std::filesystem;

const std::string kHashA(64, 'a'), kHashB(64, 'b');

// A containment check that returns `verdict` and counts its calls.
struct FakeCheck {
  ContainmentVerdict verdict;
  int calls = 0;
  std::function<ContainmentResult()> fn() {
    return [this] {
      ++calls;
      ContainmentResult r;
      r.verdict = verdict;
      r.detail = "stand-in";
      return r;
    };
  }
};

// The decision on a claimed class (none: nullopt) with recorded and current file hashes, the
// stand-in check answering `verdict`: it must give `status` and `trusted` after `calls` runs of
// the check. Returns the decision for the test's further checks.
ClassTrust expectDecision(std::optional<ProxyClass> claim, const std::string& recorded,
                          const std::string& current, ContainmentVerdict verdict,
                          ClassStatus status, ProxyClass trusted, int calls) {
  FakeCheck check{verdict};
  const ClassTrust t = decideClassTrust(claim, recorded, current, check.fn());
  EXPECT_EQ(t.status, status) << t.reason;
  EXPECT_EQ(t.trusted, trusted);
  EXPECT_EQ(check.calls, calls);
  return t;
}

TEST(ClassTrustDecision, NoClaimIsUnverifiedGeneralWithoutCheck) {
  expectDecision(std::nullopt, "", "", ContainmentVerdict::kContains, ClassStatus::kUnverified,
                 ProxyClass::kGeneral, 0);
}

TEST(ClassTrustDecision, GeneralClaimNeedsNoCheck) {
  expectDecision(ProxyClass::kGeneral, "", kHashA, ContainmentVerdict::kIntersecting,
                 ClassStatus::kGeneral, ProxyClass::kGeneral, 0);
}

TEST(ClassTrustDecision, MatchingHashIsTrustedWithoutCheck) {
  // The check would downgrade if it ran.
  const ClassTrust t =
      expectDecision(ProxyClass::kOutside, kHashA, kHashA, ContainmentVerdict::kIntersecting,
                     ClassStatus::kVerifiedByHash, ProxyClass::kOutside, 0);
  EXPECT_STREQ(classStatusName(t.status), "verified-by-hash");
}

TEST(ClassTrustDecision, MissingHashRunsTheCheckWhichReVerifies) {
  const ClassTrust t =
      expectDecision(ProxyClass::kOutside, "", kHashA, ContainmentVerdict::kContains,
                     ClassStatus::kReVerified, ProxyClass::kOutside, 1);
  EXPECT_NE(t.reason.find("no recorded sha256"), std::string::npos) << t.reason;
  EXPECT_STREQ(classStatusName(t.status), "re-verified");
}

TEST(ClassTrustDecision, ChangedFileThatFailsTheCheckIsDowngraded) {
  const ClassTrust t =
      expectDecision(ProxyClass::kOutside, kHashA, kHashB, ContainmentVerdict::kIntersecting,
                     ClassStatus::kDowngraded, ProxyClass::kGeneral, 1);
  EXPECT_NE(t.reason.find("sha256 differs"), std::string::npos) << t.reason;
  EXPECT_NE(t.reason.find("intersecting"), std::string::npos) << t.reason;
  EXPECT_STREQ(classStatusName(t.status), "downgraded");
}

TEST(ClassTrustDecision, EachClassNeedsItsOwnVerdict) {
  FakeCheck contains{ContainmentVerdict::kContains}, contained{ContainmentVerdict::kContained};
  EXPECT_EQ(decideClassTrust(ProxyClass::kInside, "", kHashA, contains.fn()).status,
            ClassStatus::kDowngraded);
  EXPECT_EQ(decideClassTrust(ProxyClass::kOutside, "", kHashA, contained.fn()).status,
            ClassStatus::kDowngraded);
  const ClassTrust inside = decideClassTrust(ProxyClass::kInside, "", kHashA, contained.fn());
  EXPECT_EQ(inside.status, ClassStatus::kReVerified);
  EXPECT_EQ(inside.trusted, ProxyClass::kInside);
}

TEST(ClassTrustDecision, UndecidableOrDisjointIsDowngraded) {
  for (ContainmentVerdict v : {ContainmentVerdict::kUndecidable, ContainmentVerdict::kDisjoint}) {
    SCOPED_TRACE(containmentName(v));
    expectDecision(ProxyClass::kOutside, "", kHashA, v, ClassStatus::kDowngraded,
                   ProxyClass::kGeneral, 1);
  }
}

// A scene of one sphere of radius 0.4 in the unit box (placed with a translation, which the check
// must ignore) whose proxy file the tests write, under a light far above every proxy (so the
// renderer's light check keeps the class). Box proxies have fewer triangles than the sphere, so
// the renderer uses them.
class ClassTrustScene : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           (std::string("pv_class_trust_") +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    saveMesh(test::makeSphere({0.5f, 0.5f, 0.5f}, 0.4f), dir_ / "sphere.off");
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Writes the proxy (to a new file each time: one that was read cannot be replaced in the same
  // process) and a scene claiming `claimed` with `hash` ("" = none); loads the scene.
  SceneDesc scene(const TriMesh& proxy, const std::string& claimed, const std::string& hash) {
    proxy_ = dir_ / ("proxy" + std::to_string(++count_) + ".off");
    saveMesh(proxy, proxy_);
    std::string p = R"({"kind": "outside", "file": ")" + proxy_.filename().string() + "\"";
    if (!claimed.empty()) p += R"(, "class": ")" + claimed + "\"";
    if (!hash.empty()) p += R"(, "sha256": ")" + hash + "\"";
    const fs::path file = dir_ / ("scene" + std::to_string(count_) + ".json");
    std::ofstream(file) << R"({
      "camera": {"eye": [0, 3, 6], "look_at": [0, 0.5, 0], "resolution": [8, 8]},
      "lights": [{"type": "quad", "corner": [-1, 20, -1], "edge_u": [2, 0, 0],
                  "edge_v": [0, 0, 2], "radiance": [1, 1, 1]}],
      "meshes": [{"name": "ball", "file": "sphere.off", "transform": {"translate": [5, 0, 0]},
                  "proxies": [)" +
                               p + "}]}]}";
    return loadSceneDesc(file);
  }
  std::string proxyHash() const { return sha256OfFile(proxy_); }

  fs::path dir_, proxy_;
  int count_ = 0;
};

const TriMesh kUnitBox = test::makeBox({0, 0, 0}, {1, 1, 1});
// The unit box contains the sphere; shrunk to half its size about its centre it cuts it, so
// labelled outside it is mislabelled.
const TriMesh kShrunk = test::transformed(kUnitBox, {0.5f, 0.5f, 0.5f}, 0.5f, {}, "shrunk");
const TriMesh kGrown = test::transformed(kUnitBox, {0.5f, 0.5f, 0.5f}, 1.2f, {}, "grown");

TEST_F(ClassTrustScene, MislabelledShrunkProxyIsDowngradedAndTheRendererUsesGeneral) {
  SceneDesc desc = scene(kShrunk, "outside", "");
  // Taken at its word, the claim reaches the estimators: the bias this guards against.
  RenderSceneOptions quiet;
  quiet.quiet = true;
  EXPECT_EQ(loadRenderScene(desc, quiet)->proxyClass(), ProxyClass::kOutside);

  const std::vector<ProxyTrust> trust = establishProxyClasses(desc, quiet);
  ASSERT_EQ(trust.size(), 1u);
  EXPECT_EQ(trust[0].trust.status, ClassStatus::kDowngraded);
  EXPECT_EQ(trust[0].claimed, ProxyClass::kOutside);
  EXPECT_EQ(desc.meshes[0].proxies[0].verified_class, ProxyClass::kGeneral);
  EXPECT_EQ(loadRenderScene(desc, quiet)->proxyClass(), ProxyClass::kGeneral);
  const std::string line = describeProxyTrust(trust[0]);
  EXPECT_NE(line.find("downgraded to general"), std::string::npos) << line;
  EXPECT_NE(line.find("proxy1.off"), std::string::npos) << line;
}

TEST_F(ClassTrustScene, RecordedHashIsTheFastPath) {
  const fs::path shrunk = dir_ / "shrunk.off";
  saveMesh(kShrunk, shrunk);  // the same bytes scene() writes
  // The hash vouches even for a wrong claim: it records what was proven, so the check is skipped
  // (which is what makes it fast); proxy-gen and proxy-check only record hashes of proven classes.
  SceneDesc desc = scene(kShrunk, "outside", sha256OfFile(shrunk));
  desc.meshes[0].transform = Affine3f{};  // in place: nothing is rounded again
  const std::vector<ProxyTrust> trust = establishProxyClasses(desc, {});
  ASSERT_EQ(trust.size(), 1u);
  EXPECT_EQ(trust[0].trust.status, ClassStatus::kVerifiedByHash);
  EXPECT_EQ(trust[0].verified_on, "object space");
  EXPECT_EQ(desc.meshes[0].proxies[0].verified_class, ProxyClass::kOutside);
}

// A mesh placed with a transform is traced as float copies of its placed vertices: the hash
// vouches for the files, not for those copies, so the class is checked on them as well.
TEST_F(ClassTrustScene, APlacedMeshIsCheckedOnThePlacedCopies) {
  saveMesh(kShrunk, dir_ / "shrunk.off");
  SceneDesc wrong = scene(kShrunk, "outside", sha256OfFile(dir_ / "shrunk.off"));
  std::vector<ProxyTrust> trust = establishProxyClasses(wrong, {});
  ASSERT_EQ(trust.size(), 1u);
  EXPECT_EQ(trust[0].trust.status, ClassStatus::kDowngraded);
  EXPECT_EQ(trust[0].verified_on, "placed float copies");
  EXPECT_NE(trust[0].trust.reason.find("placed float copies"), std::string::npos);
  EXPECT_EQ(wrong.meshes[0].proxies[0].verified_class, ProxyClass::kGeneral);

  saveMesh(kGrown, dir_ / "grown.off");
  SceneDesc right = scene(kGrown, "outside", sha256OfFile(dir_ / "grown.off"));
  trust = establishProxyClasses(right, {});
  ASSERT_EQ(trust.size(), 1u);
  EXPECT_EQ(trust[0].trust.status, ClassStatus::kVerifiedByHash);
  EXPECT_EQ(trust[0].verified_on, "placed float copies");
  EXPECT_EQ(right.meshes[0].proxies[0].verified_class, ProxyClass::kOutside);
}

TEST_F(ClassTrustScene, ProxyEditedAfterItsHashIsReVerified) {
  saveMesh(kGrown, dir_ / "earlier.off");  // an earlier version of the proxy, when it was hashed
  const std::string old_hash = sha256OfFile(dir_ / "earlier.off");
  const TriMesh edited = test::transformed(kUnitBox, {0.5f, 0.5f, 0.5f}, 1.5f, {}, "edited");
  SceneDesc desc = scene(edited, "outside", old_hash);
  ASSERT_NE(proxyHash(), old_hash);
  const std::vector<ProxyTrust> trust = establishProxyClasses(desc, {});
  ASSERT_EQ(trust.size(), 1u);
  EXPECT_EQ(trust[0].trust.status, ClassStatus::kReVerified);
  EXPECT_NE(trust[0].trust.reason.find("sha256 differs"), std::string::npos);
  EXPECT_EQ(desc.meshes[0].proxies[0].verified_class, ProxyClass::kOutside);
}

TEST_F(ClassTrustScene, UnclaimedAndUnusedProxiesAreLeftAlone) {
  SceneDesc desc = scene(kShrunk, "", "");
  std::vector<ProxyTrust> trust = establishProxyClasses(desc, {});
  ASSERT_EQ(trust.size(), 1u);
  EXPECT_EQ(trust[0].trust.status, ClassStatus::kUnverified);
  EXPECT_FALSE(desc.meshes[0].proxies[0].verified_class.has_value());

  desc = scene(kShrunk, "outside", "");
  RenderSceneOptions inside_kind;
  inside_kind.proxy_kind = "inside";  // the renderer would use none of this mesh's proxies
  EXPECT_TRUE(establishProxyClasses(desc, inside_kind).empty());
  desc.meshes[0].place = false;  // nor of a mesh that is neither placed nor instanced
  EXPECT_TRUE(establishProxyClasses(desc, {}).empty());
}

// decideProxyTrust is the one decision of both renderers; the data-parallel one passes a check that
// refuses, so it must be reached exactly when the single-process renderer would re-verify: an
// outside or inside claim whose recorded hash is missing or not the file's.
TEST_F(ClassTrustScene, ProxyTrustRunsTheCheckOnlyWhereTheHashDoesNotVouch) {
  const fs::path grown = dir_ / "grown.off";
  saveMesh(kGrown, grown);  // the same bytes scene() writes
  FakeCheck refuse{ContainmentVerdict::kUndecidable};
  SceneDesc desc = scene(kGrown, "outside", sha256OfFile(grown));
  ClassTrust t = decideProxyTrust(desc.meshes[0].proxies[0], refuse.fn());
  EXPECT_EQ(t.status, ClassStatus::kVerifiedByHash);
  EXPECT_EQ(t.trusted, ProxyClass::kOutside);
  EXPECT_EQ(refuse.calls, 0);

  for (const std::string& claim : {std::string(), std::string("general")}) {
    desc = scene(kGrown, claim, "");
    t = decideProxyTrust(desc.meshes[0].proxies[0], refuse.fn());
    EXPECT_EQ(t.trusted, ProxyClass::kGeneral) << claim;
    EXPECT_EQ(refuse.calls, 0) << claim;
  }

  for (const std::string& hash : {std::string(), kHashB}) {
    desc = scene(kGrown, "outside", hash);
    t = decideProxyTrust(desc.meshes[0].proxies[0], refuse.fn());
    EXPECT_EQ(t.status, ClassStatus::kDowngraded);
  }
  EXPECT_EQ(refuse.calls, 2);

  // The single-process check proves the same claim again.
  FakeCheck proves{ContainmentVerdict::kContains};
  t = decideProxyTrust(desc.meshes[0].proxies[0], proves.fn());
  EXPECT_EQ(t.status, ClassStatus::kReVerified);
  EXPECT_EQ(t.trusted, ProxyClass::kOutside);
  EXPECT_EQ(proves.calls, 1);
}

}  // namespace
}  // namespace proxyvis
