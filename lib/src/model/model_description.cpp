#include "stickslip/model/model_description.hpp"

#include <algorithm>
#include <utility>

#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"

namespace stickslip {

std::optional<int> ModelDescription::ParameterIndex(std::string_view name) const {
  for (int k = 0; k < ParameterCount(); ++k) {
    if (parameters[k].name == name) return k;
  }
  return std::nullopt;
}

int ModelDescription::VariedParameter(std::string_view field, const std::string& parameter, bool autonomous) const {
  const std::optional<int> k = ParameterIndex(parameter);
  if (k && !(*k == 0 && autonomous)) return *k;
  std::string names;
  for (int i = autonomous ? 1 : 0; i < ParameterCount(); ++i) names += (names.empty() ? "" : ", ") + parameters[i].name;
  throw InvalidInput(std::string(field), "'" + parameter + "'",
                     autonomous ? names + fmt::format(" ({} plays no part without forcing)", parameters[0].name) : names);
}


void CheckUnits(const ModelUnits& units) {
  for (const auto& [field, unit] : {std::pair{"units.length", &units.length}, std::pair{"units.time", &units.time},
                                    std::pair{"units.force", &units.force}}) {
    const bool printable = std::none_of(unit->begin(), unit->end(), [](char c) {
      return (static_cast<unsigned char>(c) < 0x20) || c == 0x7f || c == '$';
    });
    if (unit->empty() || unit->size() > kMaxUnitBytes || !printable) {
      throw InvalidInput(field, fmt::format("'{}'", *unit),
                         fmt::format("a unit's name of 1 to {} characters, without control characters or '$' (\"mm\", "
                                     "\"ms\", \"kN\")",
                                     kMaxUnitBytes));
    }
  }
}

}  // namespace stickslip
