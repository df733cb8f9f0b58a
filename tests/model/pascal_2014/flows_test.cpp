// Exact derivatives of the flows against central finite differences, and the flows against the
// equations of motion (2) they solve.
#include "stickslip/model/pascal_2014/flows.hpp"

#include <random>

#include <gtest/gtest.h>

#include "support/random_flow_cases.hpp"
#include "support/test_names.hpp"

namespace stickslip {
namespace {

std::vector<FlowCase> RandomCases(Mode mode, int count) {
  return RandomFlowCases(mode, count, 7u + static_cast<unsigned>(mode));
}

class FlowDerivativesTest : public ::testing::TestWithParam<Mode> {};

TEST_P(FlowDerivativesTest, MatchCentralFiniteDifferences) {
  for (const FlowCase& c : RandomCases(GetParam(), 25)) {
    const FlowDerivatives d = FlowWithDerivatives(c.mode, c.start, c.phase, c.s, c.p);
    EXPECT_LT((d.state - Flow(c.mode, c.start, c.phase, c.s, c.p)).norm(), 1e-14);
    const double h = 1e-6;
    auto check = [&](const Eigen::Vector4d& exact, auto&& flow_of, const char* what) {
      const Eigen::Vector4d fd = (flow_of(h) - flow_of(-h)) / (2 * h);
      const double scale = 1.0 + exact.lpNorm<Eigen::Infinity>();
      EXPECT_LT((exact - fd).lpNorm<Eigen::Infinity>(), 1e-7 * scale)
          << what << " in " << ToString(c.mode) << "\nexact " << exact.transpose() << "\nfd    "
          << fd.transpose();
    };
    for (int i = 0; i < 4; ++i) {
      check(d.d_start.col(i), [&](double e) {
        State x = c.start;
        x(i) += e;
        return Flow(c.mode, x, c.phase, c.s, c.p);
      }, "d/dstart");
    }
    check(d.d_elapsed, [&](double e) { return Flow(c.mode, c.start, c.phase, c.s + e, c.p); }, "d/ds");
    check(d.d_phase, [&](double e) { return Flow(c.mode, c.start, c.phase + e, c.s, c.p); }, "d/dphase");
    for (int k = 0; k < kParameterCount; ++k) {
      check(d.d_parameters.col(k), [&](double e) {
        Parameters q = c.p;
        q[kAllParameters[k]] += e;
        return Flow(c.mode, c.start, c.phase, c.s, q);
      }, ToString(kAllParameters[k]));
    }
  }
}

// The time derivative of the flow is the vector field of eq. (2) (eq. 9 in a stick), evaluated
// independently of the closed form by Acceleration.
TEST_P(FlowDerivativesTest, TimeDerivativeIsTheEquationOfMotion) {
  for (const FlowCase& c : RandomCases(GetParam(), 25)) {
    const FlowDerivatives d = FlowWithDerivatives(c.mode, c.start, c.phase, c.s, c.p);
    const Eigen::Vector2d a = Acceleration(c.mode, d.state, c.phase + c.p.omega * c.s, c.p);
    EXPECT_LT((d.d_elapsed.head<2>() - d.state.tail<2>()).norm(), 1e-12);
    EXPECT_LT((d.d_elapsed.tail<2>() - a).norm(), 1e-10 * (1.0 + a.norm()));
  }
}

TEST(FlowDerivatives, StaticFrictionDoesNotEnterAnyFlow) {
  for (Mode mode : {Mode::kSlipNegative, Mode::kSlipPositive, Mode::kStick}) {
    const FlowCase c = RandomCases(mode, 1).front();
    const int u_r = static_cast<int>(ParameterId::kStaticFriction);
    EXPECT_EQ(FlowWithDerivatives(mode, c.start, c.phase, c.s, c.p).d_parameters.col(u_r).norm(), 0.0);
  }
}

INSTANTIATE_TEST_SUITE_P(EveryMode, FlowDerivativesTest,
                         ::testing::Values(Mode::kSlipNegative, Mode::kSlipPositive, Mode::kStick),
                         ModeTestName);

}  // namespace
}  // namespace stickslip
