#include "stickslip/orbits/signature.hpp"

#include <gtest/gtest.h>

namespace stickslip {
namespace {

Signature Parsed(const char* text) {
  std::string error;
  const auto s = Signature::Parse(text, &error);
  EXPECT_TRUE(s.has_value()) << error;
  return *s;
}

TEST(Signature, DerivesEveryEndFromTheNextMode) {
  const Signature s = Parsed("slip- slip- slip+ stick slip+ stick");
  EXPECT_EQ(s.EndKind(0), SegmentEndKind::kAbnormalStop);
  EXPECT_EQ(s.EndKind(1), SegmentEndKind::kReversal);
  EXPECT_EQ(s.EndKind(2), SegmentEndKind::kStickEntry);
  EXPECT_EQ(s.EndKind(3), SegmentEndKind::kExitToPositive);
  EXPECT_EQ(s.EndKind(4), SegmentEndKind::kStickEntry);
  EXPECT_EQ(s.EndKind(5), SegmentEndKind::kExitToNegative);  // cyclically back to slip-
}

TEST(Signature, AntisymmetricOrbitContinuesWithTheMirrorOfItsFirstSegment) {
  const Signature s = Parsed("slip- stick slip- / antisymmetric");
  EXPECT_TRUE(s.antisymmetric());
  EXPECT_EQ(s.NextMode(2), Mode::kSlipPositive);
  EXPECT_EQ(s.EndKind(2), SegmentEndKind::kReversal);
  EXPECT_EQ(s.FullPeriod().size(), 6u);
  EXPECT_EQ(s.FullPeriod()[3], Mode::kSlipPositive);
  EXPECT_DOUBLE_EQ(s.CoveredFraction(), 0.5);
}

TEST(Signature, RoundTripsThroughItsTextForm) {
  for (const char* text : {"slip- slip+ stick slip+", "slip- stick slip- / antisymmetric",
                           "slip- slip+ / period 2", "slip- / antisymmetric period 3"}) {
    EXPECT_EQ(Parsed(text).ToString(), text);
  }
}

TEST(Signature, ParseErrorsSayWhereAndWhy) {
  std::string error;
  EXPECT_FALSE(Signature::Parse("slip- stik", &error));
  EXPECT_NE(error.find("token 2 'stik'"), std::string::npos) << error;
  EXPECT_FALSE(Signature::Parse("slip- stick stick", &error));
  EXPECT_NE(error.find("segment 2 is a stick followed by a stick"), std::string::npos) << error;
  EXPECT_FALSE(Signature::Parse("stick slip+ stick", &error));
  EXPECT_NE(error.find("cyclically"), std::string::npos) << error;
  EXPECT_FALSE(Signature::Parse("", &error));
  EXPECT_NE(error.find("no segment"), std::string::npos) << error;
  EXPECT_FALSE(Signature::Parse("slip- / symmetric", &error));
  EXPECT_NE(error.find("option 'symmetric'"), std::string::npos) << error;
  EXPECT_FALSE(Signature::Parse("slip- / antisymmetric period 2", &error));
  EXPECT_NE(error.find("odd"), std::string::npos) << error;
  EXPECT_FALSE(Signature::Parse("slip- / period 0", &error));
  EXPECT_NE(error.find("period"), std::string::npos) << error;
}

}  // namespace
}  // namespace stickslip
