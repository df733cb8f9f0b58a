#include "stickslip/io/start_input.hpp"

#include <optional>
#include <string_view>
#include <utility>

#include <fmt/format.h>

#include "stickslip/io/result_files.hpp"

namespace stickslip {

RestartPoint ReadRestartPoint(const std::filesystem::path& results_root, const std::string& run,
                              const std::string& label) {
  RestartPoint point{.run = run, .label = label};
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
  point.type = labelled.type;
  point.test_function = labelled.test_function;
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

InvalidInput AtRunField(const RunFile& run, const InvalidInput& error) {
  const std::optional<std::string_view> key = KeyOfStartField(error.field());
  if (!key) {  // a value out of range (a parameter, a duration), wherever it came from
    if (run.naming == RunNaming::kOptions) return error;
    return RunFileError(fmt::format("{}: key 'start' gives invalid data: {}", run.Location("start"), error.what()), "start");
  }
  const std::string predicate = error.Predicate();
  const bool leading = predicate.size() != std::string_view(error.what()).size();
  return KeyError(run, std::string(*key), fmt::format("{}{}", leading ? "" : "is invalid: ", predicate));
}

}  // namespace stickslip
