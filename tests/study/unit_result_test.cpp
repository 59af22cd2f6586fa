// study/unit.h: a unit's result written to its plan folder reads back equal, images included;
// a result of another plan or of another image size is refused.
#include <gtest/gtest.h>

#include "plan/plan.h"
#include "study/unit.h"
#include "tests/support/scratch_dir.h"
#include "tests/support/two_unit_plan.h"
#include "util/error.h"

namespace proxyvis {
namespace {

Image rgb(int w, int h, float v) {
  return Image{w, h, 3, std::vector<float>(size_t(w) * h * 3, v)};
}

StudyPlan twoUnitPlan() {
  return test::twoUnitPlan("0123", 42, UnitKind::kEqualTime);
}

UnitResult sampleResult() {
  UnitResult result;
  result.facts.build = "flattened";
  result.facts.proxy_classes.push_back({"m", "p.ply", "none", "general", "unchecked", ""});
  RenderResult r;
  r.spp = 4;
  r.seconds = 0.125;
  r.radiance = rgb(2, 3, 0.5f);
  r.visibility = Image{2, 3, 1, std::vector<float>(6, 1.0f)};
  r.cost = rgb(2, 3, 2.0f);
  result.renders.push_back(r);
  r.radiance = rgb(2, 3, 0.25f);
  r.visibility = Image{};
  r.cost = Image{};
  result.renders.push_back(r);
  return result;
}

TEST(UnitResultFile, ReadsBackEqual) {
  test::ScratchDir dir;
  const StudyPlan plan = twoUnitPlan();
  writePlanFolder(dir / "plan", plan);
  const UnitResult result = sampleResult();
  writeUnitResult(dir / "plan", plan, 1, result);
  EXPECT_TRUE(std::filesystem::exists(unitDonePath(dir / "plan", 1)));
  const UnitResult back = readUnitResult(dir / "plan", plan, 1, 2, 3);
  EXPECT_TRUE(back == result);
}

TEST(UnitResultFile, AForeignOrMisshapenResultIsRefused) {
  test::ScratchDir dir;
  const StudyPlan plan = twoUnitPlan();
  writePlanFolder(dir / "plan", plan);
  writeUnitResult(dir / "plan", plan, 1, sampleResult());
  EXPECT_THROW(readUnitResult(dir / "plan", plan, 1, 3, 2), Error);  // another image size
  EXPECT_THROW(readUnitResult(dir / "plan", plan, 0, 2, 3), Error);  // unit 0 has not run
  StudyPlan other = plan;
  other.seed = 43;
  try {
    (void)readUnitResult(dir / "plan", other, 1, 2, 3);
    FAIL() << "a unit of another seed was read";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("its seed is 42, the plan's is 43"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace proxyvis
