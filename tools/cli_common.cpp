#include "cli_common.hpp"
#include "commands.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <optional>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "stickslip/io/result_files.hpp"
#include "stickslip/model/paper_examples.hpp"

namespace stickslip::cli {

double ParseNumber(std::string_view field, std::string_view text, std::string_view valid_range) {
  double value = 0.0;
  std::string_view digits = text;
  if (digits.size() > 1 && digits.front() == '+') digits.remove_prefix(1);  // from_chars rejects '+'
  const char* end = digits.data() + digits.size();
  const auto [ptr, ec] = std::from_chars(digits.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(value)) {
    throw InputError(fmt::format("{} = '{}' is not a finite number: valid range {}", field, text,
                                 valid_range));
  }
  return value;
}

namespace {

struct SetKey {
  std::string_view key;
  std::string_view meaning;
  std::string_view valid_range;
};

constexpr std::array<SetKey, 10> kSetKeys = {{
    {"chi", "stiffness ratio k2/(k1+k2)", "0 < chi < 1"},
    {"eta", "mass ratio m1/m2", "eta > 0"},
    {"omega", "forcing frequency (scaled time)", "omega > 0, not a natural frequency"},
    {"u_s", "sliding friction level", "u_s > 0"},
    {"u_r", "static friction level", "u_r >= u_s"},
    {"x10", "initial x1", "any finite number"},
    {"x20", "initial x2", "any finite number"},
    {"v10", "initial x1'", "any finite number"},
    {"v20", "initial x2'", "any finite number"},
    {"phi", "forcing phase at t = 0, cos(omega t + phi) (rad)", "any finite number"},
}};

}  // namespace

std::string SetKeysHelp() {
  std::string help = "KEY=VALUE, repeatable; overrides the preset. Keys:";
  for (const SetKey& k : kSetKeys) {
    help += fmt::format("\n  {:<6} {} ({})", k.key, k.meaning, k.valid_range);
  }
  return help;
}

std::string ValidRange(ParameterId id) {
  for (const SetKey& k : kSetKeys) {
    if (k.key == ToString(id)) return std::string(k.valid_range);
  }
  return "a finite number";
}

ModelInput ResolveModelInput(const std::string& preset, const std::vector<std::string>& assignments) {
  return ResolveModelInput(preset, "", "", assignments);
}

ModelInput ResolveModelInput(const std::string& preset, const std::string& point, const std::string& results,
                             const std::vector<std::string>& assignments) {
  ModelInput input;
  std::array<bool, kParameterCount> given{};
  if (!preset.empty() && !point.empty()) {
    throw InputError(fmt::format("preset = '{}' and point = '{}': give at most one of them", preset, point));
  }
  if (!point.empty()) {
    const auto colon = point.find(':');
    if (colon == std::string::npos || colon == 0 || colon + 1 == point.size()) {
      throw InputError(fmt::format("point = '{}' is invalid: valid RUN:LABEL, a labelled point of results/RUN", point));
    }
    LabelledPoint labelled;
    try {
      labelled = ReadLabelledPoint(results, point.substr(0, colon), point.substr(colon + 1));
    } catch (const std::exception& e) {
      throw InputError(fmt::format("point = '{}' cannot be used: {}", point, e.what()));
    }
    auto column = [&](std::string_view name) {
      for (const auto& [key, value] : labelled.variables) {
        if (key == name) return value;
      }
      throw InputError(fmt::format("point = '{}' has no column {}", point, name));
    };
    for (ParameterId id : kAllParameters) input.parameters[id] = column(ToString(id));
    input.initial_state = State(column("x10"), column("x20"), column("v10"), 0.0);
    input.phi = column("phi");
    given.fill(true);
  }
  if (!preset.empty()) {
    const PaperExample* example = FindPaperExample(preset);
    if (example == nullptr) {
      std::string names;
      for (const PaperExample& e : PaperExamples()) {
        names += fmt::format("{}{}", names.empty() ? "" : ", ", e.name);
      }
      throw InputError(fmt::format("preset = '{}' is unknown: valid presets {}", preset, names));
    }
    input.parameters = example->parameters;
    input.initial_state = example->initial_state;
    input.phi = example->phi;
    input.preset = preset;
    given.fill(true);
  }
  for (const std::string& assignment : assignments) {
    const auto equals = assignment.find('=');
    const std::string_view key =
        std::string_view(assignment).substr(0, equals == std::string::npos ? assignment.size() : equals);
    const auto* entry = std::find_if(kSetKeys.begin(), kSetKeys.end(),
                                     [&](const SetKey& k) { return k.key == key; });
    if (equals == std::string::npos || entry == kSetKeys.end()) {
      throw InputError(fmt::format(
          "--set '{}' is not KEY=VALUE with a known key: valid keys chi, eta, omega, u_s, u_r, "
          "x10, x20, v10, v20, phi",
          assignment));
    }
    const double value =
        ParseNumber(entry->key, std::string_view(assignment).substr(equals + 1), entry->valid_range);
    if (const std::optional<ParameterId> id = ParameterFromString(key)) {
      input.parameters[*id] = value;
      given[static_cast<std::size_t>(*id)] = true;
    } else if (key == "phi") {
      input.phi = value;
    } else {
      constexpr std::array<std::string_view, 4> kStateKeys = {"x10", "x20", "v10", "v20"};
      const auto index = std::find(kStateKeys.begin(), kStateKeys.end(), key) - kStateKeys.begin();
      input.initial_state(index) = value;
    }
  }
  for (ParameterId id : kAllParameters) {
    if (!given[static_cast<std::size_t>(id)]) {
      throw InputError(fmt::format("{} is missing: give --preset or --set {}=VALUE ({})",
                                   ToString(id), ToString(id),
                                   kSetKeys[static_cast<std::size_t>(id)].valid_range));
    }
  }
  if (const auto invalid = Validate(input.parameters)) throw InputError(invalid->what());
  return input;
}

void AddPointOptions(CLI::App& cmd, std::string* point, std::string* results) {
  cmd.add_option("--point", *point,
                 "start from a labelled point of a continuation run instead of a preset: its data, "
                 "its orbit's initial state and phase (RUN:LABEL, e.g. paper-5.1-omega-up:TR2)")
      ->type_name("RUN:LABEL");
  cmd.add_option("--results", *results, "where the runs of --point are stored")->capture_default_str();
}

std::string DescribeParameters(const Parameters& p) {
  std::string text;
  for (ParameterId id : kAllParameters) {
    text += fmt::format("{}{}={}", text.empty() ? "" : " ", ToString(id), p[id]);
  }
  return text;
}

}  // namespace stickslip::cli
