// The options of the front ends beyond the start problem, checked in one place: the command
// line's simulate and continue and the Python module (lib/python/) call these, so that the same
// input gives the same one-line message (InvalidInput) whichever way it arrives.
//
//   RunFile run = AsOneOffRun({});
//   run = WithStart(std::move(run), input);
//   run.direction = ContinuationDirection("up");
//   CheckRunValues(run);
//   OrbitContinuationSetup setup = MakeSetup(run, "results");
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <string_view>

#include <vector>

#include "stickslip/analysis/atlas.hpp"
#include "stickslip/analysis/brute_force_map.hpp"
#include "stickslip/analysis/orbit_finder.hpp"
#include "stickslip/analysis/sweep.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/io/run_file.hpp"
#include "stickslip/model/pascal_2014/parameters.hpp"
#include "stickslip/model/simulation.hpp"
#include "stickslip/orbits/orbit_solver.hpp"
#include "stickslip/orbits/start_problem.hpp"

namespace stickslip {

// The path of a one-off run's RunFile, which its summary stores as its run file.
inline constexpr std::string_view kOneOffRunPath = "(command line)";
// `run` as a run given by its options (continue, trace, atlas, find --trace, Python): the path
// kOneOffRunPath, its fields named as the options (RunNaming::kOptions).
RunFile AsOneOffRun(RunFile run);

// "RUN:LABEL" split at its first colon. Throws InvalidInput naming "restart" when the text is not
// RUN:LABEL.
std::pair<std::string, std::string> RunAndLabel(std::string_view run_and_label);
// A labelled point given as "RUN:LABEL", read from results_root/RUN for a restart. Throws
// InvalidInput naming "restart" when the text is not RUN:LABEL, and as ReadRestartPoint
// (io/start_input.hpp) when the point cannot be read.
RestartPoint ReadRestartPoint(const std::filesystem::path& results_root, std::string_view run_and_label);

// simulate: `periods` periods of simulated time (0 < periods <= 1e6), each `period` long (the
// forcing's 2 pi/omega; without forcing a model's time unit), and a sample every
// 1/samples_per_period of a period (1 <= samples_per_period <= 1e5) when `sampled`. Throws
// InvalidInput naming "periods" or "samples-per-period".
template <typename StateType>
BasicSimulationOptions<StateType> SimulationOver(double period, double periods, double samples_per_period, bool sampled) {
  if (!(periods > 0.0 && periods <= 1e6)) throw InvalidInput("periods", periods, "0 < periods <= 1e6");
  if (!(samples_per_period >= 1.0 && samples_per_period <= 1e5)) {
    throw InvalidInput("samples-per-period", samples_per_period, "1 <= samples-per-period <= 1e5");
  }
  BasicSimulationOptions<StateType> options;
  options.duration = periods * period;
  if (sampled) options.sample_step = period / samples_per_period;
  return options;
}
// The paper's model's, over forcing periods 2 pi/omega.
SimulationOptions SimulationOver(const Parameters& p, double periods, double samples_per_period, bool sampled);

// simulate: the defaults of its options, which the command line and Python show and take: two
// periods shown, 200 samples a period, by the exact flows, no transient before them.
struct SimulateCommand {
  double periods = 2;
  double samples_per_period = 200;
  std::string method = "exact";  // or "odeint"
  double transients = 0;
  double max_events = 10000000;  // per simulation: the guard against chattering
};

// A continuation run given by its keys instead of a run file (`stickslip continue`, Python's
// continue_orbit): the start of `input` as the run file's [start] and [unknowns]. A value given
// with a fix becomes the last guess of that variable, which is what a fix's value means to the
// builder; MakeSetup reads the restart point again, by run and label.
RunFile WithStart(RunFile run, const StartInput& input);

// "up" -> +1, "down" -> -1. Throws InvalidInput naming "direction".
int ContinuationDirection(std::string_view direction);

// A branch's steps given as options without a run (find --trace's, Python's trace keywords):
// CheckStepValues in the options' words, naming ds-min, ds-max, ds or max-points.
void CheckSteps(const BranchSteps& steps);

// A linear solver given (non-empty `linear_solver`) with shooting "single" would be ignored: single
// shooting solves its dense system directly. Throws InvalidInput naming "linear-solver"; the
// command line's --linear-solver and Python's linear_solver= alike.
void CheckLinearSolverIsUsed(std::string_view linear_solver, std::string_view shooting);

// solve's options from its shooting ("auto", "single", "multiple") and linear solver ("klu",
// "umfpack", "dense"; empty: not given, klu where multiple shooting is used), as the command line
// and Python give them. Throws InvalidInput naming "shooting" or "linear-solver".
OrbitSolverOptions SolverOptionsOf(std::string_view shooting, std::string_view linear_solver);

// sweep: the options as given, numbers not yet checked to be whole or in range. The defaults are
// the library's (SweepOptions), which the command line and Python show and take.
struct SweepCommand {
  std::string parameter = "omega";  // a parameter of the model's description
  double from = 0.0;
  double to = 0.0;
  double steps = SweepOptions{}.steps;  // whole numbers, each in the range SweepOptionRange gives
  double transients = SweepOptions{}.transient_periods;
  double periods = SweepOptions{}.recorded_periods;
  std::string start = SweepOptions{}.start == SweepStart::kChained ? "chained" : "fixed";
  double chains = 4;
  double scatter = 1.0;  // 0 <= scatter <= 1e6
  double seed = 1;
  double threads = SweepOptions{}.threads;
};
// The valid range of a sweep option ("1 <= steps <= 100000"), for help texts and messages.
std::string SweepOptionRange(std::string_view field);

// The sweep `command` describes of a model: its options (the parameter by its name in the model's
// description), and how its chains start: ScatteredStarts(the given state, scatter, chains, seed).
// Throws InvalidInput naming "parameter", "start", "scatter" or the whole-number option out of its
// range; the swept values are checked by Sweep.
struct SweepPlan {
  SweepOptions options;
  int chains = 1;
  double scatter = 0.0;
  std::uint64_t seed = 0;
};
SweepPlan PlanSweep(const SweepCommand& command, const ModelDescription& model);

// find: the options as given (numbers not yet checked to be whole or in range), the defaults the
// library's. FindOptionsOf checks them, naming "transients", "max-multiple", "tolerance" or
// "confirmations"; FindOptionRange(field) is the valid range of one, for help texts and messages.
struct FindCommand {
  double transients = FindOrbitOptions{}.transient_periods;
  double max_multiple = FindOrbitOptions{}.max_multiple;
  double tolerance = FindOrbitOptions{}.periodicity_tolerance;
  double confirmations = FindOrbitOptions{}.confirmations;
};
std::string FindOptionRange(std::string_view field);
FindOrbitOptions FindOptionsOf(const FindCommand& command);

// map-sweep: the options as given (numbers not yet checked to be whole or in range), the defaults
// the library's (BruteForceMapOptions); shard and shards already read from the command line's
// "k/N". MapOptionsOf checks them as the command line names them ("first", "first-steps",
// "transients", "periods", "starts", "seed", "tolerance", "threads"; the cells' parameters as
// "grid"), the centre of the scattered starts being the origin's state.
struct MapSweepCommand {
  std::string first = ToString(BruteForceMapOptions{}.first.parameter);
  std::string second = ToString(BruteForceMapOptions{}.second.parameter);
  double first_from = 0.0;
  double first_to = 0.0;
  double first_steps = BruteForceMapOptions{}.first.steps;
  double second_from = 0.0;
  double second_to = 0.0;
  double second_steps = BruteForceMapOptions{}.second.steps;
  double transients = BruteForceMapOptions{}.transient_periods;
  double periods = BruteForceMapOptions{}.recorded_periods;
  double starts = BruteForceMapOptions{}.scattered_starts;
  double scatter = BruteForceMapOptions{}.scatter;
  double seed = static_cast<double>(BruteForceMapOptions{}.seed);
  double tolerance = BruteForceMapOptions{}.periodicity_tolerance;
  double threads = BruteForceMapOptions{}.threads;
  int shard = 1;
  int shards = 1;
};
// The valid range of a map-sweep option ("whole numbers 0 <= first-steps <= 10000"), for help
// texts and messages.
std::string MapSweepOptionRange(std::string_view field);
BruteForceMapOptions MapOptionsOf(const MapSweepCommand& command, const ModelStart& origin);

// atlas: the options as given (the command line's flags, Python's keywords; numbers not yet checked
// to be whole or in range), the defaults the library's (AtlasOptions; the grid's steps 40).
// AtlasOptionsOf checks them as the command line names them ("parameter", "range", "steps",
// "transients", "periods", "starts", "seed", "tolerance", "threads", "max-multiple",
// "max-amplitude", "max-points", "resonance-approach"; the range's ends, each a value of the parameter, as "range"; the
// grid values' parameters as "grid"), the brute force's scattered starts around the origin's state.
struct AtlasCommand {
  std::string parameter = ToString(AtlasOptions{}.brute_force.first.parameter);
  double from = 0.0;  // the range: from < to
  double to = 0.0;
  double steps = 40;
  double transients = AtlasOptions{}.brute_force.transient_periods;
  double periods = AtlasOptions{}.brute_force.recorded_periods;
  double starts = AtlasOptions{}.brute_force.scattered_starts;
  double scatter = AtlasOptions{}.brute_force.scatter;
  double seed = static_cast<double>(AtlasOptions{}.brute_force.seed);
  double tolerance = AtlasOptions{}.brute_force.periodicity_tolerance;
  double threads = AtlasOptions{}.brute_force.threads;
  double max_multiple = AtlasOptions{}.max_multiple;
  double max_amplitude = AtlasOptions{}.trace.max_amplitude;
  double max_points = AtlasOptions{}.continuation.max_points;  // per branch of every trace
  double resonance_approach = AtlasOptions{}.resonance_approach;
};
AtlasOptions AtlasOptionsOf(const AtlasCommand& command, const ModelStart& origin);

}  // namespace stickslip
