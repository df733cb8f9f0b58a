// Names for value-parameterised tests over the modes of motion and the paper's presets, and for
// typed tests over a model at a fixed size and sized at run time.
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

// Over the paper's presets: "paper-4.1" is "Section4_1".
inline std::string PresetTestName(const ::testing::TestParamInfo<const char*>& preset) {
  std::string name = std::string(preset.param).substr(6);
  for (char& c : name) c = c == '.' ? '_' : c;
  return "Section" + name;
}

// Over models of either size: "SizedAtCompileTime" or "SizedAtRunTime" (Eigen::Dynamic).
class ModelSizeName {
 public:
  template <typename Model>
  static std::string GetName(int) {
    return Model::kStateSize == Eigen::Dynamic ? "SizedAtRunTime" : "SizedAtCompileTime";
  }
};

}  // namespace stickslip
