// The one exception for bad input: its message, and the field renamed for a front end.
#include "stickslip/invalid_input.hpp"

#include <string>

#include <gtest/gtest.h>

namespace stickslip {
namespace {

TEST(InvalidInput, NamesFieldValueAndValidRangeInOneLine) {
  const InvalidInput e("omega", -1.0, "omega > 0");
  EXPECT_STREQ(e.what(), "omega = -1 is invalid: valid range omega > 0");
  EXPECT_EQ(e.Predicate(), "= -1 is invalid: valid range omega > 0");
}

TEST(InvalidInput, RenamingReplacesTheLeadingFieldOnly) {
  const InvalidInput e = InvalidInput::WithMessage("restart", "restart = 'a:B1' cannot be used: no restart here");
  const InvalidInput renamed = e.Renamed("point");
  EXPECT_EQ(renamed.field(), "point");
  EXPECT_STREQ(renamed.what(), "point = 'a:B1' cannot be used: no restart here");
}

TEST(InvalidInput, RenamingAStandardViolationRenamesTheFieldInItsRangeToo) {
  const InvalidInput e("loop_tolerance", 1.0, "0 < loop_tolerance <= 1e-2");
  const InvalidInput renamed = e.Renamed("loop-tolerance");
  EXPECT_EQ(renamed.valid_range(), "0 < loop-tolerance <= 1e-2");
  EXPECT_STREQ(renamed.what(), "loop-tolerance = 1 is invalid: valid range 0 < loop-tolerance <= 1e-2");
}

TEST(InvalidInput, AMessageNotLedByItsFieldKeepsItsText) {
  const InvalidInput e = InvalidInput::WithMessage("unknowns", "the system is not square");
  EXPECT_EQ(e.Predicate(), "the system is not square");
  EXPECT_STREQ(e.Renamed("choice").what(), "the system is not square");
}

}  // namespace
}  // namespace stickslip
