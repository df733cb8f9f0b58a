// The exact simulator against the independent Boost.Odeint simulator, from the paper's printed
// initial states.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "stickslip/model/pascal_2014/odeint_simulator.hpp"
#include "stickslip/model/pascal_2014/paper_examples.hpp"
#include "stickslip/model/simulation.hpp"

namespace stickslip {
namespace {

SimulationOptions Periods(const PaperExample& e, double periods) {
  SimulationOptions options;
  options.duration = periods * 2.0 * std::numbers::pi / e.parameters.omega;
  return options;
}

class ExactAgainstOdeint : public ::testing::TestWithParam<const char*> {};

// Same event sequence over two periods and event times within 1e-6: Odeint runs at tolerance
// 1e-12 and bisects events to 1e-12, so 1e-6 leaves room only for the growth of integration
// error over two periods, not for a missed or misclassified event.
TEST_P(ExactAgainstOdeint, GiveTheSameEventsOverTwoPeriods) {
  const PaperExample& e = *FindPaperExample(GetParam());
  const SimulationOptions options = Periods(e, 2.0);
  const SimulationResult exact = SimulateExact(e.parameters, e.initial_state, e.phi, options);
  const SimulationResult odeint = SimulateOdeint(e.parameters, e.initial_state, e.phi, options);
  ASSERT_TRUE(exact.Completed());
  ASSERT_TRUE(odeint.Completed());
  ASSERT_EQ(exact.events.size(), odeint.events.size());
  ASSERT_GE(exact.events.size(), 2u);
  for (std::size_t i = 0; i < exact.events.size(); ++i) {
    const Event& a = exact.events[i];
    const Event& b = odeint.events[i];
    EXPECT_STREQ(ToString(a.kind), ToString(b.kind)) << "event " << i;
    EXPECT_STREQ(ToString(a.mode_after), ToString(b.mode_after)) << "event " << i;
    EXPECT_NEAR(a.t, b.t, 1e-6) << "event " << i;
    EXPECT_LT((a.state - b.state).lpNorm<Eigen::Infinity>(), 1e-6) << "event " << i;
  }
}

INSTANTIATE_TEST_SUITE_P(PaperExamples, ExactAgainstOdeint,
                         ::testing::Values("paper-5.1", "paper-5.2", "paper-6"),
                         [](const ::testing::TestParamInfo<const char*>& name) {
                           std::string s = name.param;
                           for (char& c : s) {
                             if (c == '-' || c == '.') c = '_';
                           }
                           return s.substr(6);  // "5_1": digits only, no "paper_" prefix
                         });

// Section 4.2's abnormal stops are tangencies at u_r = u_s where the rounding of the printed
// state decides the outcome; the two simulators are compared up to the first stop only.
TEST(ExactAgainstOdeintSection42, AgreeUpToTheFirstStop) {
  const PaperExample& e = *FindPaperExample("paper-4.2");
  const SimulationOptions options = Periods(e, 1.0);
  const SimulationResult exact = SimulateExact(e.parameters, e.initial_state, e.phi, options);
  const SimulationResult odeint = SimulateOdeint(e.parameters, e.initial_state, e.phi, options);
  ASSERT_FALSE(exact.events.empty());
  ASSERT_FALSE(odeint.events.empty());
  EXPECT_EQ(exact.segments.front().mode, odeint.segments.front().mode);
  EXPECT_NEAR(exact.events.front().t, odeint.events.front().t, 1e-6);
  EXPECT_LT((exact.events.front().state - odeint.events.front().state).lpNorm<Eigen::Infinity>(),
            1e-6);
}

}  // namespace
}  // namespace stickslip
