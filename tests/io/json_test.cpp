#include "stickslip/io/json.hpp"

#include <gtest/gtest.h>

namespace stickslip {
namespace {

// RFC 8259 section 7: quotation mark, reverse solidus and the control characters U+0000 to
// U+001F must be escaped; everything else may stand as it is.
TEST(JsonString, EscapesWhatRfc8259RequiresAndNothingElse) {
  EXPECT_EQ(JsonString("slip- slip+ / period 2"), "\"slip- slip+ / period 2\"");
  EXPECT_EQ(JsonString("a \"quoted\" path\\name"), R"("a \"quoted\" path\\name")");
  EXPECT_EQ(JsonString("line\nbreak\ttab\rreturn"), R"("line\nbreak\ttab\rreturn")");
  EXPECT_EQ(JsonString(std::string_view("\x01\x1f\x00", 3)), R"("\u0001\u001f\u0000")");
  EXPECT_EQ(JsonString("\x7f §4.1"), "\"\x7f §4.1\"");
  EXPECT_EQ(JsonString(""), "\"\"");
}

}  // namespace
}  // namespace stickslip
