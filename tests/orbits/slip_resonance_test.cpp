// Where a forced orbit that never sticks has no bounded amplitude: the nearest natural frequency of
// an undamped slip, against the closed forms (eq. 56's roots by the quadratic formula; Den
// Hartog's oscillator k = m = 1), and none where the orbit sticks, the slip is damped or nothing
// forces the model.
#include "stickslip/orbits/slip_resonance.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "support/den_hartog_oscillator.hpp"

namespace stickslip {
namespace {

Orbit NonSticking(double omega) {
  return Orbit{Signature::Parse("slip- / antisymmetric"), {0.3, 4.0, omega, 0.1, 0.2996}, 1.0, 2.0, 0.1, 0.3,
               {std::numbers::pi / omega}};
}

TEST(NearestSlipResonance, OfTheNonStickingPaperOrbitIsTheNearerRootOfEq56) {
  const double b = 1.0 + 0.3 * 4.0, c = 0.3 * 4.0 * 0.7;
  const double omega1 = std::sqrt(0.5 * (b - std::sqrt(b * b - 4.0 * c)));
  const double omega2 = std::sqrt(0.5 * (b + std::sqrt(b * b - 4.0 * c)));
  const std::optional<SlipResonance> low = NearestSlipResonance(NonSticking(0.69));
  ASSERT_TRUE(low);
  EXPECT_EQ(low->index, 1);
  EXPECT_NEAR(low->frequency, omega1, 1e-14);
  EXPECT_NEAR(low->distance, (omega1 - 0.69) / omega1, 1e-14);
  const std::optional<SlipResonance> high = NearestSlipResonance(NonSticking(1.2));
  ASSERT_TRUE(high);
  EXPECT_EQ(high->index, 2);
  EXPECT_NEAR(high->frequency, omega2, 1e-14);
}

TEST(NearestSlipResonance, IsNoneForAnOrbitThatSticks) {
  Orbit o = NonSticking(0.7);
  o.signature = Signature::Parse("slip- stick slip+ stick");
  o.durations = {1.0, 1.0, 1.0, 1.0};
  EXPECT_FALSE(NearestSlipResonance(o));
}

TEST(NearestSlipResonance, IsNoneWhereTheSlipIsDampedOrNothingForcesTheModel) {
  const BasicOrbit<LinearOscillator<1>> o{Signature::Parse("slip- slip+"), {0.9, 0.1, 0.1, 0.0}, {1.0, 0.0}, 0.0,
                                          {1.0, 1.0}};
  const std::optional<SlipResonance> undamped = NearestSlipResonance(DenHartogModel(), o);
  ASSERT_TRUE(undamped);
  EXPECT_EQ(undamped->index, 1);
  EXPECT_NEAR(undamped->frequency, 1.0, 1e-14);
  EXPECT_NEAR(undamped->distance, 0.1, 1e-14);
  LinearOscillatorData damped = DenHartogData();
  damped.damping = Eigen::MatrixXd::Constant(1, 1, 0.05);
  EXPECT_FALSE(NearestSlipResonance(LinearOscillator<1>(damped), o));
  LinearOscillatorData free = DenHartogData();
  free.forcing = Eigen::VectorXd::Zero(1);
  EXPECT_FALSE(NearestSlipResonance(LinearOscillator<1>(free), o));
}

}  // namespace
}  // namespace stickslip
