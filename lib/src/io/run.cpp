#include "stickslip/io/run.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

#include "stickslip/branches/bifurcation_branches.hpp"
#include "stickslip/branches/boundary_curve.hpp"
#include "stickslip/io/result_files.hpp"
#include "stickslip/io/start_input.hpp"
#include "stickslip/io/switched_restart.hpp"

namespace stickslip {

namespace ov = orbit_variables;

ContinuationOptions WithSteps(ContinuationOptions options, const BranchSteps& steps) {
  options.step.ds = steps.ds;
  options.step.ds_min = steps.ds_min;
  options.step.ds_max = steps.ds_max;
  options.max_points = steps.max_points;
  return options;
}

ContinuationOptions WithContinuationKeys(ContinuationOptions o, const RunFile& run) {
  o.direction = run.direction;
  o.lambda_min = run.range_min;
  o.lambda_max = run.range_max;
  o = WithSteps(std::move(o), run.steps);
  o.detect_folds = run.detect_folds;
  o.detect_branch_points = run.detect_branch_points;
  o.continue_past_terminal = run.continue_past_type_changes;
  return o;
}

namespace {

void CheckRangeHolds(const RunFile& run, double value, const std::string& what) {
  if (run.range_min <= value && value <= run.range_max) return;
  throw KeyError(run, "continuation.range", fmt::format("= {} excludes {}, {} = {}", RangeIn(run), what, run.parameter, value));
}

}  // namespace

void CheckRangeHoldsStart(const RunFile& run, double value) { CheckRangeHolds(run, value, "the start"); }

void CheckRangeHoldsFirstPoint(const RunFile& run, const Branch& branch) {
  if (branch.points.empty()) return;
  // A switched branch's first point lies ds along it from the label: on a label at a bound, a
  // range that holds the label may not hold it. Both halves of a pitchfork may leave it alike, so
  // the side is named by its key, not as a way in the parameter.
  CheckRangeHolds(run, branch.points.front().lambda,
                  run.restart_switch_branch
                      ? fmt::format("the first point of the branch that leaves '{}' (direction = \"{}\")",
                                    run.restart_label, run.direction > 0 ? "up" : "down")
                      : std::string("the first point"));
  // Inside the range asked for but past a bound of the physics (a friction level at the other,
  // a parameter's valid range), which the engine narrows the range to.
  if (branch.end == BranchEnd::kStartOutsideRange) {
    throw KeyError(run, run.restart_switch_branch ? "start.restart.switch_branch" : "continuation.range",
                   run.restart_switch_branch
                       ? fmt::format("= true is invalid at '{}' (direction = \"{}\"): {}", run.restart_label,
                                     run.direction > 0 ? "up" : "down", branch.end_message)
                       : fmt::format("is invalid: {}", branch.end_message));
  }
}

std::vector<UserValue> UserValuesOf(const RunFile& run, const std::vector<int>& order,
                                    const std::function<std::optional<int>(const std::string&)>& index_of) {
  std::vector<UserValue> values;
  for (const auto& [name, value] : run.user_values) {
    const std::optional<int> index = index_of(name);
    const auto position = index ? std::find(order.begin(), order.end(), *index) : order.end();
    if (position == order.end()) {
      throw KeyError(run, "continuation.user_values_of", fmt::format("names '{}', which is not an unknown of the run", name));
    }
    values.push_back({static_cast<int>(position - order.begin()), value, fmt::format("{}={}", name, value)});
  }
  return values;
}

OrbitContinuationSetup MakeSetup(const RunFile& run, const std::filesystem::path& results_root) {
  // The restart point read once: its orbit starts the run, its type and test function say how a
  // restart leaves its branch.
  const auto [input, start] = [&] {
    try {
      StartInput read = StartInputOf(run, results_root);
      StartProblem built = BuildStartProblem(read);
      return std::pair{std::move(read), std::move(built)};
    } catch (const InvalidInput& e) {
      throw AtRunField(run, e);
    }
  }();
  const UnknownChoice& unknowns = start.unknowns;
  const std::vector<int>& free = start.free;
  const int parameter = *start.parameter;
  OrbitContinuationSetup setup{start.orbit, unknowns, run.parameter, ShootingChoice::kAuto, LinearSolverType::kKlu, {}, {}};
  CheckRangeHoldsStart(run, ov::Pack(start.orbit)(parameter));
  setup.shooting = *ShootingChoiceFromString(run.shooting);  // checked by the run-file reader
  setup.sparse_solver = *LinearSolverFromString(run.linear_solver);
  setup.max_amplitude = run.max_amplitude;
  setup.resonance_approach = run.resonance_approach;
  ContinuationOptions& o = setup.options;
  o = WithContinuationKeys(std::move(o), run);
  if (run.restart_switch_branch || !run.restart_boundary.empty()) {
    if (!input.restart) throw std::logic_error("a switch or a boundary without a restart point (CheckRunValues refuses it)");
    const RestartPoint& at = *input.restart;
    setup = run.restart_switch_branch ? SwitchedAtLabel(run, at.type, setup)
                                      : CurveOfRestart(run, at.type, at.test_function, setup);
  }
  // User values address unknowns: the free variables in their order, then the parameter (of the
  // branch that leaves the point, or of the boundary, where the start's type changed).
  const bool retyped = run.restart_switch_branch || !run.restart_boundary.empty();
  const int n = setup.start.signature.size();
  std::vector<int> order = retyped ? FreeIndices(setup.start.signature, setup.unknowns) : free;
  order.push_back(retyped ? *ov::IndexOf(n, run.parameter) : parameter);
  o.user_values = UserValuesOf(run, order, [n](const std::string& name) { return ov::IndexOf(n, name); });
  return setup;
}

}  // namespace stickslip
