#include "stickslip/model/mode.hpp"

namespace stickslip {

const char* ToString(Mode mode) {
  switch (mode) {
    case Mode::kSlipNegative: return "slip-";
    case Mode::kSlipPositive: return "slip+";
    case Mode::kStick: break;
  }
  return "stick";
}

std::optional<Mode> ModeFromString(std::string_view text) {
  for (Mode m : {Mode::kSlipNegative, Mode::kSlipPositive, Mode::kStick}) {
    if (text == ToString(m)) return m;
  }
  return std::nullopt;
}

int SlipDirection(Mode mode) {
  switch (mode) {
    case Mode::kSlipNegative: return -1;
    case Mode::kSlipPositive: return 1;
    case Mode::kStick: break;
  }
  return 0;
}

}  // namespace stickslip
