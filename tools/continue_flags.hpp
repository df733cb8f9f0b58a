// The flags a one-off continuation takes (the keys of a run file's [start], [unknowns] and
// [continuation]), shared by `continue` and `trace`, and the run they describe, checked as a run
// file is.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "start_options.hpp"
#include "stickslip/io/run_file.hpp"

namespace stickslip::cli {

struct ContinueArgs {
  StartFlags start;
  RunFile run;
  std::string range;
  std::string direction = "up";
  std::vector<std::string> user_values;  // NAME=VALUE
  std::string detect_folds = "true";
  std::string detect_branch_points = "true";
  bool linear_solver_given = false;  // refused with --shooting single, where it would be ignored
  bool boundary_given = false;       // --boundary '' is refused, not taken as none
};

// --ds, --ds-min, --ds-max and --max-points (a branch's steps, the run file's keys of those names)
// into `steps`; `scope` ends each option's help (find's ", of each branch (with --trace or
// --write-run)").
void AddStepFlags(CLI::App& cmd, BranchSteps* steps, const std::string& scope);

// The start options, --parameter, --range, --ds, --ds-min, --ds-max, --max-points, --user-value,
// --shooting, --linear-solver, --detect-folds, --detect-branch-points, --output and --results.
void AddContinuationFlags(CLI::App& cmd, ContinueArgs* args);
// continue's --switch-branch and --boundary: what a restart continues from its label (a trace,
// which goes both ways along branches in one parameter, takes neither).
void AddRestartKindFlags(CLI::App& cmd, ContinueArgs* args);

// args->run completed from the flags (start, range, user values, switches) and checked as a run
// file is; throws InvalidInput naming the option.
void BuildOneOffRun(ContinueArgs* args);

}  // namespace stickslip::cli
