#include "stickslip/io/start_input.hpp"

#include <array>
#include <utility>

#include <fmt/format.h>

#include "stickslip/io/result_files.hpp"

namespace stickslip {

RestartPoint ReadRestartPoint(const std::filesystem::path& results_root, const std::string& run,
                              const std::string& label) {
  RestartPoint point{run, label, {}, {}};
  auto fail = [&](const std::string& why) {
    return InvalidInput::WithMessage("restart", fmt::format("restart = '{}:{}' cannot be used: {}", run, label, why));
  };
  LabelledPoint labelled;
  try {
    labelled = ReadLabelledPoint(results_root, run, label);
  } catch (const InvalidInput& e) {
    throw fail(e.what());
  }
  point.signature = labelled.signature;
  point.values = labelled.variables;
  return point;
}

StartInput StartInputOf(const RunFile& run, const std::filesystem::path& results_root) {
  StartInput input;
  input.preset = run.preset;
  input.signature = run.signature;
  if (!run.restart_run.empty()) input.restart = ReadRestartPoint(results_root, run.restart_run, run.restart_label);
  input.set = run.set;
  input.guess = run.guess;
  input.free = run.free;
  for (const std::string& name : run.fix) input.fix.push_back({name, std::nullopt});
  input.tie_u_r = run.tie_u_r;
  input.parameter = run.parameter;
  return input;
}

RunFileError AtRunFileKey(const RunFile& run, const InvalidInput& error) {
  static constexpr std::array<std::pair<std::string_view, std::string_view>, 10> kKeys = {{
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
  for (const auto& [field, key] : kKeys) {
    if (field != error.field()) continue;
    const std::string predicate = error.Predicate();
    const bool leading = predicate.size() != std::string_view(error.what()).size();
    return RunFileError(fmt::format("{}: key '{}' {}{}", run.Location(std::string(key)), key,
                                    leading ? "" : "is invalid: ", predicate),
                        std::string(key));
  }
  // A value out of range (a parameter, a duration), wherever it came from.
  return RunFileError(fmt::format("{}: key 'start' gives invalid data: {}", run.Location("start"), error.what()), "start");
}

}  // namespace stickslip
