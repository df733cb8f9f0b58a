#include "cli_common.hpp"

#include <cmath>

#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/io/trace_files.hpp"
#include "stickslip/orbits/start_problem.hpp"

namespace stickslip::cli {

namespace {

std::string FieldOf(const std::string& name) { return name.substr(name.find_first_not_of('-')); }

}  // namespace

void CheckHoldsRun(const std::filesystem::path& directory, const std::string& field, std::string_view valid) {
  namespace fs = std::filesystem;
  std::error_code error;
  if (fs::exists(directory / "branch.csv", error)) return;
  const char* why = !fs::exists(directory, error)        ? "it does not exist"
                    : !fs::is_directory(directory, error) ? "it is not a directory"
                    : IsTraceDirectory(directory)         ? "it is a trace's directory (its runs are its branch-<k>/)"
                                                          : "it holds no branch.csv";
  throw InvalidInput::WithMessage(field, fmt::format("{} = '{}' is invalid: {}: valid {}", field, directory.string(), why, valid));
}

CLI::Option* AddNumberOption(CLI::App& cmd, const std::string& name, double* value, const std::string& valid_range,
                             const std::string& help) {
  return cmd
      .add_option_function<std::string>(
          name, [=](const std::string& text) { *value = ParseNumber(FieldOf(name), text, valid_range); }, help)
      ->type_name("FLOAT")
      ->default_str(fmt::format("{}", *value));
}

CLI::Option* AddCountOption(CLI::App& cmd, const std::string& name, int* value, int low, int high,
                            const std::string& help) {
  return cmd
      .add_option_function<std::string>(
          name, [=](const std::string& text) { *value = ParseCount(FieldOf(name), text, low, high); }, help)
      ->type_name("INT")
      ->default_str(fmt::format("{}", *value));
}

ExitWithReason SolvedOrbitExitCode(const Margin& smallest, const Verification& verification) {
  if (std::isnan(smallest.value)) {
    return {kExitNotAMotion, fmt::format("the solution's admissibility is not known: margin {} is not defined (its root "
                                         "search was cut short)", smallest.Name())};
  }
  if (!(smallest.value > 0)) {
    return {kExitNotAMotion, fmt::format("the solution is not a motion of the system: margin {} = {:.6g} <= 0",
                                         smallest.Name(), smallest.value)};
  }
  if (!verification.Passed()) return {kExitNotAMotion, "the solution failed its verification by simulation"};
  return {};
}

std::string SetKeysHelp() {
  std::string help = "KEY=VALUE, repeatable; overrides the preset. Keys:";
  for (const SetKey& k : SetKeys()) {
    help += fmt::format("\n  {:<6} {} ({})", k.key, k.meaning, k.valid_range);
  }
  return help;
}

std::string DescribeParameters(const Parameters& p) {
  std::string text;
  for (ParameterId id : kAllParameters) {
    text += fmt::format("{}{}={}", text.empty() ? "" : " ", ToString(id), p[id]);
  }
  return text;
}

int FindExitCode(FindOrbitStatus status) {
  switch (status) {
    case FindOrbitStatus::kFound: return kExitOk;
    case FindOrbitStatus::kNotPeriodic:
    case FindOrbitStatus::kNoOrbitType: return kExitNotPeriodic;
    case FindOrbitStatus::kSimulationIncomplete: return kExitFailure;
    case FindOrbitStatus::kSolveFailed: return kExitNoConvergence;
    case FindOrbitStatus::kNotAMotion: break;
  }
  return kExitNotAMotion;
}

}  // namespace stickslip::cli
