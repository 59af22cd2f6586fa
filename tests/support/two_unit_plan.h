#pragma once
// A study plan of two default units, the second of `second_kind`, stamped with this build: what
// the plan and unit tests check a result's stamp against.
#include <cstdint>
#include <string>

#include "plan/plan.h"
#include "util/program_build_id.h"

namespace proxyvis::test {

inline StudyPlan twoUnitPlan(const std::string& scene_hash, uint64_t seed, UnitKind second_kind) {
  StudyPlan plan;
  plan.scene_hash = scene_hash;
  plan.seed = seed;
  plan.build = programBuildId();
  plan.units.resize(2);
  plan.units[1].kind = second_kind;
  return plan;
}

}  // namespace proxyvis::test
