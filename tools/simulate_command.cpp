// stickslip simulate: event-driven simulation from an initial state, exact or with Boost.Odeint.
#include <cmath>
#include <functional>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "cli_common.hpp"
#include "commands.hpp"
#include "progress_line.hpp"
#include "start_options.hpp"
#include "stickslip/io/atomic_file.hpp"
#include "stickslip/io/command_options.hpp"
#include "stickslip/io/output_marker.hpp"
#include "model_find.hpp"
#include "stickslip/io/model_find.hpp"
#include "stickslip/model/exact_simulator.hpp"
#include "stickslip/model/odeint_simulation.hpp"
#include "stickslip/model/pascal_2014/odeint_simulator.hpp"
#include "stickslip/model/transient.hpp"
#include "stickslip/model/simulation.hpp"
#include "stickslip/model/transient.hpp"

namespace stickslip::cli {

namespace {

struct SimulateArgs {
  StartFlags start;
  std::string periods = fmt::format("{}", SimulateCommand{}.periods);
  std::string transients = fmt::format("{}", SimulateCommand{}.transients);
  std::string method = SimulateCommand{}.method;
  std::string csv_path;
  bool csv_given = false;  // --csv "" is refused, not taken as no --csv
  std::string samples_per_period = fmt::format("{}", SimulateCommand{}.samples_per_period);
  std::string max_events = fmt::format("{}", SimulateCommand{}.max_events);
  bool json = false;
  bool force = false;
  std::string model;  // --model FILE: a user's oscillator (io/model_find.hpp)
};

// The CSV's header, its first line: t, the state by the model's column names, mode (the paper's:
// t,x1,x2,v1,v2,mode). A first line of that form, any model's, is the mark of a file that
// simulate wrote and may replace.
std::string CsvHeader(const ModelDescription& d) { return fmt::format("t,{},mode", fmt::join(d.state_columns, ",")); }
bool IsCsvHeader(std::string_view line) {
  return line.starts_with("t,") && line.ends_with(",mode") && line.find(' ') == std::string_view::npos;
}

template <typename StateType>
std::string StateJson(const StateType& x) {
  std::vector<double> values(x.data(), x.data() + x.size());
  return fmt::format("[{}]", fmt::join(values, ", "));
}

// The events as one JSON object, printed event by event (a long simulation has millions). The
// printed times are absolute: the simulation after a transient of t0 counts its time from t0 (the
// forcing has the same phase there), and t0 is added back.
template <typename Result>
void PrintEventsJson(const Result& result, double t0) {
  fmt::print("{{\"events\": [");
  bool first = true;
  for (const auto& e : result.events) {
    if (!e.state.allFinite()) continue;  // where a motion growing without bound overflowed: it ends there
    fmt::print("{}{{\"t\": {}, \"kind\": \"{}\", \"mode_after\": \"{}\", \"state\": {}}}",
               first ? "" : ", ", t0 + e.t, ToString(e.kind), ToString(e.mode_after), StateJson(e.state));
    first = false;
  }
  fmt::print("]}}\n");
}

// One row per event, the state by the model's component names (the paper's x1, x2, x1', x2').
template <typename Result>
void PrintEventTable(const Result& result, double t0, const ModelDescription& d) {
  std::string header = fmt::format("{:>22} {:<14} {:<6}", "t", "event", "after");
  for (const std::string& name : d.state_components) header += fmt::format(" {:>22}", name);
  fmt::print("{}\n", header);
  for (const auto& e : result.events) {
    if (!e.state.allFinite()) continue;  // where a motion growing without bound overflowed: it ends there
    const std::string kind = e.IsAbnormalStop() ? std::string("abnormal-stop") : std::string(ToString(e.kind));
    std::string row = fmt::format("{:>22.15g} {:<14} {:<6}", t0 + e.t, kind, ToString(e.mode_after));
    for (int i = 0; i < e.state.size(); ++i) row += fmt::format(" {:>22.15g}", e.state(i));
    fmt::print("{}\n", row);
  }
}

// The largest --max-events: the events and segments a simulation keeps take about 150 bytes each.
constexpr int kMaxEventsLimit = 10000000;

// One simulation, as every model runs it: what is to be simulated and how it is described.
template <typename Model>
struct Simulation {
  const Model& model;
  typename Model::Parameters parameters;
  typename Model::State x0;
  double phi = 0.0;
  // The forcing's frequency, or without forcing the slowest free oscillation's: --periods and
  // --transients count its periods 2 pi/frequency.
  double frequency = 1.0;
  // The lines before the table: the data and the start, then (given the transient's end) where the
  // shown part starts.
  std::function<void(const BasicTransient<typename Model::State>&, int transients, double periods)> describe;
};

// The transient (not shown), then --periods shown: the table, --json or --csv, and the exit code.
template <typename Model, typename Simulate>
int SimulateAndReport(const Simulation<Model>& sim, const Simulate& simulate, const SimulateArgs& args) {
  using ModelState = typename Model::State;
  const double periods = ParseNumber("periods", args.periods, "0 < periods <= 1e6");
  const double samples_per_period =
      ParseNumber("samples-per-period", args.samples_per_period, "1 <= samples-per-period <= 1e5");
  auto options = SimulationOver<ModelState>(2.0 * std::numbers::pi / sim.frequency, periods, samples_per_period,
                                            args.csv_given);
  const int transients = ParseCount("transients", args.transients, 0, kMaxTransientPeriods);
  options.max_events = ParseCount("max-events", args.max_events, 1, kMaxEventsLimit);
  ProgressLine line("simulate");
  // One line over the transient and the shown periods.
  auto reporting = [&](double offset) -> ProgressCallback {
    if (!line.enabled()) return {};
    return [&line, offset, total = transients + periods](const Progress& p) {
      line.Update({offset + p.done, total, "periods"});
    };
  };
  BasicTransientOptions<ModelState> transient;
  transient.periods = transients;
  transient.simulation.progress = reporting(0.0);
  const auto settled =
      SimulateTransientAt(sim.frequency, simulate, sim.parameters, sim.x0, sim.phi, transient);
  if (!settled.Completed()) {
    line.Clear();
    fmt::print(stderr, "error: simulation incomplete in the transient: {}\n", settled.message);
    return kExitFailure;
  }
  const double t0 = settled.t;
  options.progress = reporting(transients);
  // The time series goes to the file sample by sample (1e6 periods at 1e5 samples each would
  // not fit in memory), and the file appears, whole, once the simulation has ended.
  std::optional<AtomicFileWriter> csv;
  if (args.csv_given) {
    csv.emplace(args.csv_path);
    csv->Write(CsvHeader(sim.model.Description()) + "\n");
    options.on_sample = [&csv, t0](const BasicTimeSample<ModelState>& s, Mode mode) {
      if (!s.state.allFinite()) return;  // where a motion growing without bound overflowed: it ends there
      std::vector<double> values(s.state.data(), s.state.data() + s.state.size());
      csv->Write(fmt::format("{},{},{}\n", t0 + s.t, fmt::join(values, ","), ToString(mode)));
    };
  }
  const auto result = simulate(sim.parameters, settled.state, sim.phi, options);
  line.Clear();
  if (csv) csv->Commit();
  if (args.json) {
    PrintEventsJson(result, t0);
  } else {
    sim.describe(settled, transients, periods);
    PrintEventTable(result, t0, sim.model.Description());
    fmt::print("{} event(s), {} segment(s){}\n", result.events.size(), result.segments.size(),
               !args.csv_given ? "" : fmt::format("; time series written to {}", args.csv_path));
  }
  if (!result.Completed()) {
    fmt::print(stderr, "error: simulation incomplete: {}{}\n", result.message,
               result.end == SimulationEnd::kMaxEvents ? "; --max-events (up to 1e7) or a shorter --periods lets it end" : "");
    return kExitFailure;
  }
  return kExitOk;
}

void CheckCsv(const SimulateArgs& args) {
  if (!args.csv_given) return;
  const OutputMarker marker{"stickslip simulate", IsCsvHeader};
  CheckReplaceableOutputFile(args.csv_path, "csv", marker, args.force);
}

int RunSimulate(const SimulateArgs& args) {
  CheckCsv(args);
  const Pascal2014 model;
  const ModelStart input = BuildModelStart(ToStartInput(args.start));
  const Simulation<Pascal2014> sim{
      model, input.parameters, input.initial_state, input.phi, input.parameters.omega,
      [&](const Transient& settled, int transients, double periods) {
        const State& x = input.initial_state;
        fmt::print("stickslip simulate{}: {}\n", args.start.preset.empty() ? "" : " " + args.start.preset,
                   DescribeParameters(input.parameters));
        fmt::print("start: x10={} x20={} v10={} v20={} phi={}; {} period(s) of 2 pi/omega = {}; method {}\n", x(0), x(1),
                   x(2), x(3), input.phi, periods, 2.0 * std::numbers::pi / input.parameters.omega, args.method);
        if (transients > 0) {
          const State& y = settled.state;
          fmt::print("after {} transient period(s), not shown: t={} x1={} x2={} x1'={} x2'={}\n", transients,
                     settled.t, y(0), y(1), y(2), y(3));
        }
      }};
  if (args.method == "exact") {
    return SimulateAndReport(sim, [](const Parameters& p, const State& x, double phi, const SimulationOptions& o) {
      return SimulateExact(p, x, phi, o);
    }, args);
  }
  return SimulateAndReport(sim, [](const Parameters& p, const State& x, double phi, const SimulationOptions& o) {
    return SimulateOdeint(p, x, phi, o);
  }, args);
}

// simulate --model: the run file's oscillator from the start it and --set give; without forcing
// --periods counts periods of the slowest free oscillation of its slip (as find's).
int RunModelSimulate(const SimulateArgs& args, const CLI::App& cmd) {
  RefuseWithModel(cmd, {"--preset", "--point"},
                  "the run file's [model] and --set give the oscillator, its parameters and its start");
  using Model = DynamicLinearOscillator;
  CheckCsv(args);
  if (args.csv_given) RefuseOutputOverModel(args.csv_path, args.model, "csv");
  const ModelFileStart start = ReadModelFileStart(args.model, ModelSetOf(args.start.set));
  const double frequency = start.model.Autonomous() ? start.slowest_frequency : start.parameters.omega;
  const ModelDescription& d = start.model.Description();
  const auto named = [](const std::vector<std::string>& names, const Eigen::VectorXd& x) {
    std::string text;
    for (int i = 0; i < x.size(); ++i) text += fmt::format("{}{}={}", i == 0 ? "" : " ", names[i], x(i));
    return text;
  };
  const Simulation<Model> sim{
      start.model, start.parameters, start.state, start.phi, frequency,
      [&](const BasicTransient<Model::State>& settled, int transients, double periods) {
        std::string parameters;
        for (int k = 0; k < Model::kParameterCount; ++k) {
          parameters += fmt::format("{}{}={}", k == 0 ? "" : " ", d.parameters[k].name, Model::ParameterAt(start.parameters, k));
        }
        fmt::print("stickslip simulate --model {}: {}\n", args.model, parameters);
        fmt::print("start: {} phi={}; {} period(s) of {} = {}; method {}\n", named(d.initial_state, start.state), start.phi,
                   periods, start.model.Autonomous() ? "2 pi/omega_1 (the slowest free oscillation)" : "2 pi/omega",
                   2.0 * std::numbers::pi / frequency, args.method);
        if (transients > 0) {
          fmt::print("after {} transient period(s), not shown: t={} {}\n", transients, settled.t,
                     named(d.state_components, settled.state));
        }
      }};
  using Options = BasicSimulationOptions<Model::State>;
  if (args.method == "exact") {
    return SimulateAndReport(sim, [&](const Model::Parameters& p, const Model::State& x, double phi, const Options& o) {
      return SimulateExact(start.model, p, x, phi, o);
    }, args);
  }
  return SimulateAndReport(sim, [&](const Model::Parameters& p, const Model::State& x, double phi, const Options& o) {
    return SimulateOdeint(start.model, p, x, phi, o);
  }, args);
}

}  // namespace

Command AddSimulateCommand(CLI::App& app) {
  auto args = std::make_shared<SimulateArgs>();
  CLI::App* cmd = app.add_subcommand(
      "simulate",
      "Simulate the oscillator from an initial state under Coulomb's law and print every stop "
      "and stick exit (time, kind, mode after, state). Time is the paper's scaled time t.");
  AddStartOptions(*cmd, &args->start, StartOptions::kMotion);
  cmd->add_option("--results", args->start.results, "where the runs of --point are stored")->capture_default_str();
  cmd->add_option("--periods", args->periods,
                  "simulated time in forcing periods 2 pi/omega (0 < periods <= 1e6)")
      ->type_name("FLOAT")
      ->capture_default_str();
  cmd->add_option("--transients", args->transients,
                  "forcing periods simulated first and not shown (whole numbers, 0 to 1e6); the table, "
                  "--json and --csv then cover --periods after them, with times still counted from the "
                  "start of the simulation (the paper's t, so that phases keep their meaning: the "
                  "first shown time is >= transients * 2 pi/omega)")
      ->type_name("N")
      ->capture_default_str();
  cmd->add_option("--method", args->method,
                  "exact: closed-form flows with rigorous event location (1e-13 in time); "
                  "odeint: independent Boost.Odeint dopri5 integration (tolerance 1e-12)")
      ->check(CLI::IsMember({"exact", "odeint"}))
      ->capture_default_str();
  cmd->add_option("--max-events", args->max_events,
                  "stop after this many events of the shown --periods, with exit code 1 and a message (1 to "
                  "1e7; a guard against chattering and a bound on memory, about 150 bytes an event; the "
                  "transient runs in chunks of 1000 periods, each under 1e6 events)")
      ->type_name("INT")
      ->capture_default_str();
  cmd->add_option("--csv", args->csv_path,
                  "also write the time series to this CSV file (header t,x1,x2,v1,v2,mode); "
                  "written whole or not at all")
      ->type_name("FILE")
      ->each([args](const std::string&) { args->csv_given = true; });
  cmd->add_flag("--force", args->force, kForceHelp);
  cmd->add_option("--samples-per-period", args->samples_per_period,
                  "CSV sampling density (1 to 1e5 samples per forcing period)")
      ->type_name("FLOAT")
      ->capture_default_str();
  cmd->add_flag("--json", args->json,
                "print one JSON object {\"events\": [{\"t\", \"kind\", \"mode_after\", "
                "\"state\": [x1, x2, x1', x2']}]} instead of the table");
  cmd->add_option("--model", args->model,
                  "simulate the oscillator in this run file's [model] (see describe) instead of the paper's, in its "
                  "own units (SI unless its units say otherwise): from the file's start (rest unless it gives one) and --set's parameters, start "
                  "state (x1_0, v1_0, ...) and phi; the table, --json and the CSV (t, the model's state columns, mode) "
                  "name its coordinates. Without forcing --periods and --transients count periods of its slowest free "
                  "oscillation 2 pi/omega_1")
      ->type_name("FILE");
  return {cmd, [args, cmd] {
            if (cmd->count("--model") != 0 && args->model.empty()) throw InvalidInput("model", "''", "a run file's path");
            return args->model.empty() ? RunSimulate(*args) : RunModelSimulate(*args, *cmd);
          }};
}

}  // namespace stickslip::cli
