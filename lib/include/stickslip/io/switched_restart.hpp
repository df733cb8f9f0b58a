// A restart's `switch_branch = true` (a run file's [start] restart, Python's Branch.switch) for any
// model: the branch that leaves the labelled PD or SB (branches/bifurcation_branches.hpp) on the
// run's side, from the setup at the label. The paper's model's run (run.cpp) and a [model]'s label
// (model_restart.cpp) take it from here; a [model]'s BranchFromBifurcation is compiled once
// (branches/model_trace.hpp).
#pragma once

#include <string>

#include <fmt/format.h>

#include "stickslip/branches/bifurcation_branches.hpp"
#include "stickslip/io/run.hpp"
#include "stickslip/io/run_file.hpp"

namespace stickslip {

// `type` is the label's stored type (special-points.csv's column: PD, SB, ...). Throws the run
// file's error at start.restart.switch_branch where the label is no crossing of
// branches (a PD or SB whose new problem is singular there, relative to 1e-6), and at
// continuation.shooting for multiple shooting (the new branch is solved by single shooting).
template <OscillatorModel Model>
BasicOrbitContinuationSetup<Model> SwitchedAtLabel(const RunFile& run, const std::string& type,
                                                   const BasicOrbitContinuationSetup<Model>& setup) {
  if (setup.shooting == ShootingChoice::kMultiple) {
    throw KeyError(run, "continuation.shooting",
                   "= \"multiple\" is invalid with start.restart.switch_branch: valid \"auto\" or \"single\" (the "
                   "branch that leaves a bifurcation is solved by single shooting)");
  }
  const std::string& label = run.restart_label;
  try {
    const BasicBifurcationBranchStart<Model> start = BranchFromBifurcation(type, setup, run.direction);
    // The tests see 1e-16 .. 1e-7 at located points; far above, the stored point is no crossing.
    if (!(start.singularity <= 1e-6)) {
      throw InvalidInput("special point", fmt::format("{}", start.singularity),
                         "a crossing of branches: the Jacobian's smallest singular value, relative, <= 1e-6");
    }
    return start.setup;
  } catch (const InvalidInput& e) {
    throw KeyError(run, "start.restart.switch_branch",
                   e.valid_range().empty()
                       ? fmt::format("= true is invalid at '{}': {}", label, e.Predicate())
                       : fmt::format("= true is invalid at '{}' (type {}): valid at {}", label, type, e.valid_range()));
  }
}

}  // namespace stickslip
