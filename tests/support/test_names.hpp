// Names for value-parameterised tests over the modes of motion.
#pragma once

#include <string>

#include <gtest/gtest.h>

#include "stickslip/model/pascal_2014/flows.hpp"

namespace stickslip {

inline std::string ModeTestName(const ::testing::TestParamInfo<Mode>& mode) {
  switch (mode.param) {
    case Mode::kSlipNegative: return "SlipNegative";
    case Mode::kSlipPositive: return "SlipPositive";
    case Mode::kStick: break;
  }
  return "Stick";
}

}  // namespace stickslip
