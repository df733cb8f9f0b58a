// solve's exit code for a converged orbit: 4 when the orbit is not a motion of the system or its
// verification failed, each on its own, so that a script can rely on it. The verification alone
// fails only at edge cases of the simulators today, so it is set up here rather than found.
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "cli_common.hpp"

namespace stickslip::cli {
namespace {

Margin MarginOf(double value) { return Margin{.base = "G", .kind = MarginKind::kDuration, .segment = 2, .value = value}; }

Verification Passing() {
  Verification v;
  v.exact.sequence_matches = true;
  v.odeint.sequence_matches = true;
  return v;
}

TEST(SolvedOrbitExitCode, AdmissibleVerifiedOrbitIsSuccess) {
  ASSERT_TRUE(Passing().Passed());
  const ExitWithReason outcome = SolvedOrbitExitCode(MarginOf(0.01), Passing());
  EXPECT_EQ(outcome.exit_code, kExitOk);
  EXPECT_EQ(outcome.reason, "");
}

TEST(SolvedOrbitExitCode, NonPositiveMarginIsNotAMotionEvenWhenVerified) {
  for (double value : {0.0, -0.0072388}) {
    const ExitWithReason outcome = SolvedOrbitExitCode(MarginOf(value), Passing());
    EXPECT_EQ(outcome.exit_code, kExitNotAMotion);
    EXPECT_NE(outcome.reason.find("not a motion of the system: margin G:3 = "), std::string::npos) << outcome.reason;
  }
}

TEST(SolvedOrbitExitCode, FailedVerificationOfAnAdmissibleOrbitIsNotAMotion) {
  Verification v = Passing();
  v.exact.sequence_matches = false;
  const ExitWithReason outcome = SolvedOrbitExitCode(MarginOf(0.01), v);
  EXPECT_EQ(outcome.exit_code, kExitNotAMotion);
  EXPECT_EQ(outcome.reason, "the solution failed its verification by simulation");
}

TEST(SolvedOrbitExitCode, NanMarginIsAnUnknownAdmissibilityNotAComparisonWithZero) {
  const ExitWithReason outcome = SolvedOrbitExitCode(MarginOf(std::numeric_limits<double>::quiet_NaN()), Passing());
  EXPECT_EQ(outcome.exit_code, kExitNotAMotion);
  EXPECT_EQ(outcome.reason,
            "the solution's admissibility is not known: margin G:3 is not defined (its root search was cut short)");
}

}  // namespace
}  // namespace stickslip::cli
