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


namespace {

// Whether `text` holds a control character: ASCII's (and DEL), Unicode's C1 (U+0080-U+009F), or
// the line and paragraph separators and direction marks that garble a terminal's line
// (U+200E-U+200F, U+2028-U+202E, U+2066-U+2069), in UTF-8.
bool HoldsControlCharacter(std::string_view text) {
  const auto byte = [&](std::size_t i) { return i < text.size() ? static_cast<unsigned char>(text[i]) : 0u; };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const unsigned c = byte(i);
    if (c < 0x20 || c == 0x7f) return true;
    if (c == 0xc2 && byte(i + 1) >= 0x80 && byte(i + 1) <= 0x9f) return true;
    if (c == 0xe2 && byte(i + 1) == 0x80 && (byte(i + 2) == 0x8e || byte(i + 2) == 0x8f ||
                                              (byte(i + 2) >= 0xa8 && byte(i + 2) <= 0xae))) {
      return true;
    }
    if (c == 0xe2 && byte(i + 1) == 0x81 && byte(i + 2) >= 0xa6 && byte(i + 2) <= 0xa9) return true;
  }
  return false;
}

}  // namespace

void CheckUnits(const ModelUnits& units) {
  for (const auto& [field, unit] : {std::pair{"units.length", &units.length}, std::pair{"units.time", &units.time},
                                    std::pair{"units.force", &units.force}}) {
    const bool blank = unit->find_first_not_of(' ') == std::string::npos;
    if (blank || unit->size() > kMaxUnitBytes || HoldsControlCharacter(*unit) || unit->find('$') != std::string::npos) {
      throw InvalidInput(field, fmt::format("'{}'", *unit),
                         fmt::format("a unit's name of 1 to {} bytes (UTF-8), not blank, without control characters "
                                     "or '$' (\"mm\", \"ms\", \"kN\")",
                                     kMaxUnitBytes));
    }
  }
}

}  // namespace stickslip
