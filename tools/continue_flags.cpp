#include "continue_flags.hpp"

#include <optional>
#include <tuple>
#include <utility>

#include <fmt/format.h>

#include "cli_common.hpp"
#include "number_text.hpp"
#include "stickslip/io/command_options.hpp"
#include "stickslip/io/model_restart.hpp"

namespace stickslip::cli {

namespace {

// "true" or "false", as the run file's booleans.
bool ParseSwitch(const char* field, const std::string& text) {
  if (text != "true" && text != "false") throw InvalidInput(field, "'" + text + "'", "true, false");
  return text == "true";
}

}  // namespace

void AddStepFlags(CLI::App& cmd, BranchSteps* steps, const std::string& scope) {
  AddNumberOption(cmd, "--ds", &steps->ds, "0 < ds-min <= ds <= ds-max", "initial arclength step (> 0)" + scope);
  AddNumberOption(cmd, "--ds-min", &steps->ds_min, "0 < ds-min <= ds <= ds-max", "smallest step (> 0)" + scope);
  AddNumberOption(cmd, "--ds-max", &steps->ds_max, "0 < ds-min <= ds <= ds-max", "largest step" + scope);
  AddCountOption(cmd, "--max-points", &steps->max_points, 1, kMaxRunPoints, "accepted points (1 to 1e6)" + scope);
}

void AddContinuationFlags(CLI::App& cmd, ContinueArgs* args) {
  AddStartOptions(cmd, &args->start, StartOptions::kOrbit);
  cmd.add_option("--parameter", args->run.parameter, "continued variable (omega, u_r, u_s, chi, eta, ...)")->required();
  cmd.add_option("--range", args->range, "MIN,MAX of the parameter")->type_name("MIN,MAX")->required();
  AddStepFlags(cmd, &args->run.steps, "");
  AddNumberOption(cmd, "--resonance-approach", &args->run.resonance_approach, "0 <= resonance-approach < 1",
                  "a branch of orbits that never stick ends as a resonance at its first point within this "
                  "(relative) of a natural frequency of the undamped slip that it approaches (0: never)");
  cmd.add_option("--user-value", args->user_values,
                 "report a UZ point where the variable NAME (the parameter or another unknown) passes VALUE; "
                 "repeatable (the run file's user_values and user_values_of)")
      ->type_name("NAME=VALUE");
  cmd.add_option("--shooting", args->run.shooting,
                 "single (dense), multiple (block-sparse), or auto (single up to 6 listed segments)")
      ->check(CLI::IsMember({"auto", "single", "multiple"}))
      ->capture_default_str();
  cmd.add_option("--linear-solver", args->run.linear_solver,
                 "sparse solver for multiple shooting (with --shooting multiple or auto; refused with single)")
      ->check(CLI::IsMember({"klu", "umfpack", "dense"}))
      ->capture_default_str()
      ->each([args](const std::string&) { args->linear_solver_given = true; });
  cmd.add_option("--detect-folds", args->detect_folds, "locate folds (LP): true or false")
      ->type_name("true|false")
      ->capture_default_str();
  cmd.add_option("--detect-branch-points", args->detect_branch_points, "locate branch points (BP): true or false")
      ->type_name("true|false")
      ->capture_default_str();
  cmd.add_option("--output", args->run.output, "results/<output>/")->required();
  cmd.add_option("--results", args->start.results, "results directory: where --point is read and <output>/ written")
      ->capture_default_str();
}

void AddRestartKindFlags(CLI::App& cmd, ContinueArgs* args) {
  cmd.add_flag("--switch-branch", args->run.restart_switch_branch,
               "with --point at a PD or an SB: continue the branch that leaves it, on the side --direction names "
               "(both: either side), not the branch the point lies on (the run file's start.restart.switch_branch)");
  cmd.add_option("--boundary", args->run.restart_boundary,
                 "with --point at a located change of type, LP, PD, SB or TR: continue its curve in the plane of "
                 "--parameter and this second parameter (u_r, u_s, chi, eta; a [model]'s: any of its parameters; the "
                 "run file's start.restart.boundary)")
      ->type_name("NAME")
      ->each([args](const std::string&) { args->boundary_given = true; });
}

namespace {

// --boundary given empty, which the run's fields cannot tell from not given (CheckRunValues has
// the rules of --switch-branch and --boundary that a run file's start.restart has too).
void RefuseEmptyBoundary(const ContinueArgs& args) {
  if (args.boundary_given && args.run.restart_boundary.empty()) {
    throw InvalidInput::WithMessage("boundary", "boundary = '' is invalid: valid the name of a second parameter to release");
  }
}

}  // namespace

void BuildOneOffRun(ContinueArgs* args) {
  RunFile& run = args->run;
  run = AsOneOffRun(std::move(run));
  // A [model]'s label: only its run and label here; the model and the orbit come with the run
  // (MakeModelSetup), which refuses the start options only the paper's oscillator takes.
  StartFlags start = args->start;
  const auto model_point = ModelPointOf(start.results, start.point);
  if (model_point) start.point.clear();
  run = WithStart(std::move(run), ToStartInput(start));
  if (model_point) std::tie(run.restart_run, run.restart_label) = *model_point;
  const auto comma = args->range.find(',');
  if (comma == std::string::npos) throw InvalidInput("range", "'" + args->range + "'", "MIN,MAX");
  run.range_min = ParseNumber("range", args->range.substr(0, comma), "MIN,MAX with MIN < MAX, both finite");
  run.range_max = ParseNumber("range", args->range.substr(comma + 1), "MIN,MAX with MIN < MAX, both finite");
  RefuseEmptyBoundary(*args);
  CheckRunValues(run);
  CheckLinearSolverIsUsed(args->linear_solver_given ? run.linear_solver : "", run.shooting);
  for (const std::string& text : args->user_values) {
    const auto equals = text.find('=');
    if (equals == std::string::npos || equals == 0) throw InvalidInput("user-value", "'" + text + "'", "NAME=VALUE");
    const std::string name = text.substr(0, equals);
    run.user_values.emplace_back(name, ParseNumber("user-value", text.substr(equals + 1), "a finite number"));
  }
  run.detect_folds = ParseSwitch("detect-folds", args->detect_folds);
  run.detect_branch_points = ParseSwitch("detect-branch-points", args->detect_branch_points);
}

}  // namespace stickslip::cli
