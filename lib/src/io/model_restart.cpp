#include "stickslip/io/model_restart.hpp"

#include <algorithm>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/io/command_options.hpp"
#include "stickslip/io/result_files.hpp"
#include "stickslip/io/run.hpp"
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
          {"start.guess", !run.guess.empty()},
          {"unknowns.free", !run.free.empty()},
          {"unknowns.fix", !run.fix.empty()},
          {"unknowns.tie_u_r", run.tie_u_r},
          {"start.restart.switch_branch", run.restart_switch_branch},
          {"start.restart.boundary", !run.restart_boundary.empty()}};
}

const StoredSpecialPoint& LabelIn(const StoredRun& stored, const RunFile& run, const std::filesystem::path& directory) {
  std::vector<std::string> labels;
  for (const StoredSpecialPoint& s : stored.special_points) {
    if (s.point.label == run.restart_label) return s;
    labels.push_back(s.point.label);
  }
  throw RunFileError(fmt::format("{}: key 'start.restart' = '{}:{}' cannot be used: label '{}' is not in '{}': valid "
                                 "labels {}",
                                 run.Location("start.restart"), run.restart_run, run.restart_label, run.restart_label,
                                 (directory / "special-points.csv").string(), fmt::join(labels, ", ")),
                     "start.restart");
}

}  // namespace

bool HoldsModelRun(const std::filesystem::path& results_root, const std::string& run) {
  if (!IsRunName(run)) return false;
  try {
    return !ReadRunFiles(results_root / run).summary.model.empty();
  } catch (const InvalidInput&) {
    return false;
  }
}

ModelFileStart ModelOfStoredRun(const StoredRun& run) {
  if (run.summary.run_file == kOneOffRunPath) {
    throw InvalidInput::WithMessage(
        "run", fmt::format("'{}' was computed from the command line (--set): its model is in no run file: valid a run "
                           "whose summary.json names its [model]'s file",
                           run.summary.output));
  }
  return ReadModelFileStart(run.summary.run_file, {});
}

std::optional<ModelRunSetup> MakeModelSetup(const RunFile& run, const std::filesystem::path& results_root) {
  if (run.restart_run.empty() || !HoldsModelRun(results_root, run.restart_run)) return std::nullopt;
  const auto fail = [&](const std::string& key, const std::string& what) {
    return RunFileError(fmt::format("{}: key '{}' {}", run.Location(key), key, what), key);
  };
  for (const PaperOnlyKey& k : PaperOnlyKeys(run)) {
    if (k.given) throw fail(k.key, fmt::format("is invalid with a [model]'s label ('{}:{}'): the label gives the model, "
                                               "its orbit and its unknowns (the orbit's at fixed parameters); the key "
                                               "is the paper's oscillator's",
                                               run.restart_run, run.restart_label));
  }
  const std::filesystem::path directory = results_root / run.restart_run;
  const StoredRun stored = ReadRunFiles(directory);
  const StoredSpecialPoint& label = LabelIn(stored, run, directory);
  ModelFileStart file = [&] {
    try {
      return ModelOfStoredRun(stored);
    } catch (const InvalidInput& e) {
      throw fail("start.restart", fmt::format("= '{}:{}' cannot be used: {}", run.restart_run, run.restart_label, e.what()));
    }
  }();
  const Model& model = file.model;
  BasicOrbit<Model> orbit = [&] {
    try {
      return OrbitOf(model, file.parameters, stored, label.point);
    } catch (const InvalidInput& e) {
      throw fail("start.restart", fmt::format("= '{}:{}' cannot be used: {}", run.restart_run, run.restart_label, e.what()));
    }
  }();
  file.parameters = orbit.parameters;
  int k = 0;
  try {
    k = model.Description().VariedParameter("continuation.parameter", run.parameter, model.Autonomous());
  } catch (const InvalidInput& e) {
    throw fail("continuation.parameter", e.Predicate());
  }
  const double value = Model::ParameterAt(orbit.parameters, k);
  if (!(run.range_min <= value && value <= run.range_max)) {
    throw fail("continuation.range", fmt::format("= [{}, {}] excludes the start, {} = {}", run.range_min,
                                                 run.range_max, run.parameter, value));
  }
  // In the belt's speed an antisymmetric orbit is written over its whole period (as TraceModel).
  if (k == Model::kRestVelocityParameter && orbit.signature.antisymmetric()) orbit = Unfolded(orbit, 1);
  BasicOrbitContinuationSetup<Model> setup{std::move(orbit), {}, run.parameter,
                                           *ShootingChoiceFromString(run.shooting),  // checked by the reader
                                           *LinearSolverFromString(run.linear_solver), {}, {}, {}, {},
                                           run.max_amplitude, run.resonance_approach, model};
  SetContinuationOptions(run, &setup.options);
  // User values of the continued parameter: the last of the unknowns, after the orbit's own.
  const OrbitVariableSet variables = VariableSetOf(model, setup.start.signature);
  const int position = static_cast<int>(FreeIndices(variables, UnknownsAtFixedParameters(variables)).size());
  for (const auto& [name, v] : run.user_values) {
    if (name != run.parameter) {
      throw fail("continuation.user_values_of",
                 fmt::format("names '{}', which is not an unknown of the run: valid at a [model]'s label the continued "
                             "parameter '{}'",
                             name, run.parameter));
    }
    setup.options.user_values.push_back({position, v, fmt::format("{}={}", name, v)});
  }
  return ModelRunSetup{std::move(file), stored.summary.run_file, std::move(setup)};
}

}  // namespace stickslip
