// A number as the io layer's JSON writers store it: null where it is not finite (JSON has no NaN
// or infinity; a reader sees null, not a token it cannot parse).
#pragma once

#include <cmath>

#include <nlohmann/json.hpp>

namespace stickslip::detail {

inline nlohmann::ordered_json JsonNumber(double x) { return std::isfinite(x) ? nlohmann::ordered_json(x) : nullptr; }

}  // namespace stickslip::detail
