// A branch of the adjacent orbit type, started at a located change of type from a zero-length
// segment (orbits/signature_edits.hpp). Section 4.1's branch over omega ends at SK2, where the
// force at the first stop reaches the static level: below it the mass sticks there. With a
// zero-length stick inserted at that stop, the continuation starts on the type boundary; the
// stick grows as omega goes on down, and the simulator confirms the new type. Started upwards it
// ends at once, naming the margin that left its admissible side.
#include <filesystem>
#include <stdexcept>

#include <gtest/gtest.h>

#include "stickslip/branches/orbit_continuation.hpp"
#include "stickslip/io/result_files.hpp"
#include "stickslip/orbits/signature_edits.hpp"
#include "stickslip/orbits/verification.hpp"

namespace stickslip {
namespace {

Orbit LabelledOrbit(const char* run, const char* label) {
  const StoredRun stored = ReadRunFiles(std::filesystem::path(STICKSLIP_SOURCE_DIR) / "results" / run);
  for (const StoredSpecialPoint& s : stored.special_points) {
    if (s.point.label == label) return OrbitOf(stored, s.point);
  }
  throw std::runtime_error(std::string(label) + " is not in " + run);
}

OrbitBranch ContinueInOmega(const Orbit& start, int direction) {
  OrbitContinuationSetup setup{.start = start, .unknowns = {}, .parameter = "omega", .shooting = ShootingChoice::kAuto,
                               .sparse_solver = LinearSolverType::kKlu, .options = {}, .flow = {}};
  setup.options.direction = direction;
  setup.options.lambda_min = 0.5;
  setup.options.lambda_max = 0.69;
  setup.options.step.ds = 0.002;
  setup.options.max_points = 30;
  return ContinueOrbit(setup);
}

// The start is corrected to rounding only: the located point may sit a hair off the boundary (a
// margin of -1e-16 at the start is on it, not beyond it).
class TypeChangeStart : public ::testing::TestWithParam<double> {};

TEST_P(TypeChangeStart, ZeroLengthStickAtAReversalStartsTheStickingBranch) {
  const Orbit at_sk = LabelledOrbit("paper-4.1-omega-down", "SK2");
  Orbit start = InsertSegment(at_sk, 1, Mode::kStick);
  ASSERT_EQ(start.signature.ToString(), "slip- stick / antisymmetric");  // a stick at both stops
  start.x10 += GetParam();

  const OrbitBranch down = ContinueInOmega(start, -1);
  ASSERT_NE(down.branch.end, BranchEnd::kStartFailed) << down.branch.end_message;
  ASSERT_GE(down.orbits.size(), 10u) << down.branch.end_message;
  EXPECT_NEAR(down.orbits.front().durations[1], 0.0, 1e-9);  // the start sits on the boundary
  for (std::size_t k = 1; k < 10; ++k) {
    const Orbit& o = down.orbits[k];
    EXPECT_EQ(down.branch.points[k].label, "") << "no type change near the start";
    EXPECT_LT(o.parameters.omega, at_sk.parameters.omega);
    EXPECT_GT(o.durations[1], down.orbits[k - 1].durations[1]) << "the stick grows away from the boundary";
    EXPECT_GT(SmallestMargin(AdmissibilityMargins(o)).value, 0.0) << "point " << k;
  }
  // Independently: both simulators, started from the orbit, go through slip-, a stick, slip+,
  // a stick, and come back to the start.
  const Verification v = VerifyOrbit(down.orbits[9]);
  EXPECT_TRUE(v.Passed()) << v.Report();

  const OrbitBranch up = ContinueInOmega(start, +1);
  EXPECT_EQ(up.branch.end, BranchEnd::kTerminalEvent) << up.branch.end_message;
  EXPECT_EQ(up.branch.points.size(), 1u);
  // On the boundary the stick has zero length and the force at its entry is at the static level:
  // the first step upwards makes one of the two margins negative.
  const std::string& why = up.branch.end_message;
  EXPECT_TRUE(why.find("margin:duration:2") != std::string::npos || why.find("margin:stick-entry:1") != std::string::npos)
      << why;
}

INSTANTIATE_TEST_SUITE_P(LocatedAndPerturbed, TypeChangeStart, ::testing::Values(0.0, 1e-10));

}  // namespace
}  // namespace stickslip
