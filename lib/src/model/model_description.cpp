#include "stickslip/model/model_description.hpp"

namespace stickslip {

std::optional<int> ModelDescription::ParameterIndex(std::string_view name) const {
  for (int k = 0; k < ParameterCount(); ++k) {
    if (parameters[k].name == name) return k;
  }
  return std::nullopt;
}

}  // namespace stickslip
