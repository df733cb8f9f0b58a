#include "stickslip/io/command_options.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <span>
#include <stdexcept>
#include <string_view>
#include <utility>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "stickslip/io/start_input.hpp"
#include "stickslip/model/transient.hpp"
#include "stickslip/numerics/linear_solver.hpp"

namespace stickslip {

RunFile AsOneOffRun(RunFile run) {
  run.path = kOneOffRunPath;
  run.naming = RunNaming::kOptions;
  return run;
}

std::pair<std::string, std::string> RunAndLabel(std::string_view run_and_label) {
  const auto colon = run_and_label.find(':');
  if (colon == std::string_view::npos || colon == 0 || colon + 1 == run_and_label.size()) {
    throw InvalidInput::WithMessage(
        "restart", fmt::format("restart = '{}' is invalid: valid RUN:LABEL, a labelled point of results/RUN", run_and_label));
  }
  return {std::string(run_and_label.substr(0, colon)), std::string(run_and_label.substr(colon + 1))};
}

RestartPoint ReadRestartPoint(const std::filesystem::path& results_root, std::string_view run_and_label) {
  const auto [run, label] = RunAndLabel(run_and_label);
  return ReadRestartPoint(results_root, run, label);
}

SimulationOptions SimulationOver(const Parameters& p, double periods, double samples_per_period, bool sampled) {
  return SimulationOver<State>(2.0 * std::numbers::pi / p.omega, periods, samples_per_period, sampled);
}

RunFile WithStart(RunFile run, const StartInput& input) {
  run.preset = input.preset;
  run.signature = input.signature;
  if (input.restart) {
    run.restart_run = input.restart->run;
    run.restart_label = input.restart->label;
  }
  run.set = input.set;
  run.guess = input.guess;
  run.free = input.free;
  for (const FixedVariable& f : input.fix) {
    run.fix.push_back(f.name);
    if (f.value) run.guess.emplace_back(f.name, *f.value);
  }
  run.tie_u_r = input.tie_u_r;
  return run;
}

int ContinuationDirection(std::string_view direction) {
  if (direction == "up") return 1;
  if (direction == "down") return -1;
  throw InvalidInput("direction", fmt::format("'{}'", direction), "up, down");
}

void CheckSteps(const BranchSteps& steps) {
  RunFile run = AsOneOffRun({});
  run.steps = steps;
  CheckStepValues(run);
}

void CheckLinearSolverIsUsed(std::string_view linear_solver, std::string_view shooting) {
  if (linear_solver.empty() || shooting != "single") return;
  throw InvalidInput::WithMessage(
      "linear-solver", fmt::format("linear-solver = '{}' is invalid with --shooting single: valid with --shooting "
                                   "multiple or auto (single shooting solves its dense system directly)",
                                   linear_solver));
}

OrbitSolverOptions SolverOptionsOf(std::string_view shooting, std::string_view linear_solver) {
  OrbitSolverOptions options;
  const std::optional<ShootingChoice> choice = ShootingChoiceFromString(shooting);
  if (!choice) throw InvalidInput("shooting", fmt::format("'{}'", shooting), "auto, single, multiple");
  options.shooting = *choice;
  CheckLinearSolverIsUsed(linear_solver, shooting);
  const std::optional<LinearSolverType> solver = LinearSolverFromString(linear_solver.empty() ? "klu" : linear_solver);
  if (!solver) throw InvalidInput("linear-solver", fmt::format("'{}'", linear_solver), "klu, umfpack, dense");
  options.sparse_solver = *solver;
  return options;
}

namespace {

struct WholeRange {
  std::string_view field;
  int low;
  int high;
};
constexpr std::array<WholeRange, 6> kSweepWholeNumbers = {{{"steps", 1, 100000},
                                                           {"transients", 0, kMaxTransientPeriods},
                                                           {"periods", 1, 100000},
                                                           {"chains", 1, 10000},
                                                           {"seed", 0, 1000000000},
                                                           {"threads", 0, 1024}}};
constexpr std::array<WholeRange, 7> kMapWholeNumbers = {{{"first-steps", 0, BruteForceMapOptions::kMaxSteps},
                                                         {"second-steps", 0, BruteForceMapOptions::kMaxSteps},
                                                         {"transients", 0, kMaxTransientPeriods},
                                                         {"periods", 2, BruteForceMapOptions::kMaxRecordedPeriods},
                                                         {"starts", 0, BruteForceMapOptions::kMaxScatteredStarts},
                                                         {"seed", 0, 1000000000},
                                                         {"threads", 0, 1024}}};
constexpr std::array<WholeRange, 3> kFindWholeNumbers = {{{"transients", 0, FindOrbitOptions::kMaxTransient},
                                                          {"max-multiple", 1, FindOrbitOptions::kMaxMultiple},
                                                          {"confirmations", 1, FindOrbitOptions::kMaxConfirmations}}};

// The range of the whole-number option `field` in `table`, or null when it has none.
const WholeRange* RangeOf(std::span<const WholeRange> table, std::string_view field) {
  for (const WholeRange& r : table) {
    if (r.field == field) return &r;
  }
  return nullptr;
}

int WholeNumberOf(std::span<const WholeRange> table, std::string_view field, double value) {
  const WholeRange* r = RangeOf(table, field);
  if (!r) throw std::logic_error(fmt::format("no whole-number option '{}'", field));
  return WholeNumber(field, value, r->low, r->high);
}

}  // namespace

std::string SweepOptionRange(std::string_view field) {
  if (field == "scatter") return "0 <= scatter <= 1e6";
  if (const WholeRange* r = RangeOf(kSweepWholeNumbers, field)) return fmt::format("{} <= {} <= {}", r->low, field, r->high);
  return std::string(SetKeyRange(field));  // from, to: the swept parameter's range
}

SweepPlan PlanSweep(const SweepCommand& c, const ModelDescription& model) {
  const std::optional<int> parameter = model.ParameterIndex(c.parameter);
  if (!parameter) {
    std::vector<std::string> names;
    for (const ParameterDescription& p : model.parameters) names.push_back(p.name);
    throw InvalidInput("parameter", "'" + c.parameter + "'", fmt::format("{}", fmt::join(names, ", ")));
  }
  SweepPlan plan;
  SweepOptions& options = plan.options;
  options.parameter = *parameter;
  options.from = c.from;
  options.to = c.to;
  options.steps = WholeNumberOf(kSweepWholeNumbers, "steps", c.steps);
  options.transient_periods = WholeNumberOf(kSweepWholeNumbers, "transients", c.transients);
  options.recorded_periods = WholeNumberOf(kSweepWholeNumbers, "periods", c.periods);
  if (c.start == "chained") {
    options.start = SweepStart::kChained;
  } else if (c.start == "fixed") {
    options.start = SweepStart::kFixed;
  } else {
    throw InvalidInput("start", "'" + c.start + "'", "chained, fixed");
  }
  plan.chains = WholeNumberOf(kSweepWholeNumbers, "chains", c.chains);
  if (!(c.scatter >= 0.0 && c.scatter <= 1e6)) throw InvalidInput("scatter", c.scatter, SweepOptionRange("scatter"));
  plan.scatter = c.scatter;
  plan.seed = static_cast<std::uint64_t>(WholeNumberOf(kSweepWholeNumbers, "seed", c.seed));
  options.threads = WholeNumberOf(kSweepWholeNumbers, "threads", c.threads);
  return plan;
}

std::string FindOptionRange(std::string_view field) {
  if (const WholeRange* r = RangeOf(kFindWholeNumbers, field)) return WholeNumberRange(field, r->low, r->high);
  if (field == "tolerance") {
    return fmt::format("{} <= tolerance <= {}", FindOrbitOptions::kMinTolerance, FindOrbitOptions::kMaxTolerance);
  }
  throw std::logic_error(fmt::format("no find option '{}'", field));
}

FindOrbitOptions FindOptionsOf(const FindCommand& command) {
  FindOrbitOptions options;
  options.transient_periods = WholeNumberOf(kFindWholeNumbers, "transients", command.transients);
  options.max_multiple = WholeNumberOf(kFindWholeNumbers, "max-multiple", command.max_multiple);
  options.confirmations = WholeNumberOf(kFindWholeNumbers, "confirmations", command.confirmations);
  if (!(command.tolerance >= FindOrbitOptions::kMinTolerance && command.tolerance <= FindOrbitOptions::kMaxTolerance)) {
    throw InvalidInput("tolerance", command.tolerance, FindOptionRange("tolerance"));
  }
  options.periodicity_tolerance = command.tolerance;
  return options;
}

std::string MapSweepOptionRange(std::string_view field) {
  if (const WholeRange* r = RangeOf(kMapWholeNumbers, field)) return WholeNumberRange(field, r->low, r->high);
  if (field == "tolerance") {
    return fmt::format("{} <= tolerance <= {}", BruteForceMapOptions::kMinTolerance, BruteForceMapOptions::kMaxTolerance);
  }
  if (field == "scatter") return "0 <= scatter <= 1e6";
  throw std::logic_error(fmt::format("no map-sweep option '{}'", field));
}

BruteForceMapOptions MapOptionsOf(const MapSweepCommand& c, const ModelStart& origin) {
  const auto axis = [](const char* field, const std::string& name) {
    const std::optional<ParameterId> id = ParameterFromString(name);
    if (!id) throw InvalidInput(field, "'" + name + "'", "chi, eta, omega, u_s, u_r");
    return *id;
  };
  BruteForceMapOptions o;
  o.first = {axis("first", c.first), c.first_from, c.first_to, WholeNumberOf(kMapWholeNumbers, "first-steps", c.first_steps)};
  o.second = {axis("second", c.second), c.second_from, c.second_to,
              WholeNumberOf(kMapWholeNumbers, "second-steps", c.second_steps)};
  if (o.first.parameter == o.second.parameter) {
    throw InvalidInput("second", "'" + c.second + "'", "chi, eta, omega, u_s, u_r other than --first");
  }
  o.transient_periods = WholeNumberOf(kMapWholeNumbers, "transients", c.transients);
  o.recorded_periods = WholeNumberOf(kMapWholeNumbers, "periods", c.periods);
  o.scattered_starts = WholeNumberOf(kMapWholeNumbers, "starts", c.starts);
  o.centre = origin.initial_state;
  o.scatter = c.scatter;
  o.seed = static_cast<std::uint64_t>(WholeNumberOf(kMapWholeNumbers, "seed", c.seed));
  if (!(c.tolerance >= BruteForceMapOptions::kMinTolerance && c.tolerance <= BruteForceMapOptions::kMaxTolerance)) {
    throw InvalidInput("tolerance", c.tolerance, MapSweepOptionRange("tolerance"));
  }
  o.periodicity_tolerance = c.tolerance;
  o.threads = WholeNumberOf(kMapWholeNumbers, "threads", c.threads);
  o.shard = c.shard;
  o.shards = c.shards;
  o.Validate(origin.parameters);  // scatter, the shard, the cells' parameters ("grid ...")
  return o;
}

AtlasOptions AtlasOptionsOf(const AtlasCommand& c, const ModelStart& origin) {
  const std::string range = fmt::format("'{},{}'", c.from, c.to);
  const std::string valid = "LO,HI with LO < HI, both within the parameter's valid range";
  if (!(c.from < c.to)) throw InvalidInput("range", range, valid);
  // Both ends, whatever the grid's steps (with none, the one grid value is LO).
  if (const std::optional<ParameterId> id = ParameterFromString(c.parameter)) {
    for (const double end : {c.from, c.to}) {
      Parameters p = origin.parameters;
      p[*id] = end;
      if (const std::optional<InvalidInput> invalid = Validate(p, *id)) {
        throw InvalidInput::WithMessage("range", fmt::format("range = {} is invalid: {}", range, invalid->what()));
      }
    }
  }
  // The brute force is one row of a map: its second axis a parameter other than the atlas's, held.
  MapSweepCommand grid;
  grid.first = c.parameter;
  grid.first_from = c.from;
  grid.first_to = c.to;
  grid.first_steps = c.steps;
  const std::optional<ParameterId> first = ParameterFromString(c.parameter);
  const ParameterId held = first ? HeldBeside(*first) : kAllParameters[0];  // none: MapOptionsOf refuses it
  grid.second = ToString(held);
  grid.second_from = grid.second_to = origin.parameters[held];
  grid.second_steps = 0;
  grid.transients = c.transients;
  grid.periods = c.periods;
  grid.starts = c.starts;
  grid.scatter = c.scatter;
  grid.seed = c.seed;
  grid.tolerance = c.tolerance;
  grid.threads = c.threads;
  AtlasOptions options;
  try {
    options.brute_force = MapOptionsOf(grid, origin);
  } catch (const InvalidInput& e) {  // the grid's names: first is the parameter, first-steps the steps
    if (e.field() == "first") throw e.Renamed("parameter");
    if (e.field() == "first-steps") throw e.Renamed("steps");
    throw;
  }
  const std::string multiples = fmt::format("whole numbers 1 <= max-multiple <= {}", AtlasOptions::kMaxMultiple);
  if (!(c.max_multiple >= 1 && c.max_multiple <= AtlasOptions::kMaxMultiple && std::trunc(c.max_multiple) == c.max_multiple)) {
    throw InvalidInput("max-multiple", c.max_multiple, multiples);
  }
  options.max_multiple = static_cast<int>(c.max_multiple);
  if (!(std::isfinite(c.max_amplitude) && c.max_amplitude > 0.0)) {
    throw InvalidInput("max-amplitude", c.max_amplitude, "a finite max-amplitude > 0");
  }
  options.trace.max_amplitude = c.max_amplitude;
  options.continuation.max_points = WholeNumber("max-points", c.max_points, 1, kMaxRunPoints);
  if (!(c.resonance_approach >= 0.0 && c.resonance_approach < 1.0)) {
    throw InvalidInput("resonance-approach", c.resonance_approach, "0 <= resonance-approach < 1");
  }
  options.resonance_approach = c.resonance_approach;
  options.Validate(origin.parameters);
  return options;
}

}  // namespace stickslip
