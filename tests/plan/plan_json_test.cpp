// plan/plan.h, plan/unit_stamp.h: a study's plan and a unit's stamp as JSON, read back exactly,
// and the checks that refuse a unit of another plan.
#include <gtest/gtest.h>

#include "plan/plan.h"
#include "plan/unit_stamp.h"
#include "tests/support/json_round_trip.h"
#include "tests/support/scratch_dir.h"
#include "tests/support/two_unit_plan.h"
#include "util/error.h"
#include "util/plan_folder.h"
#include "util/program_build_id.h"

namespace proxyvis {
namespace {

PlannedUnit randomUnit(test::RandomValues& v) {
  // Only the keys of its kind are written: the others stay at their defaults.
  PlannedUnit u;
  u.kind = UnitKind(v.pick(4));
  if (u.kind == UnitKind::kEqualSpp) {
    u.estimator = EstimatorKind(v.pick(6));
    u.spp = v.smallInt();
    u.run = v.smallInt();
  }
  if (u.kind == UnitKind::kEqualTime) u.run = v.smallInt();
  if (u.kind == UnitKind::kReference) u.partial = v.smallInt();
  return u;
}

StudyPlan randomPlan(test::RandomValues& v) {
  StudyPlan p;
  v.fill(p.args, p.scene, p.scene_hash, p.build, p.seed, p.reference_spp, p.reference_partials,
         p.reference_per_partial);
  for (uint64_t i = 0, n = v.pick(8); i < n; ++i) p.units.push_back(randomUnit(v));
  return p;
}

UnitStamp randomStamp(test::RandomValues& v) {
  return {v.u64(), v.text(), v.text(), v.u64(), v.text(), v.text()};
}

PlanCommands randomCommands(test::RandomValues& v) {
  return {v.smallInt(), v.text(), v.u64(), v.texts(), v.texts()};
}

TEST(PlanJson, RandomCommandsRoundTrip) {
  test::expectRoundTrips<PlanCommands>(randomCommands);
}

TEST(PlanJson, RandomUnitsRoundTrip) {
  test::expectRoundTrips<PlannedUnit>(randomUnit);
}

TEST(PlanJson, RandomPlansRoundTrip) {
  test::expectRoundTrips<StudyPlan>(randomPlan);
}

TEST(PlanJson, RandomStampsRoundTrip) {
  test::expectRoundTrips<UnitStamp>(randomStamp);
}

TEST(PlanJson, EveryKeyIsRequiredAndTyped) {
  test::RandomValues v(11);
  StudyPlan plan = randomPlan(v);
  test::expectEveryKeyChecked(plan);
  test::expectEveryKeyChecked(randomStamp(v));
  test::expectEveryKeyChecked(randomCommands(v));
  PlannedUnit u;
  u.kind = UnitKind::kEqualSpp;
  test::expectEveryKeyChecked(u);
  u.kind = UnitKind::kReference;
  test::expectEveryKeyChecked(u);
}

TEST(PlanJson, AnUnknownKindOrEstimatorIsNamed) {
  StudyPlan plan;
  plan.units.resize(3);
  nlohmann::json j = plan;
  j["unit_list"][2]["estimator"] = "exactly";
  EXPECT_EQ(test::errorPath<StudyPlan>(j), "unit_list[2].estimator");
  j["unit_list"][1]["kind"] = "equal-something";
  EXPECT_EQ(test::errorPath<StudyPlan>(j), "unit_list[1].kind");
}

TEST(PlanFolder, WrittenPlanReadsBackAndABrokenOneIsRefused) {
  test::ScratchDir dir;
  test::RandomValues v(13);
  StudyPlan plan = randomPlan(v);
  writePlanFolder(dir / "p", plan);
  EXPECT_TRUE(readPlan(dir / "p") == plan);
  const nlohmann::json file = planToJson(plan, "/bin/render-compare");
  EXPECT_EQ(file.at("units"), plan.units.size());
  EXPECT_EQ(file.at("merge"),
            nlohmann::json::array({"/bin/render-compare", "--merge", "{plan_dir}"}));

  nlohmann::json broken = file;
  broken["render_compare"].erase("seed");
  dir.write("q/plan.json", broken.dump());
  try {
    (void)readPlan(dir / "q");
    FAIL() << "a plan without its seed was read";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("q/plan.json: not a render-compare plan; "
                                         "render_compare.seed: missing"),
              std::string::npos)
        << e.what();
  }
  dir.write("r/plan.json", "{\"units\": ");
  EXPECT_THROW((void)readPlan(dir / "r"), Error);
}

TEST(UnitStamp, ADifferenceIsNamedWithBothValues) {
  const StudyPlan plan = test::twoUnitPlan("abc", 9, UnitKind::kCeiling);
  const UnitStamp expected = plannedStamp(plan, 1);
  EXPECT_EQ(expected.kind, "ceiling");
  EXPECT_EQ(expected.study, studyId(plan));
  EXPECT_NO_THROW(requireSameStamp("u.result", expected, expected));
  UnitStamp other = expected;
  other.scene_hash = "abd";
  try {
    requireSameStamp("u.result", other, expected);
    FAIL() << "a unit of another scene was taken";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("its scene hash is abd, the plan's is abc"),
              std::string::npos)
        << e.what();
  }
  other = expected;
  other.seed = 10;
  EXPECT_THROW(requireSameStamp("u.result", other, expected), Error);
  // Another study (another unit list) has another fingerprint.
  StudyPlan longer = plan;
  longer.units.push_back({});
  EXPECT_NE(studyId(longer), studyId(plan));
  EXPECT_NO_THROW(requirePlanningBuild(programBuildId(), "plan.json", "plan again"));
  EXPECT_THROW(requirePlanningBuild("another build", "plan.json", "plan again"), Error);
}

}  // namespace
}  // namespace proxyvis
