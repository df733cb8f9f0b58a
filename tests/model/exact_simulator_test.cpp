// The exact simulator through the model interface, on a model other than the paper's: Den
// Hartog's one-mass oscillator (tests/support/den_hartog_oscillator.hpp), against his closed-form
// non-sticking orbit (../shared/FRICTION-LITERATURE.md).
#include "stickslip/model/exact_simulator.hpp"

#include <utility>

#include <gtest/gtest.h>

#include "stickslip/model/pascal_2014.hpp"
#include "support/den_hartog_orbit.hpp"
#include "support/den_hartog_oscillator.hpp"
#include "support/den_hartog_orbit.hpp"

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

}  // namespace
}  // namespace stickslip
