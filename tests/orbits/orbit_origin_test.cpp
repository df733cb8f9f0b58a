// The same orbit from another origin (orbits/orbit_origin.hpp): from every segment end of the
// paper's plain and antisymmetric orbits, the rotated orbit is verified as a periodic motion of its
// own signature by both simulators (independent of the closed-form walk that rotated it), with the
// same period; the antisymmetric orbit from its mirrored half starts at -X of its listed half.
#include "stickslip/orbits/orbit_origin.hpp"

#include <numbers>
#include <stdexcept>

#include <gtest/gtest.h>

#include "stickslip/orbits/verification.hpp"
#include "support/solved_presets.hpp"

namespace stickslip {
namespace {

class FromEveryOrigin : public ::testing::TestWithParam<const char*> {};

TEST_P(FromEveryOrigin, TheRotatedOrbitIsVerifiedBySimulation) {
  const Orbit orbit = SolvedPreset(GetParam());
  ASSERT_TRUE(VerifyOrbit(orbit).Passed());
  for (int j = 0; j < OriginCount(orbit.signature); ++j) {
    const Orbit rotated = WithOriginAt(orbit, j);
    const Verification check = VerifyOrbit(rotated);
    EXPECT_TRUE(check.Passed()) << "origin " << j << " (" << rotated.signature.ToString() << "): " << check.Report();
    EXPECT_DOUBLE_EQ(rotated.Period(), orbit.Period());
  }
}

INSTANTIATE_TEST_SUITE_P(Paper, FromEveryOrigin, ::testing::Values("paper-5.1", "paper-6"),
                         [](const ::testing::TestParamInfo<const char*>& param_info) {
                           return std::string(param_info.index == 0 ? "Paper51" : "Paper6");
                         });

TEST(WithOriginAt, TheMirroredHalfStartsAtTheMirrorImageHalfAPeriodLater) {
  const Orbit orbit = SolvedPreset("paper-6");  // 'slip- stick slip- / antisymmetric'
  const Orbit mirrored = WithOriginAt(orbit, orbit.signature.size());
  EXPECT_EQ(mirrored.signature.ToString(), "slip+ stick slip+ / antisymmetric");
  EXPECT_DOUBLE_EQ(mirrored.x10, -orbit.x10);
  EXPECT_DOUBLE_EQ(mirrored.x20, -orbit.x20);
  EXPECT_DOUBLE_EQ(mirrored.v10, -orbit.v10);
  EXPECT_NEAR(std::remainder(mirrored.phi - orbit.phi - std::numbers::pi, 2.0 * std::numbers::pi), 0.0, 1e-12);
  EXPECT_THROW(WithOriginAt(orbit, OriginCount(orbit.signature)), std::out_of_range);
}

}  // namespace
}  // namespace stickslip
