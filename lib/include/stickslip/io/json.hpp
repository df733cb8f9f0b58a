// The one piece of JSON writing stickslip needs beyond numbers: a string literal.
#pragma once

#include <string>
#include <string_view>

namespace stickslip {

// `text` as a JSON string literal (RFC 8259): quoted, with '"', '\' and control characters
// escaped. Bytes >= 0x80 pass through (the text is taken to be UTF-8).
std::string JsonString(std::string_view text);

}  // namespace stickslip
