#include "stickslip/io/run.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "stickslip/io/result_files.hpp"
#include "stickslip/orbits/paper_presets.hpp"

namespace stickslip {

namespace ov = orbit_variables;

OrbitContinuationSetup MakeSetup(const RunFile& run, const std::filesystem::path& results_root) {
  auto fail = [&](const std::string& key, const std::string& what) -> RunFileError {
    return RunFileError(fmt::format("{}: key '{}' {}", run.Location(key), key, what));
  };
  // The start orbit: a preset's printed values, a restart point, or a signature with values.
  std::optional<Orbit> start;
  UnknownChoice unknowns;
  if (!run.preset.empty()) {
    const PaperPreset* preset = FindPaperPreset(run.preset);
    if (preset == nullptr) {
      throw fail("start.preset", fmt::format("= '{}' is unknown: valid paper-4.1, paper-4.2, paper-5.1, paper-5.2, paper-6",
                                             run.preset));
    }
    start = preset->Guess();
    unknowns = preset->unknowns;
  }
  std::string signature_text = run.signature;
  LabelledPoint restart;
  if (!run.restart_run.empty()) {
    try {
      restart = ReadLabelledPoint(results_root, run.restart_run, run.restart_label);
    } catch (const InvalidInput& e) {
      throw fail("start.restart", fmt::format("cannot be used: {}", e.what()));
    }
    if (signature_text.empty()) signature_text = restart.signature;
  }
  if (!signature_text.empty()) {
    std::string error;
    const std::optional<Signature> signature = Signature::Parse(signature_text, &error);
    if (!signature) throw fail("start.signature", "is invalid: " + error);
    if (!start) {
      start = Orbit{*signature, {}, 0.0, 0.0, 0.0, 0.0, std::vector<double>(signature->size(), 0.0)};
    } else if (!(start->signature == *signature)) {
      throw fail("start.signature", "differs from the preset's; give one of them");
    }
  }
  Eigen::VectorXd variables = ov::Pack(*start);
  const int n = start->signature.size();
  auto assign = [&](const std::string& key, const std::string& name, double value) {
    const std::optional<int> index = ov::IndexOf(n, name);
    if (!index) {
      std::vector<std::string> names;
      for (int i = 0; i < ov::Count(n); ++i) names.push_back(ov::Name(n, i));
      throw fail(key, fmt::format("names '{}', not a variable: valid {}", name, fmt::join(names, ", ")));
    }
    variables(*index) = value;
  };
  for (const auto& [name, value] : restart.variables) {
    if (ov::IndexOf(n, name)) assign("start.restart", name, value);
  }
  for (const auto& [name, value] : run.set) assign("start.set", name, value);
  for (const auto& [name, value] : run.guess) assign("start.guess", name, value);
  Orbit orbit = ov::Unpack(start->signature, variables);

  unknowns.release.insert(unknowns.release.end(), run.free.begin(), run.free.end());
  unknowns.fix.insert(unknowns.fix.end(), run.fix.begin(), run.fix.end());
  unknowns.tie_static_friction = unknowns.tie_static_friction || run.tie_u_r;
  if (unknowns.tie_static_friction) orbit.parameters.u_r = orbit.parameters.u_s;
  if (const auto invalid = Validate(orbit.parameters)) throw fail("start", std::string("gives invalid data: ") + invalid->what());
  for (int i = 0; i < n; ++i) {
    if (!(orbit.durations[i] > 0.0)) {
      throw fail("start.guess", fmt::format("misses d{} (> 0): give the duration of segment {}", i + 1, i + 1));
    }
  }
  const FreeVariables free = ResolveUnknowns(orbit.signature, unknowns);
  if (!free.error.empty()) throw fail("unknowns", "is invalid: " + free.error);

  OrbitContinuationSetup setup{orbit, unknowns, run.parameter, ShootingChoice::kAuto, LinearSolverType::kKlu, {}, {}};
  const std::optional<int> parameter = ov::IndexOf(n, run.parameter);
  if (!parameter) throw fail("continuation.parameter", fmt::format("= '{}' is not a variable", run.parameter));
  if (unknowns.tie_static_friction && run.parameter == "u_r") {
    throw fail("continuation.parameter", "= 'u_r' is tied to u_s (tie_u_r): continue in u_s");
  }
  if (std::find(free.indices.begin(), free.indices.end(), *parameter) != free.indices.end()) {
    throw fail("continuation.parameter", fmt::format("= '{}' is an unknown already: continue in a held variable", run.parameter));
  }
  const double lambda = variables(*parameter);
  if (lambda < run.range_min || lambda > run.range_max) {
    throw fail("continuation.range", fmt::format("= [{}, {}] excludes the start, {} = {}", run.range_min,
                                                 run.range_max, run.parameter, lambda));
  }
  setup.shooting = run.shooting == "single" ? ShootingChoice::kSingle
                   : run.shooting == "multiple" ? ShootingChoice::kMultiple
                                                : ShootingChoice::kAuto;
  setup.sparse_solver = *LinearSolverFromString(run.linear_solver);
  ContinuationOptions& o = setup.options;
  o.direction = run.direction;
  o.lambda_min = run.range_min;
  o.lambda_max = run.range_max;
  o.step.ds = run.ds;
  o.step.ds_min = run.ds_min;
  o.step.ds_max = run.ds_max;
  o.max_points = run.max_points;
  o.detect_folds = run.detect_folds;
  o.detect_branch_points = run.detect_branch_points;
  o.continue_past_terminal = run.continue_past_type_changes;
  // User values address unknowns: the free variables in their order, then the parameter.
  std::vector<int> order = free.indices;
  order.push_back(*parameter);
  for (const auto& [name, value] : run.user_values) {
    const std::optional<int> index = ov::IndexOf(n, name);
    const auto position = index ? std::find(order.begin(), order.end(), *index) : order.end();
    if (position == order.end()) {
      throw fail("continuation.user_values_of", fmt::format("names '{}', which is not an unknown of the run", name));
    }
    o.user_values.push_back({static_cast<int>(position - order.begin()), value, fmt::format("{}={}", name, value)});
  }
  return setup;
}

}  // namespace stickslip
