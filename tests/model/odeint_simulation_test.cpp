// The Odeint simulator through the model interface (model/odeint_simulation.hpp), on a model other
// than the paper's: Den Hartog's one-mass oscillator (tests/support/den_hartog_oscillator.hpp)
// against his closed-form non-sticking orbit, and against the exact simulator where the mass
// sticks. And the paper's model's equations of motion (what the integrator is given) against its
// closed forms.
#include "stickslip/model/odeint_simulation.hpp"

#include <random>
#include <utility>

#include <gtest/gtest.h>

#include "stickslip/model/pascal_2014/events.hpp"
#include "stickslip/model/exact_simulator.hpp"
#include "stickslip/model/pascal_2014.hpp"
#include "support/den_hartog_orbit.hpp"
#include "support/den_hartog_oscillator.hpp"

namespace stickslip {
namespace {

static_assert(IntegrableOscillatorModel<Pascal2014>);
static_assert(IntegrableOscillatorModel<DenHartogOscillator>);

using DenHartogState = DenHartogOscillator::State;

class DenHartogNonStickingOrbitUnderOdeint : public testing::TestWithParam<std::pair<double, double>> {};

TEST_P(DenHartogNonStickingOrbitUnderOdeint, IsWhatTheOdeintSimulatorFollowsThroughTheModelInterface) {
  ExpectDenHartogsOrbit([](const auto&... args) { return SimulateOdeint(args...); }, GetParam(), 1e-8);
}

INSTANTIATE_TEST_SUITE_P(FrequencyRatios, DenHartogNonStickingOrbitUnderOdeint, testing::ValuesIn(kDenHartogNonStickingCases));

// Started at rest on the non-sticking orbit's turning point with a static level above r^2 X, the
// mass sticks there (Den Hartog's condition) and again at the upper turning points two and four
// periods later; the two simulators agree on every stick, stick exit and stop over the four
// periods.
TEST(OdeintSimulator, AgreesWithTheExactSimulatorOnDenHartogsStickSlip) {
  const DenHartogOrbit orbit(0.8, 0.2);
  const DenHartogOscillator model = DenHartogModel();
  const DenHartogOscillator::Parameters p{0.8, 0.2, 1.01 * 0.64 * orbit.amplitude};
  const DenHartogState start(orbit.amplitude, 0.0);
  BasicSimulationOptions<DenHartogState> options;
  options.duration = 4.0 * orbit.Period();
  const auto exact = SimulateExact(model, p, start, orbit.phi, options);
  const auto odeint = SimulateOdeint(model, p, start, orbit.phi, options);
  ASSERT_TRUE(exact.Completed()) << exact.message;
  ASSERT_TRUE(odeint.Completed()) << odeint.message;
  ASSERT_EQ(exact.segments.front().mode, Mode::kStick);
  ASSERT_EQ(odeint.segments.front().mode, Mode::kStick);
  ASSERT_EQ(exact.events.size(), odeint.events.size());
  int sticks = 0;
  for (std::size_t i = 0; i < exact.events.size(); ++i) {
    EXPECT_EQ(exact.events[i].kind, odeint.events[i].kind) << "event " << i;
    EXPECT_EQ(exact.events[i].mode_after, odeint.events[i].mode_after) << "event " << i;
    EXPECT_NEAR(exact.events[i].t, odeint.events[i].t, 1e-8) << "event " << i;
    EXPECT_LT((exact.events[i].state - odeint.events[i].state).lpNorm<Eigen::Infinity>(), 1e-8) << "event " << i;
    sticks += exact.events[i].mode_after == Mode::kStick;
  }
  EXPECT_GE(sticks, 2);  // sticks after the start, not only at it
}

// What the integrator is given for the paper's model, written from eq. (2), against the closed
// forms: the vector field is the closed-form motion's rate at its start (in a stick from rest),
// the holding force and its rate are the stick force of eq. (11) and its rate at rest.
TEST(Pascal2014, GivesTheIntegratorTheEquationsTheClosedFormsSolve) {
  const Pascal2014 model;
  std::mt19937 rng(2014);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int trial = 0; trial < 50; ++trial) {
    const Parameters p{0.5 + 0.2 * u(rng), 2.0 + u(rng), 1.0 + 0.4 * u(rng), 0.15 + 0.05 * u(rng), 0.3};
    const State x(u(rng), u(rng), u(rng), u(rng));
    const double phase = 3.0 * u(rng);
    for (Mode mode : {Mode::kSlipNegative, Mode::kSlipPositive, Mode::kStick}) {
      const State start = mode == Mode::kStick ? AtRest(x) : x;
      const ModeMotion<double> motion = model.MotionInMode(mode, start, phase, p);
      State rate;
      for (int i = 0; i < 4; ++i) rate(i) = CoordinateAlong(motion, i).Derivative()(0.0);
      EXPECT_LT((model.VectorField(mode, start, phase, p) - rate).lpNorm<Eigen::Infinity>(), 1e-11) << ToString(mode);
    }
    EXPECT_NEAR(model.HoldingForce(x, phase, p), model.StickForce(x, phase, p), 1e-14);
    EXPECT_NEAR(model.HoldingForceRate(x, phase, p), StickForceRate(AtRest(x), phase, p), 1e-14);
  }
}

}  // namespace
}  // namespace stickslip
