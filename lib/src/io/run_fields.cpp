#include "stickslip/io/run_fields.hpp"

#include <algorithm>
#include <array>
#include <utility>

namespace stickslip {

namespace {

// The start problem's fields and their run-file keys.
constexpr std::array<std::pair<std::string_view, std::string_view>, 10> kStartFieldKeys = {{
    {"preset", "start.preset"},
    {"signature", "start.signature"},
    {"restart", "start.restart"},
    {"set", "start.set"},
    {"guess", "start.guess"},
    {"free", "unknowns.free"},
    {"fix", "unknowns.fix"},
    {"tie_u_r", "unknowns.tie_u_r"},
    {"unknowns", "unknowns"},
    {"parameter", "continuation.parameter"},
}};

// The keys whose option is not their last part spelt with '-'.
constexpr std::array<std::pair<std::string_view, std::string_view>, 3> kOptionsOfOwnName = {{
    {"start.restart", "point"},
    {"unknowns.tie_u_r", "tie-u_r"},  // a variable's name keeps its '_'
    {"continuation.user_values_of", "user-value"},
}};

}  // namespace

std::string OptionOfKey(std::string_view key) {
  for (const auto& [own, option] : kOptionsOfOwnName) {
    if (own == key) return std::string(option);
  }
  const auto dot = key.rfind('.');
  std::string option(dot == std::string_view::npos ? key : key.substr(dot + 1));
  std::replace(option.begin(), option.end(), '_', '-');
  return option;
}

std::optional<std::string_view> KeyOfStartField(std::string_view field) {
  for (const auto& [name, key] : kStartFieldKeys) {
    if (name == field) return key;
  }
  return std::nullopt;
}

InvalidInput OnCommandLine(const InvalidInput& error) {
  return error.field() == "restart" ? error.Renamed(OptionOfKey("start.restart")) : error;
}

}  // namespace stickslip
