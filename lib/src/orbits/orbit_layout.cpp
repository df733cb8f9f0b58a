#include "stickslip/orbits/orbit_layout.hpp"

#include <fmt/format.h>

namespace stickslip {

std::string OrbitLayout::Name(int index) const {
  if (index < StartVariables()) return model_->initial_state[index];
  if (index == Phi()) return "phi";
  if (index < Parameter(0)) return fmt::format("d{}", index - Phi());
  return model_->parameters[index - Parameter(0)].name;
}

std::optional<int> OrbitLayout::IndexOf(std::string_view name) const {
  for (int i = 0; i < Count(); ++i) {
    if (Name(i) == name) return i;
  }
  return std::nullopt;
}

}  // namespace stickslip
