#include "stickslip/orbits/signature.hpp"

#include <gtest/gtest.h>

namespace stickslip {
namespace {

Signature Parsed(const char* text) { return Signature::Parse(text); }

// The message of the InvalidInput that parsing `text` throws.
std::string ParseError(const char* text) {
  try {
    Signature::Parse(text);
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.field(), "signature");
    return e.what();
  }
  ADD_FAILURE() << "'" << text << "' parsed";
  return "";
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
  EXPECT_NE(ParseError("slip- stik").find("signature 'slip- stik': token 2 'stik'"), std::string::npos);
  EXPECT_NE(ParseError("slip- stick stick").find("segment 2 is a stick followed by a stick"), std::string::npos);
  EXPECT_NE(ParseError("stick slip+ stick").find("cyclically"), std::string::npos);
  EXPECT_NE(ParseError("").find("no segment"), std::string::npos);
  EXPECT_NE(ParseError("slip- / symmetric").find("option 'symmetric'"), std::string::npos);
  EXPECT_NE(ParseError("slip- / antisymmetric period 2").find("odd"), std::string::npos);
  EXPECT_NE(ParseError("slip- / period 0").find("period"), std::string::npos);
  EXPECT_NE(ParseError("slip- / period 1 period 3").find("option 'period' is given twice"), std::string::npos);
  EXPECT_NE(ParseError("slip- / antisymmetric antisymmetric").find("given twice"), std::string::npos);
}

}  // namespace
}  // namespace stickslip
