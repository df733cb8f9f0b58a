#include "stickslip/io/model_restart.hpp"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "stickslip/branches/model_trace.hpp"  // BranchFromBifurcation of a [model], compiled there
#include "stickslip/invalid_input.hpp"
#include "stickslip/io/command_options.hpp"
#include "stickslip/io/result_files.hpp"
#include "stickslip/io/run.hpp"
#include "stickslip/io/switched_restart.hpp"
#include "stickslip/io/trace_files.hpp"
#include "stickslip/orbits/any_orbit.hpp"
#include "stickslip/orbits/orbit_solver.hpp"
#include "stickslip/orbits/signature_edits.hpp"

namespace stickslip {

namespace {

using Model = DynamicLinearOscillator;

// The keys of a run file that only the paper's start builder reads, with what they hold.
struct PaperOnlyKey {
  const char* key;
  bool given;
};

std::vector<PaperOnlyKey> PaperOnlyKeys(const RunFile& run) {
  return {{"start.preset", !run.preset.empty()},
          {"start.signature", !run.signature.empty()},
          {"start.set", !run.set.empty()},
          {"unknowns.fix", !run.fix.empty()},  // before guess: --fix NAME=VALUE gives a guess too
          {"start.guess", !run.guess.empty()},
          {"unknowns.free", !run.free.empty()},
          {"unknowns.tie_u_r", run.tie_u_r}};
}

}  // namespace

bool HoldsModelRun(const std::filesystem::path& results_root, const std::string& run) {
  if (!IsRunName(run)) return false;
  try {
    return !ReadRunSummary(results_root / run).model.empty();
  } catch (const InvalidInput&) {
    return false;
  }
}

std::optional<std::pair<std::string, std::string>> ModelPointOf(const std::filesystem::path& results_root,
                                                                std::string_view point) {
  if (point.empty()) return std::nullopt;
  auto run_and_label = RunAndLabel(point);
  if (!HoldsModelRun(results_root, run_and_label.first)) return std::nullopt;
  return run_and_label;
}

std::filesystem::path ModelFileOf(const StoredRun& run, const std::filesystem::path& run_directory) {
  if (run.summary.run_file == kOneOffRunPath) {
    throw InvalidInput::WithMessage(
        "run", fmt::format("'{}' was computed from the command line (--set): its model is in no run file: valid a run "
                           "whose summary.json names its [model]'s file",
                           run.summary.output));
  }
  const std::filesystem::path file = run.summary.run_file;
  std::error_code error;
  if (file.is_absolute()) return file;
  // A path relative to where the run was made: a directory above the results (the project's root,
  // where tools/run.sh writes results/), nearest first, else the working directory. Those above
  // come first: a file of the same name where the command runs now may be another model's.
  for (std::filesystem::path above = std::filesystem::absolute(run_directory, error); !above.empty();
       above = above.parent_path()) {
    if (std::filesystem::exists(above / file, error)) return above / file;
    if (above == above.root_path()) break;
  }
  return file;
}

// What reads a stored run writes its numbers again under the run file's units: refused where they
// are no longer the run's, which would relabel every number (the numbers are the same in any units).
void CheckUnitsUnchanged(const StoredRun& run, const ModelFileStart& file) {
  const ModelUnits& now = file.model.Description().units;
  if (now == run.summary.units) return;
  const auto text = [](const ModelUnits& u) { return fmt::format("{}, {}, {}", u.length, u.time, u.force); };
  throw InvalidInput::WithMessage(
      "run_file", fmt::format("'{}': the run's numbers are in {} (length, time, force) but '{}' declares {} now: valid "
                              "the run file the run was made from",
                              run.summary.output, text(run.summary.units), run.summary.run_file, text(now)));
}

ModelFileStart ModelOfStoredRun(const StoredRun& run, const std::filesystem::path& run_directory) {
  return ReadModelFileStart(ModelFileOf(run, run_directory), {});
}

std::vector<DynamicLinearOscillator::State> SampledStoredOrbit(const ModelFileStart& file, const BasicOrbit<Model>& orbit,
                                                               int samples, const StoredRun& run, const std::string& label) {
  const std::vector<Model::State> states = SampleOrbit(file.model, orbit, samples);
  const double size = OrbitSize(file.model, orbit);
  if (static_cast<int>(states.size()) != samples || !states.back().allFinite() ||
      !((states.back() - orbit.start).lpNorm<Eigen::Infinity>() <= 1e-6 * size)) {
    throw InvalidInput::WithMessage(
        "run_file", fmt::format("'{}': the orbit of {} is no periodic orbit of the model '{}' describes now (was the file "
                                "changed since the run?): valid the run file the run was made from",
                                run.summary.output, label, run.summary.run_file));
  }
  return states;
}

ModelLabel ReadModelLabel(const std::filesystem::path& results_root, const std::string& run, const std::string& label) {
  const std::filesystem::path directory = results_root / run;
  try {
    const StoredRun stored = ReadRunFiles(directory);
    const StoredSpecialPoint& point = SpecialPointLabelled(stored, label, directory);
    ModelFileStart file = ModelOfStoredRun(stored, directory);
    CheckUnitsUnchanged(stored, file);
    BasicOrbit<Model> orbit = OrbitOf(file.model, file.parameters, stored, point.point);
    SampledStoredOrbit(file, orbit, 2, stored, label);
    file.parameters = orbit.parameters;
    return {std::move(file), stored.summary.run_file, std::move(orbit), point};
  } catch (const InvalidInput& e) {
    throw InvalidInput::WithMessage("restart", fmt::format("restart = '{}:{}' cannot be used: {}", run, label, e.what()));
  }
}

BasicOrbit<DynamicLinearOscillator> ContinuableIn(BasicOrbit<DynamicLinearOscillator> orbit, int parameter) {
  if (parameter == Model::kRestVelocityParameter && orbit.signature.antisymmetric()) return Unfolded(orbit, 1);
  return orbit;
}

StoredRun ModelRunSetup::Recorded(const RunFile& run, const BasicOrbitBranch<DynamicLinearOscillator>& branch) const {
  return RecordRun(file.model, Identity(run), branch);
}

StoredTrace ModelRunSetup::Recorded(const RunFile& run, const BasicTraceResult<DynamicLinearOscillator>& trace) const {
  StoredTrace stored = RecordTrace(file.model, Identity(run), trace);
  stored.natural_frequencies = file.slip_frequencies;
  return stored;
}

namespace {

// The index of the model's parameter `name` given at `key` (the continued one, or a curve's
// second): one the model varies. Throws KeyError at `key` with the valid names, without
// `varied_already` (a curve's second: not the continued parameter).
int VariedParameterOf(const RunFile& run, const DynamicLinearOscillator& model, const std::string& key,
                      const std::string& name, std::string_view varied_already = {}) {
  try {
    return model.Description().VariedParameter(key, name, model.Autonomous(), varied_already);
  } catch (const InvalidInput& e) {
    throw KeyError(run, key, e.Predicate());
  }
}

// A moving surface breaks the half-period symmetry whose breaking an SB is: in v_b the pitchfork
// unfolds, and no second branch crosses the label's.
void RefuseSwitchInBeltSpeed(const RunFile& run, const DynamicLinearOscillator& model, int k) {
  if (k != Model::kRestVelocityParameter || run.restart_label.rfind("SB", 0) != 0) return;
  const ModelDescription& description = model.Description();
  std::vector<std::string> others;
  for (int i = model.Autonomous() ? 1 : 0; i < description.ParameterCount(); ++i) {
    if (i != k) others.push_back(description.parameters[i].name);
  }
  throw KeyError(run, "continuation.parameter",
                 fmt::format("= \"{}\" is invalid with start.restart.switch_branch at '{}': a moving surface breaks the "
                             "symmetry that an SB breaks, so no other branch crosses there in {}: valid {}",
                             run.parameter, run.restart_label, run.parameter, fmt::join(others, ", ")));
}

// An antisymmetric orbit is a motion only on a fixed surface: a curve with the belt's speed
// continued or released would need it written over its whole period, whose mirror margins (zero
// at the start) the curve's condition does not hold. Throws KeyError at start.restart.boundary.
void CheckCurveKeepsTheSurfaceFixed(const RunFile& run, const DynamicLinearOscillator& model,
                                    const BasicOrbit<Model>& orbit, int k) {
  const int second = VariedParameterOf(run, model, "start.restart.boundary", run.restart_boundary, run.parameter);
  const int speed = Model::kRestVelocityParameter;
  if (!orbit.signature.antisymmetric() || (k != speed && second != speed)) return;
  throw KeyError(run, "start.restart.boundary",
                 fmt::format("= '{}' is invalid with continuation.parameter = \"{}\" at '{}': the orbit '{}' is a motion "
                             "only where {} = 0 (the mirror of a stick on a moving surface moves the other way): valid "
                             "a curve in two parameters other than {}",
                             run.restart_boundary, run.parameter, run.restart_label, orbit.signature.ToString(),
                             model.Description().parameters[speed].name, model.Description().parameters[speed].name));
}

// The label a run file's [start.restart] names in a [model]'s run, with its model. Throws KeyError
// at a key only the paper's start builder reads, and at start.restart where the label cannot be
// read (ReadModelLabel).
ModelLabel LabelOfRestart(const RunFile& run, const std::filesystem::path& results_root) {
  for (const PaperOnlyKey& k : PaperOnlyKeys(run)) {
    if (k.given) {
      throw KeyError(run, k.key, fmt::format("is invalid with a [model]'s label ('{}:{}'): the label gives the model, its "
                                             "parameters and orbit, and the unknowns (the orbit's at fixed parameters); "
                                             "vary a parameter by continuing in it",
                                             run.restart_run, run.restart_label));
    }
  }
  try {
    return ReadModelLabel(results_root, run.restart_run, run.restart_label);
  } catch (const InvalidInput& e) {
    throw KeyError(run, "start.restart", e.Predicate());
  }
}

// The branch from `orbit` at fixed parameters in the run's parameter, with its steps and options
// (the unknowns the orbit's; with an abnormal stop a friction level is released among them).
BasicOrbitContinuationSetup<Model> BranchOfRestart(const RunFile& run, const Model& model, BasicOrbit<Model> orbit) {
  const UnknownChoice unknowns = UnknownsAtFixedParameters(VariableSetOf(model, orbit.signature));
  BasicOrbitContinuationSetup<Model> setup{std::move(orbit), unknowns, run.parameter,
                                           *ShootingChoiceFromString(run.shooting),  // checked by the reader
                                           *LinearSolverFromString(run.linear_solver), {}, {}, {}, {},
                                           run.max_amplitude, run.resonance_approach, model};
  setup.options = WithContinuationKeys(std::move(setup.options), run);
  return setup;
}

}  // namespace

std::optional<ModelRunSetup> MakeModelSetup(const RunFile& run, const std::filesystem::path& results_root) {
  if (run.restart_run.empty() || !HoldsModelRun(results_root, run.restart_run)) return std::nullopt;
  ModelLabel at = LabelOfRestart(run, results_root);
  const Model& model = at.file.model;
  const int k = VariedParameterOf(run, model, "continuation.parameter", run.parameter);
  CheckRangeHoldsStart(run, Model::ParameterAt(at.orbit.parameters, k));
  if (run.restart_switch_branch) RefuseSwitchInBeltSpeed(run, model, k);
  const bool curve = !run.restart_boundary.empty();
  if (curve) CheckCurveKeepsTheSurfaceFixed(run, model, at.orbit, k);
  BasicOrbitContinuationSetup<Model> setup = BranchOfRestart(run, model, ContinuableIn(std::move(at.orbit), k));
  if (run.restart_switch_branch) setup = SwitchedAtLabel(run, at.special.type, setup);
  if (curve) setup = CurveOfRestart(run, at.special.type, at.special.test_function, setup);
  // User values address the unknowns: the free variables in their order, then the parameter (of the
  // branch that leaves the point, where the switch changed its type).
  const OrbitVariableSet continued = VariableSetOf(model, setup.start.signature);
  std::vector<int> order = FreeIndices(continued, setup.unknowns);
  order.push_back(continued.layout.Parameter(k));
  setup.options.user_values =
      UserValuesOf(run, order, [&continued](const std::string& name) { return continued.layout.IndexOf(name); });
  return ModelRunSetup{std::move(at.file), std::move(at.run_file), std::move(setup)};
}

}  // namespace stickslip
