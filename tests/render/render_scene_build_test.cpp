// --build auto's decision: flattened exactly when the estimated bytes of the flattened Embree
// scenes fit the budget (a budget below the estimate gives instanced, above gives flat); forced
// builds and scenes without instances ignore the budget; the default budget is at most 4 GiB and
// half the memory the process may use.
#include <gtest/gtest.h>

#include "render/render_scene_build.h"

namespace proxyvis {
namespace {

TEST(RenderSceneBuild, AutoFlattensExactlyWhenTheEstimateFitsTheBudget) {
  const uint64_t tris = 1'034'000;            // about foliage, expanded
  const double bytes = 185.0 * double(tris);  // the measured bytes per flattened triangle
  const BuildChoice fits = chooseBuild(InstanceBuild::kAuto, true, tris, bytes);
  EXPECT_TRUE(fits.flat);
  EXPECT_STREQ(fits.name(), "flat");
  EXPECT_DOUBLE_EQ(fits.estimated_bytes, bytes);
  EXPECT_DOUBLE_EQ(fits.budget_bytes, bytes);
  const BuildChoice over = chooseBuild(InstanceBuild::kAuto, true, tris, bytes - 1);
  EXPECT_FALSE(over.flat);
  EXPECT_STREQ(over.name(), "instanced");
  EXPECT_NE(over.reason.find("over the memory budget"), std::string::npos) << over.reason;
  EXPECT_NE(over.description().find("1.0 M triangles"), std::string::npos) << over.description();
  EXPECT_NE(over.description().find("~0.2 GB est."), std::string::npos) << over.description();
}

TEST(RenderSceneBuild, AutoKeepsLargeScenesInstancedEvenWhenTheyFit) {
  // ecosys, expanded: fits a large budget, but was measured no faster flattened.
  const uint64_t tris = 12'341'851;
  const BuildChoice c = chooseBuild(InstanceBuild::kAuto, true, tris, 1e12);
  EXPECT_FALSE(c.flat);
  EXPECT_NE(c.reason.find("no faster"), std::string::npos) << c.reason;
  EXPECT_NE(c.description().find("12.3 M triangles"), std::string::npos) << c.description();
  EXPECT_TRUE(chooseBuild(InstanceBuild::kAuto, true, kAutoFlattenMaxTriangles, 1e12).flat);
  EXPECT_FALSE(chooseBuild(InstanceBuild::kAuto, true, kAutoFlattenMaxTriangles + 1, 1e12).flat);
  // A tiny budget: instanced; a zero budget too.
  EXPECT_FALSE(chooseBuild(InstanceBuild::kAuto, true, 1000, 1024).flat);
  EXPECT_FALSE(chooseBuild(InstanceBuild::kAuto, true, 1, 0).flat);
}

TEST(RenderSceneBuild, ForcedBuildsAndScenesWithoutInstancesIgnoreTheBudget) {
  EXPECT_TRUE(chooseBuild(InstanceBuild::kFlat, true, 1'000'000'000, 1).flat);
  EXPECT_FALSE(chooseBuild(InstanceBuild::kInstanced, true, 10, 1e12).flat);
  const BuildChoice none = chooseBuild(InstanceBuild::kAuto, false, 1'000'000'000, 1);
  EXPECT_TRUE(none.flat);  // nothing to instance: one BVH of the placed meshes
  EXPECT_NE(none.reason.find("no instances"), std::string::npos);
  EXPECT_EQ(chooseBuild(InstanceBuild::kFlat, true, 5, 1).reason, "--build flat");
}

TEST(RenderSceneBuild, DefaultBudgetIsAtMostFourGibAndHalfTheMemory) {
  const uint64_t available = availableMemoryBytes();
  ASSERT_GT(available, 64ull << 20);  // any machine that runs the tests has 64 MiB
  const double budget = defaultMemoryBudgetBytes();
  EXPECT_LE(budget, 4.0 * (1ull << 30));
  EXPECT_LE(budget, 0.5 * double(available));
  EXPECT_GE(budget, std::min(4.0 * (1ull << 30), 0.5 * double(available)));
  // A negative budget asks for the default.
  const BuildChoice c = chooseBuild(InstanceBuild::kAuto, true, 10, -1);
  EXPECT_DOUBLE_EQ(c.budget_bytes, budget);
}

}  // namespace
}  // namespace proxyvis
