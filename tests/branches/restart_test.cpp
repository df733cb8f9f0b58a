// Restarts from the labelled points of stored runs (results/): the start's own special point is
// not reported again, a pole at the start is no bifurcation, and a start on a fold goes the way
// the branch runs or says that it folds there.
#include <filesystem>

#include <gtest/gtest.h>

#include "stickslip/branches/orbit_continuation.hpp"
#include "stickslip/io/start_input.hpp"

namespace stickslip {
namespace {

OrbitBranch Restart(const char* run, const char* label, const char* parameter, int direction) {
  StartInput input;
  input.restart = ReadRestartPoint(std::filesystem::path(STICKSLIP_SOURCE_DIR) / "results", run, label);
  input.parameter = parameter;
  const StartProblem start = BuildStartProblem(input);
  ContinuationOptions options;
  options.direction = direction;
  options.lambda_min = 0.2;
  options.lambda_max = 3.0;
  options.max_points = 30;
  return ContinueOrbit({.start = start.orbit, .unknowns = start.unknowns, .parameter = parameter,
                        .shooting = ShootingChoice::kAuto, .sparse_solver = LinearSolverType::kKlu,
                        .options = options, .flow = {}});
}

// Special points (other than the start's EP) within `distance` of the start in lambda.
std::vector<std::string> NearTheStart(const OrbitBranch& b, double distance) {
  std::vector<std::string> types;
  const double start = b.branch.points.front().lambda;
  for (const SpecialPoint& s : b.branch.special_points) {
    if (s.point > 0 && std::abs(s.lambda - start) < distance) types.push_back(s.type);
  }
  return types;
}

TEST(Restart, DoesNotReportTheStartsOwnTorusOrFoldAgain) {
  // TR2 was reported again at u_r = 0.4962 + 8.6e-15, LP4 again at its omega.
  EXPECT_TRUE(NearTheStart(Restart("paper-5.1-omega-up", "TR2", "u_r", +1), 1e-6).empty());
  EXPECT_TRUE(NearTheStart(Restart("paper-5.1-omega-up", "LP4", "omega", +1), 1e-6).empty());
}

// GR6 is a grazing of the stick exit: its saltation matrix has a pole there (det(M + I) =
// -3.6e29), and the sign change through it was "located" as a PD with det(M + I) = 2.3e9.
TEST(Restart, ASignChangeThroughThePoleAtAGrazingIsNoPeriodDoubling) {
  const OrbitBranch b = Restart("paper-5.1-omega-up", "GR6", "u_r", +1);
  EXPECT_TRUE(NearTheStart(b, 1e-6).empty());
  for (const SpecialPoint& s : b.branch.special_points) {
    if (s.type == "PD") {
      EXPECT_LT(std::abs(s.test_value), 1e-3) << "a PD where det(M + I) = " << s.test_value;
    }
  }
}

// LP2 of section 6 over omega: the bordered Jacobian with the omega axis is singular there (the
// restart exited 3). Both sides of the fold lie at lower omega.
TEST(Restart, FromAFoldRunsTheWayTheBranchRunsOrSaysItFoldsThere) {
  const OrbitBranch down = Restart("paper-6-omega-up", "LP2", "omega", -1);
  ASSERT_NE(down.branch.end, BranchEnd::kStartFailed) << down.branch.end_message;
  ASSERT_GE(down.orbits.size(), 10u) << down.branch.end_message;
  for (std::size_t k = 1; k < down.orbits.size(); ++k) {
    EXPECT_LT(down.orbits[k].parameters.omega, down.orbits.front().parameters.omega);
  }
  const OrbitBranch up = Restart("paper-6-omega-up", "LP2", "omega", +1);
  EXPECT_EQ(up.branch.end, BranchEnd::kFoldAtStart) << up.branch.end_message;
  EXPECT_EQ(up.orbits.size(), 1u);
}

}  // namespace
}  // namespace stickslip
