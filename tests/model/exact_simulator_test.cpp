// The exact simulator through the model interface, on a model other than the paper's: Den
// Hartog's one-mass oscillator (tests/support/den_hartog_oscillator.hpp), against his closed-form
// non-sticking orbit (../shared/FRICTION-LITERATURE.md).
#include "stickslip/model/exact_simulator.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "stickslip/model/pascal_2014.hpp"
#include "support/den_hartog_oscillator.hpp"
#include "support/den_hartog_orbit.hpp"

namespace stickslip {
namespace {

constexpr double kPi = std::numbers::pi;

static_assert(OscillatorModel<Pascal2014>);
static_assert(OscillatorModel<DenHartogOscillator>);

class DenHartogNonStickingOrbit : public testing::TestWithParam<std::pair<double, double>> {};

TEST_P(DenHartogNonStickingOrbit, IsWhatTheExactSimulatorFollowsThroughTheModelInterface) {
  const auto [r, beta] = GetParam();
  const DenHartogOrbit orbit(r, beta);
  ASSERT_GT(r * r * orbit.amplitude, beta) << "the orbit must not stick at its turning points";
  const DenHartogOscillator model;
  const DenHartogOscillator::Parameters p{r, beta, beta};
  ASSERT_FALSE(model.Validate(p));
  const double period = 2.0 * kPi / r;
  BasicSimulationOptions<DenHartogOscillator::State> options;
  options.duration = 1.25 * period;  // the second stop inside the horizon, not on it
  options.sample_step = period / 40.0;
  const auto result = SimulateExact(model, p, DenHartogOscillator::State(orbit.amplitude, 0.0), orbit.phi, options);
  ASSERT_TRUE(result.Completed()) << result.message;
  // Two stops per period, at the turning points, each a reversal: no stick.
  ASSERT_EQ(result.events.size(), 2u);
  EXPECT_NEAR(result.events[0].t, 0.5 * period, 1e-10);
  EXPECT_EQ(result.events[0].mode_after, Mode::kSlipPositive);
  EXPECT_NEAR(result.events[0].state(0), -orbit.amplitude, 1e-10);
  EXPECT_NEAR(result.events[1].t, period, 1e-10);
  EXPECT_EQ(result.events[1].mode_after, Mode::kSlipNegative);
  EXPECT_NEAR(result.events[1].state(0), orbit.amplitude, 1e-10);
  // Every sample on the closed form, the second half by x(t + T/2) = -x(t).
  for (const auto& sample : result.samples) {
    if (sample.t > period) break;
    const bool second_half = sample.t > 0.5 * period;
    const double expected = second_half ? -orbit.X(sample.t - 0.5 * period) : orbit.X(sample.t);
    EXPECT_NEAR(sample.state(0), expected, 1e-10) << "t = " << sample.t;
  }
}

// r >= 1/2 away from the degenerate 1/(2n) and from resonance; beta at half the largest value
// without a stick, r^2 X > beta.
INSTANTIATE_TEST_SUITE_P(FrequencyRatios, DenHartogNonStickingOrbit,
                         testing::Values(std::pair{0.6, 0.1}, std::pair{0.8, 0.2}, std::pair{1.5, 0.25},
                                         std::pair{2.5, 0.25}));

TEST(ExactSimulator, StartsAStickWhereDenHartogsConditionFails) {
  // At r = 0.8 the turning point holds when beta > r^2 X (FRICTION-LITERATURE.md): started at
  // rest on the non-sticking orbit's turning point with a larger static level, the mass sticks.
  const DenHartogOrbit orbit(0.8, 0.2);
  const DenHartogOscillator model;
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

}  // namespace
}  // namespace stickslip
