// Every continuation stays inside the valid parameter ranges (parameters.hpp, eq. 4): the
// continued parameter's range stops at its valid range, a released u_s reaching zero ends the
// family as an EP even past changes of orbit type, u_r >= u_s bounds a continuation in either
// friction level, and nothing beyond an end is reported.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "stickslip/branches/orbit_continuation.hpp"
#include "stickslip/orbits/paper_presets.hpp"

namespace stickslip {
namespace {

OrbitBranch ContinuePreset(const char* name, const char* parameter, int direction, double lo, double hi,
                           bool past_type_changes) {
  const PaperPreset& preset = *FindPaperPreset(name);
  ContinuationOptions options;
  options.direction = direction;
  options.lambda_min = lo;
  options.lambda_max = hi;
  options.continue_past_terminal = past_type_changes;
  options.max_points = 400;
  return ContinueOrbit({.start = preset.Guess(), .unknowns = preset.unknowns, .parameter = parameter,
                        .shooting = ShootingChoice::kAuto, .sparse_solver = LinearSolverType::kKlu,
                        .options = options, .flow = {}});
}

double SmallestSlidingFriction(const OrbitBranch& b) {
  double smallest = b.orbits.front().parameters.u_s;
  for (const Orbit& o : b.orbits) smallest = std::min(smallest, o.parameters.u_s);
  return smallest;
}

TEST(ParameterRanges, ContinuedSlidingFrictionStopsAtItsValidRangePastTypeChangesToo) {
  const OrbitBranch b = ContinuePreset("paper-5.1", "u_s", -1, -1.0, 1.0, /*past_type_changes=*/true);
  EXPECT_EQ(b.branch.end, BranchEnd::kParameterBound) << b.branch.end_message;
  EXPECT_EQ(b.orbits.back().parameters.u_s, kMinSlidingFriction);  // it ran on to u_s = -1 before
  EXPECT_GE(SmallestSlidingFriction(b), kMinSlidingFriction);
}

// Section 4.2's family ends at u_s = 0 (u_s = u_r released): a branch point that could not be
// located inside the last step was reported at that step's end, u_s = -0.00134.
TEST(ParameterRanges, NothingBeyondTheFamilysEndIsReported) {
  const OrbitBranch b = ContinuePreset("paper-4.2", "omega", +1, 0.3, 0.9, /*past_type_changes=*/true);
  EXPECT_NE(b.branch.end_message.find("margin:sliding-friction"), std::string::npos) << b.branch.end_message;
  for (const SpecialPoint& s : b.branch.special_points) {
    EXPECT_GT(b.orbits[s.point].parameters.u_s, -1e-9) << s.type << " at u_s = " << b.orbits[s.point].parameters.u_s;
  }
}

// Issue 22, defect 3: a range past the valid range (continue --preset paper-5.1 --parameter u_s
// --range -1,1 --direction down) ended at the valid bound with two end labels on one point, EP2
// (lambda_min) and EP3 (parameter-bound); so did every located bound and the family's end. The
// located EP is the end: one end label.
std::vector<std::string> EndLabels(const OrbitBranch& b) {
  std::vector<std::string> at_end;
  for (const SpecialPoint& s : b.branch.special_points) {
    if (s.point == static_cast<int>(b.branch.points.size()) - 1) at_end.push_back(s.type + " " + s.test_function);
  }
  return at_end;
}

TEST(ParameterRanges, ARangePastTheValidRangeEndsWithOneEndLabel) {
  const OrbitBranch b = ContinuePreset("paper-5.1", "u_s", -1, -1.0, 1.0, /*past_type_changes=*/false);
  EXPECT_EQ(b.branch.end, BranchEnd::kParameterBound) << b.branch.end_message;
  EXPECT_EQ(EndLabels(b), std::vector<std::string>{"EP lambda_min"});
  const OrbitBranch family = ContinuePreset("paper-4.2", "omega", +1, 0.3, 0.9, /*past_type_changes=*/false);
  EXPECT_EQ(EndLabels(family), std::vector<std::string>{"EP margin:sliding-friction"});
  // An end at another located special point is a second row there, as before (LP3, then EP4).
  const OrbitBranch fold = ContinuePreset("paper-5.2", "omega", +1, 0.3, 0.9, /*past_type_changes=*/false);
  ASSERT_GE(EndLabels(fold).size(), 2u);
  EXPECT_EQ(EndLabels(fold).back(), "EP terminal-event");
}

TEST(ParameterRanges, StaticFrictionStopsAtTheSlidingLevel) {
  const OrbitBranch b = ContinuePreset("paper-4.1", "u_r", -1, 0.0, 1.0, /*past_type_changes=*/true);
  EXPECT_EQ(b.branch.end, BranchEnd::kParameterBound) << b.branch.end_message;
  const Parameters& last = b.orbits.back().parameters;
  EXPECT_EQ(last.u_r, last.u_s);  // the bound u_r = u_s, located exactly
}

}  // namespace
}  // namespace stickslip
