// The command line's numbers: strict decimal text, the whole of it, finite (no hexadecimal, no
// "inf", no leading space), so that a typo is an error rather than a different number.
#pragma once

#include <string_view>

namespace stickslip::cli {

// A decimal number, the whole text, finite; otherwise InvalidInput
// "<field> = '<text>' is not a finite number: valid range <valid_range>".
double ParseNumber(std::string_view field, std::string_view text, std::string_view valid_range);

// A whole number low <= value <= high written as a decimal number (ParseNumber's form: "40",
// "1e6", "+3"); otherwise InvalidInput "<field> = <value> is invalid: whole numbers low <= <field> <= high".
int ParseCount(std::string_view field, std::string_view text, int low, int high);

}  // namespace stickslip::cli
