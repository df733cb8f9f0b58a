// The modes of motion of a Coulomb contact: slipping one way, slipping the other, sticking. In
// Pascal 2014: slip with x2' < 0 (friction +u_s, eq. 5), slip with x2' > 0 ("overshooting",
// friction -u_s, eq. 8), stick with x2' = 0 (eq. 9-10). Signatures (orbits/signature.hpp) are
// written in these words.
#pragma once

#include <optional>
#include <string_view>

namespace stickslip {

enum class Mode { kSlipNegative, kSlipPositive, kStick };
const char* ToString(Mode mode);  // "slip-", "slip+", "stick"
std::optional<Mode> ModeFromString(std::string_view text);
// Sign of the contact's relative velocity in the mode: -1, +1, or 0 for a stick.
int SlipDirection(Mode mode);

}  // namespace stickslip
