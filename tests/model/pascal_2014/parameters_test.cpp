#include "stickslip/model/pascal_2014/parameters.hpp"

#include <limits>
#include <utility>

#include <gtest/gtest.h>

#include "stickslip/model/pascal_2014/modal.hpp"

namespace stickslip {
namespace {

Parameters Valid() { return {0.3, 4.0, 0.6, 0.1, 0.2996}; }

TEST(ParameterValidation, AcceptsThePaperExample) { EXPECT_FALSE(Validate(Valid()).has_value()); }

TEST(ParameterValidation, AcceptsEqualFrictionLevels) {
  Parameters p = Valid();
  p.u_r = p.u_s;
  EXPECT_FALSE(Validate(p).has_value());
}

// u_r >= u_s binds both levels: with u_s the value given, u_s is named with its range given u_r
// (a map's --second u_s above the trace's u_r named u_r and "u_s = 1000 <= u_r <= 1000").
TEST(ParameterValidation, NamesTheVariedFrictionLevelWithItsRangeGivenTheOther) {
  Parameters p = Valid();
  p.u_s = 1000.0;
  const auto as_u_s = Validate(p, ParameterId::kSlidingFriction);
  ASSERT_TRUE(as_u_s.has_value());
  EXPECT_EQ(as_u_s->field(), "u_s");
  EXPECT_EQ(as_u_s->valid_range(), "1e-06 <= u_s <= u_r = 0.2996");
  const auto as_u_r = Validate(p, ParameterId::kStaticFriction);
  ASSERT_TRUE(as_u_r.has_value());
  EXPECT_EQ(as_u_r->field(), "u_r");
  EXPECT_EQ(as_u_r->valid_range(), Validate(p)->valid_range());
  p.u_s = 0.1;
  p.chi = 5.0;
  EXPECT_EQ(Validate(p, ParameterId::kSlidingFriction)->field(), "chi");
}

struct BadCase {
  ParameterId field;
  double value;
};

class ParameterValidationRejects : public ::testing::TestWithParam<BadCase> {};

TEST_P(ParameterValidationRejects, NamesTheFieldAndTheValidRange) {
  Parameters p = Valid();
  p[GetParam().field] = GetParam().value;
  const auto invalid = Validate(p);
  ASSERT_TRUE(invalid.has_value());
  EXPECT_EQ(invalid->field(), ToString(GetParam().field));
  EXPECT_NE(std::string(invalid->what()).find(ToString(GetParam().field)), std::string::npos);
  EXPECT_NE(std::string(invalid->what()).find("valid range"), std::string::npos);
}

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

INSTANTIATE_TEST_SUITE_P(
    OutOfRange, ParameterValidationRejects,
    ::testing::Values(BadCase{ParameterId::kChi, 0.0}, BadCase{ParameterId::kChi, 1.0},
                      BadCase{ParameterId::kChi, -0.2}, BadCase{ParameterId::kEta, 0.0},
                      BadCase{ParameterId::kOmega, -1.0}, BadCase{ParameterId::kOmega, 0.0},
                      BadCase{ParameterId::kSlidingFriction, 0.0},
                      BadCase{ParameterId::kStaticFriction, 0.05},
                      BadCase{ParameterId::kEta, kNaN}, BadCase{ParameterId::kOmega, kInf},
                      BadCase{ParameterId::kStaticFriction, kNaN}));

// Just outside each magnitude bound, and far outside (the values that overflowed or hung).
INSTANTIATE_TEST_SUITE_P(
    BeyondTheMagnitudes, ParameterValidationRejects,
    ::testing::Values(BadCase{ParameterId::kChi, 0.0099}, BadCase{ParameterId::kChi, 0.9901},
                      BadCase{ParameterId::kEta, 0.0099}, BadCase{ParameterId::kEta, 100.01},
                      BadCase{ParameterId::kEta, 1e308}, BadCase{ParameterId::kOmega, 0.0099},
                      BadCase{ParameterId::kOmega, 1e-300}, BadCase{ParameterId::kOmega, 100.01},
                      BadCase{ParameterId::kSlidingFriction, 9.9e-7},
                      BadCase{ParameterId::kSlidingFriction, 1e-16},
                      BadCase{ParameterId::kSlidingFriction, 1000.1},
                      BadCase{ParameterId::kStaticFriction, 1000.1},
                      BadCase{ParameterId::kStaticFriction, 1e308}));

TEST(ParameterValidation, AcceptsEachEndOfEachMagnitudeRange) {
  const std::pair<ParameterId, double> ends[] = {
      {ParameterId::kChi, kMinChi},      {ParameterId::kChi, kMaxChi},     {ParameterId::kEta, kMinEta},
      {ParameterId::kEta, kMaxEta},      {ParameterId::kOmega, kMinOmega}, {ParameterId::kOmega, kMaxOmega},
      {ParameterId::kSlidingFriction, kMinSlidingFriction},             {ParameterId::kStaticFriction, kMaxFriction}};
  for (const auto& [id, value] : ends) {
    Parameters p = Valid();
    p[id] = value;
    EXPECT_FALSE(Validate(p).has_value()) << ToString(id) << " = " << value;
  }
  Parameters both = Valid();
  both.u_s = both.u_r = kMaxFriction;
  EXPECT_FALSE(Validate(both).has_value());
}

TEST(StateValidation, AcceptsTheBoundAndRejectsBeyondItNamingTheField) {
  EXPECT_FALSE(ValidateStateValue("x10", kMaxStateMagnitude).has_value());
  EXPECT_FALSE(ValidateStateValue("phi", -kMaxStateMagnitude).has_value());
  for (double value : {1.0000001e6, -1e308, kNaN}) {
    const auto invalid = ValidateStateValue("v20", value);
    ASSERT_TRUE(invalid.has_value()) << value;
    EXPECT_EQ(invalid->field(), "v20");
    EXPECT_EQ(invalid->valid_range(), kStateRange);
  }
}

TEST(ParameterValidation, RejectsForcingAtEachNaturalFrequency) {
  Parameters p = Valid();
  const auto [w1, w2] = NaturalFrequencies(p.chi, p.eta);
  for (double w : {w1, w2}) {
    p.omega = w;
    const auto invalid = Validate(p);
    ASSERT_TRUE(invalid.has_value());
    EXPECT_EQ(invalid->field(), "omega");
  }
}

TEST(ParameterIds, RoundTripThroughTheirNames) {
  for (ParameterId id : kAllParameters) EXPECT_EQ(ParameterFromString(ToString(id)), id);
  EXPECT_FALSE(ParameterFromString("mu").has_value());
}

}  // namespace
}  // namespace stickslip
