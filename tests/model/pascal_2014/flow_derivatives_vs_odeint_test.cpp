// The derivatives of the closed-form flows (FlowWithDerivatives: eqs. 5-10 differentiated by
// forward-mode AD) against an independent integration of the variational equations of eq. (2)
// and (9) (IntegrateModeWithDerivatives: odeint dopri5 at tolerance 1e-12 on 44 equations, the
// derivatives of the vector field written by hand), on random states, phases, durations and
// parameters away from resonance, in each of the three modes, block by block.
#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <limits>
#include <numbers>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/random_flow_cases.hpp"
#include "support/test_names.hpp"

#include "stickslip/model/pascal_2014/flows.hpp"
#include "stickslip/model/pascal_2014/modal.hpp"
#include "stickslip/model/pascal_2014/odeint_simulator.hpp"
#include "stickslip/model/pascal_2014/parameters.hpp"

namespace stickslip {
namespace {

// Each block must agree to 1e-8 relative to max(1, |block|_inf) (the reference's largest entry).
constexpr double kTolerance = 1e-8;
constexpr int kCasesPerMode = 200;
// |omega - omega_j| > kResonanceGap: the forced amplitude Q of eq. (7) and its parameter
// derivatives stay moderate, so the comparison is not dominated by near-singular terms.
constexpr double kResonanceGap = 0.05;
constexpr double kMaxDuration = 12.0;

// x2' in a stick too: eq. (9) lets x2 drift, and the closed form carries that drift, so
// d/dx2'(0) is exercised.
std::vector<FlowCase> RandomCases(Mode mode, int count, unsigned seed) {
  return RandomFlowCases(mode, count, seed, {kResonanceGap, kMaxDuration, false});
}

enum Block { kState, kStart, kElapsed, kPhase, kParameters, kBlockCount };
constexpr std::array<const char*, kBlockCount> kBlockNames = {"state", "d_start", "d_elapsed",
                                                              "d_phase", "d_parameters"};

// |a - b|_inf / max(1, |b|_inf) for every block, b the reference.
template <typename Derived>
double RelativeDifference(const Eigen::MatrixBase<Derived>& a,
                          const Eigen::MatrixBase<Derived>& b) {
  return (a - b).template lpNorm<Eigen::Infinity>() /
         std::max(1.0, b.template lpNorm<Eigen::Infinity>());
}

std::array<double, kBlockCount> BlockDifferences(const FlowDerivatives& a,
                                                 const FlowDerivatives& b) {
  return {RelativeDifference(a.state, b.state), RelativeDifference(a.d_start, b.d_start),
          RelativeDifference(a.d_elapsed, b.d_elapsed), RelativeDifference(a.d_phase, b.d_phase),
          RelativeDifference(a.d_parameters, b.d_parameters)};
}

std::string Describe(Mode mode, const FlowCase& c) {
  std::ostringstream out;
  out << std::setprecision(17) << ToString(mode) << " chi=" << c.p.chi << " eta=" << c.p.eta
      << " omega=" << c.p.omega << " u_s=" << c.p.u_s << " u_r=" << c.p.u_r
      << " phase=" << c.phase << " s=" << c.s << " start=" << c.start.transpose();
  return out.str();
}

unsigned SeedFor(Mode mode, unsigned base) { return base + static_cast<unsigned>(mode); }

class FlowDerivativesAgainstOdeint : public ::testing::TestWithParam<Mode> {};

TEST_P(FlowDerivativesAgainstOdeint, MatchesTheVariationalEquationsInEveryBlock) {
  const Mode mode = GetParam();
  std::array<double, kBlockCount> worst{};
  for (const FlowCase& c : RandomCases(mode, kCasesPerMode, SeedFor(mode, 77014u))) {
    const FlowDerivatives closed = FlowWithDerivatives(mode, c.start, c.phase, c.s, c.p);
    const FlowDerivatives numeric = IntegrateModeWithDerivatives(mode, c.start, c.phase, c.s, c.p);
    const std::array<double, kBlockCount> difference = BlockDifferences(closed, numeric);
    for (int b = 0; b < kBlockCount; ++b) {
      worst[b] = std::max(worst[b], difference[b]);
      EXPECT_LT(difference[b], kTolerance) << kBlockNames[b] << " of " << Describe(mode, c);
    }
  }
  for (int b = 0; b < kBlockCount; ++b) {
    std::ostringstream report;
    report << std::scientific << std::setprecision(2) << worst[b];
    RecordProperty(std::string("max_relative_difference_") + kBlockNames[b], report.str());
  }
}

// The comparison resolves errors far below any plausible bug in a derivative: the closed form
// evaluated at chi (1 + 1e-6) (a change smaller than a typical finite-difference error) already
// differs from the reference by more than the tolerance in the transition matrix.
TEST_P(FlowDerivativesAgainstOdeint, DetectsAPerturbationOfTheStiffnessRatio) {
  const Mode mode = GetParam();
  int detected = 0;
  int long_enough = 0;
  for (const FlowCase& c : RandomCases(mode, 50, SeedFor(mode, 4031u))) {
    if (c.s < 1.0) continue;
    ++long_enough;
    Parameters perturbed = c.p;
    perturbed.chi *= 1.0 + 1e-6;
    const FlowDerivatives closed = FlowWithDerivatives(mode, c.start, c.phase, c.s, perturbed);
    const FlowDerivatives numeric = IntegrateModeWithDerivatives(mode, c.start, c.phase, c.s, c.p);
    if (BlockDifferences(closed, numeric)[kStart] > kTolerance) ++detected;
  }
  EXPECT_EQ(detected, long_enough);
}

TEST_P(FlowDerivativesAgainstOdeint, IsTheIdentityAtZeroDuration) {
  const Mode mode = GetParam();
  for (FlowCase c : RandomCases(mode, 10, SeedFor(mode, 11u))) {
    c.s = 0.0;
    const FlowDerivatives numeric = IntegrateModeWithDerivatives(mode, c.start, c.phase, c.s, c.p);
    EXPECT_EQ(numeric.state, c.start);
    EXPECT_EQ(numeric.d_start, Eigen::Matrix4d::Identity());
    EXPECT_TRUE(numeric.d_phase.isZero(0.0));
    EXPECT_TRUE(numeric.d_parameters.isZero(0.0));
    // The closed form is exact only to rounding at s = 0: its spectral sum cancels terms of
    // size |Q|, |d0| (~2e-14 seen in d_parameters).
    const FlowDerivatives closed = FlowWithDerivatives(mode, c.start, c.phase, c.s, c.p);
    const std::array<double, kBlockCount> difference = BlockDifferences(closed, numeric);
    for (int b = 0; b < kBlockCount; ++b) {
      EXPECT_LT(difference[b], 1e-12) << kBlockNames[b] << " of " << Describe(mode, c);
    }
  }
}


INSTANTIATE_TEST_SUITE_P(AllModes, FlowDerivativesAgainstOdeint,
                         ::testing::Values(Mode::kSlipNegative, Mode::kSlipPositive, Mode::kStick),
                         ModeTestName);

TEST(OdeintVariationalReference, RejectsANegativeOrNonFiniteDuration) {
  const Parameters p{0.3, 4.0, 0.6, 0.1, 0.2996};
  const State start(0.1, -0.2, 0.3, -0.4);
  for (double s : {-1e-9, -1.0, std::numeric_limits<double>::infinity(),
                   std::numeric_limits<double>::quiet_NaN()}) {
    EXPECT_THROW(IntegrateModeWithDerivatives(Mode::kSlipNegative, start, 0.0, s, p), InvalidInput)
        << "s = " << s;
  }
}

// The static friction level enters no mode's equations, and a stick does not see the forcing.
TEST(OdeintVariationalReference, HasNoStaticFrictionColumnAndNoPhaseInAStick) {
  const Parameters p{0.3, 4.0, 0.6, 0.1, 0.2996};
  const State start(0.1, -0.2, 0.3, -0.4);
  for (Mode mode : {Mode::kSlipNegative, Mode::kSlipPositive, Mode::kStick}) {
    const FlowDerivatives numeric = IntegrateModeWithDerivatives(mode, start, 0.7, 5.0, p);
    EXPECT_TRUE(numeric.d_parameters.col(static_cast<int>(ParameterId::kStaticFriction))
                    .isZero(0.0))
        << ToString(mode);
    if (mode == Mode::kStick) {
      EXPECT_TRUE(numeric.d_phase.isZero(0.0));
    } else {
      EXPECT_FALSE(numeric.d_phase.isZero(1e-3)) << ToString(mode);
    }
  }
}

}  // namespace
}  // namespace stickslip
