// A run file's branch whose first point the engine refused (BranchEnd::kStartOutsideRange: inside the
// range asked for, past a bound of the physics) is refused at the key that asked for it: the switch
// at a label for a switched branch, else the range, with the engine's message (CheckRangeHoldsFirstPoint).
#include "stickslip/io/run.hpp"

#include <string>

#include <gtest/gtest.h>

namespace stickslip {
namespace {

// A branch of one point, F_k = 0.4000001, that the engine ended at its start past F_k <= F_s = 0.4.
Branch StartedPastTheStaticLevel() {
  Branch branch;
  branch.points.push_back({});
  branch.points.back().lambda = 0.4000001;
  branch.end = BranchEnd::kStartOutsideRange;
  branch.end_message = "the start, F_k = 0.4000001, lies outside the parameter range (F_k <= F_s = 0.4)";
  return branch;
}

std::string Refusal(const RunFile& run, const Branch& branch) {
  try {
    CheckRangeHoldsFirstPoint(run, branch);
  } catch (const RunFileError& e) {
    return e.what();
  }
  return "";
}

TEST(CheckRangeHoldsFirstPoint, RefusesAStartPastABoundOfThePhysicsAtTheKeyThatAskedForIt) {
  RunFile run;
  run.path = "curve.toml";
  run.parameter = "F_k";
  run.range_min = 0.3;
  run.range_max = 0.5;  // holds the first point: only the physics excludes it
  EXPECT_EQ(Refusal(run, StartedPastTheStaticLevel()),
            "curve.toml: key 'continuation.range' is invalid: the start, F_k = 0.4000001, lies outside the parameter "
            "range (F_k <= F_s = 0.4)");
  run.restart_switch_branch = true;
  run.restart_label = "SB2";
  run.direction = -1;
  EXPECT_EQ(Refusal(run, StartedPastTheStaticLevel()),
            "curve.toml: key 'start.restart.switch_branch' = true is invalid at 'SB2' (direction = \"down\"): the "
            "start, F_k = 0.4000001, lies outside the parameter range (F_k <= F_s = 0.4)");
  // A branch that ran is no refusal.
  Branch ran = StartedPastTheStaticLevel();
  ran.end = BranchEnd::kParameterBound;
  EXPECT_EQ(Refusal(run, ran), "");
}

}  // namespace
}  // namespace stickslip
