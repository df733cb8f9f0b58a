// The exact simulator through the model interface, on a model other than the paper's: Den
// Hartog's one-mass oscillator (tests/support/den_hartog_oscillator.hpp), against his closed-form
// non-sticking orbit (../shared/FRICTION-LITERATURE.md).
#include "stickslip/model/exact_simulator.hpp"

#include <cmath>
#include <numbers>
#include <utility>

#include <gtest/gtest.h>

#include "stickslip/model/odeint_simulation.hpp"
#include "stickslip/model/pascal_2014.hpp"
#include "support/den_hartog_orbit.hpp"
#include "support/den_hartog_oscillator.hpp"

namespace stickslip {
namespace {

static_assert(OscillatorModel<Pascal2014>);
static_assert(OscillatorModel<DenHartogOscillator>);

class DenHartogNonStickingOrbit : public testing::TestWithParam<std::pair<double, double>> {};

TEST_P(DenHartogNonStickingOrbit, IsWhatTheExactSimulatorFollowsThroughTheModelInterface) {
  ExpectDenHartogsOrbit([](const auto&... args) { return SimulateExact(args...); }, GetParam(), 1e-10);
}

INSTANTIATE_TEST_SUITE_P(FrequencyRatios, DenHartogNonStickingOrbit, testing::ValuesIn(kDenHartogNonStickingCases));

TEST(ExactSimulator, StartsAStickWhereDenHartogsConditionFails) {
  // At r = 0.8 the turning point holds when beta > r^2 X (FRICTION-LITERATURE.md): started at
  // rest on the non-sticking orbit's turning point with a larger static level, the mass sticks.
  const DenHartogOrbit orbit(0.8, 0.2);
  const DenHartogOscillator model = DenHartogModel();
  const double holding = 1.01 * 0.64 * orbit.amplitude;
  BasicSimulationOptions<DenHartogOscillator::State> options;
  options.duration = 1.0;
  const auto result =
      SimulateExact(model, {0.8, 0.2, holding}, DenHartogOscillator::State(orbit.amplitude, 0.0), orbit.phi, options);
  ASSERT_FALSE(result.segments.empty());
  EXPECT_EQ(result.segments.front().mode, Mode::kStick);
  EXPECT_EQ(InitialMode(model, DenHartogOscillator::State(orbit.amplitude, 0.0), orbit.phi,
                        DenHartogOscillator::Parameters{0.8, 0.2, 0.99 * 0.64 * orbit.amplitude}),
            Mode::kSlipNegative);
}

// Started at rest with the stick force on the static threshold, inside the band to rounding (an
// orbit's origin at a stick exit), the mass slips at once where the force is leaving the band and sticks where it
// is coming back into it, as Coulomb's law extended continuously says; the Odeint simulator, which
// integrates the equations of motion with its own event logic, follows the same motion. (The
// general model once took the threshold for inside the band and stuck there for a long while.)
TEST(ExactSimulator, OnTheStaticThresholdTheStickForcesRateDecidesAsTheIntegratorDoes) {
  const DenHartogOscillator model = DenHartogModel();
  const DenHartogOscillator::State rest(0.3, 0.0);
  BasicSimulationOptions<DenHartogOscillator::State> options;
  options.duration = 2.0;
  int slips = 0, sticks = 0;
  for (int k = 0; k < 16; ++k) {
    const double phi = 0.1 + 2.0 * std::numbers::pi * k / 16;
    const double force = model.StickForce(rest, phi, {1.5, 0.1, 0.1});
    for (const double rounding : {0.0, 4e-16, 1e-14}) {  // the level at or a rounding above the force
      const double level = std::abs(force) * (1.0 + rounding);
      const DenHartogOscillator::Parameters p{1.5, 0.8 * level, level};
      const auto exact = SimulateExact(model, p, rest, phi, options);
      const auto integrated = SimulateOdeint(model, p, rest, phi, options);
      ASSERT_TRUE(exact.Completed() && integrated.Completed()) << "phi = " << phi;
      EXPECT_EQ(exact.segments.front().mode, integrated.segments.front().mode) << "phi = " << phi;
      EXPECT_LE((exact.segments.back().end - integrated.segments.back().end).lpNorm<Eigen::Infinity>(), 1e-6)
          << "phi = " << phi << ", the level " << rounding << " off the force";
      ++(exact.segments.front().mode == Mode::kStick ? sticks : slips);
    }
  }
  EXPECT_GT(slips, 0);
  EXPECT_GT(sticks, 0);
}

}  // namespace
}  // namespace stickslip
