#include "stickslip/model/model_description.hpp"

#include <algorithm>
#include <utility>

#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"

namespace stickslip {

std::optional<int> ModelDescription::ParameterIndex(std::string_view wanted) const {
  for (int k = 0; k < ParameterCount(); ++k) {
    if (parameters[k].name == wanted) return k;
  }
  return std::nullopt;
}

int ModelDescription::VariedParameter(std::string_view field, const std::string& parameter, bool autonomous,
                                      std::string_view varied_already) const {
  const std::optional<int> k = ParameterIndex(parameter);
  if (k && !(*k == 0 && autonomous)) return *k;
  std::string names;
  for (int i = autonomous ? 1 : 0; i < ParameterCount(); ++i) {
    if (parameters[i].name != varied_already) names += (names.empty() ? "" : ", ") + parameters[i].name;
  }
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
  for (const auto& [name, member] : ModelUnits::kNamed) {
    const std::string& unit = units.*member;
    const auto spaced = [&](std::string_view end) { return unit.starts_with(end) || unit.ends_with(end); };
    const char* wrong = unit.empty() || unit.size() > kMaxUnitBytes                 ? "it has {} bytes (UTF-8)"
                        : spaced(" ") || spaced("\u00a0")                          ? "it has a space at an end"
                        : HoldsControlCharacter(unit)                               ? "it has a control character"
                        : unit.find('$') != std::string::npos                       ? "it has a '$' (figures' math markup)"
                                                                                    : nullptr;
    if (!wrong) continue;
    throw InvalidInput(std::string("units.") + name, fmt::format("'{}'", unit),
                       fmt::format("a unit's name of 1 to {} bytes without spaces at its ends, control characters or "
                                   "'$' (\"mm\", \"ms\", \"kN\"): {}",
                                   kMaxUnitBytes, fmt::format(fmt::runtime(wrong), unit.size())));
  }
}

}  // namespace stickslip
