// stickslip simulate: event-driven simulation from an initial state, exact or with Boost.Odeint.
#include <cmath>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "cli_common.hpp"
#include "commands.hpp"
#include "progress_line.hpp"
#include "start_options.hpp"
#include "stickslip/io/atomic_file.hpp"
#include "stickslip/io/command_options.hpp"
#include "stickslip/io/output_marker.hpp"
#include "stickslip/model/pascal_2014/odeint_simulator.hpp"
#include "stickslip/model/simulation.hpp"
#include "stickslip/model/transient.hpp"

namespace stickslip::cli {

namespace {

struct SimulateArgs {
  StartFlags start;
  std::string periods = "2";
  std::string transients = "0";
  std::string method = "exact";
  std::string csv_path;
  bool csv_given = false;  // --csv "" is refused, not taken as no --csv
  std::string samples_per_period = "200";
  std::string max_events = "10000000";
  bool json = false;
  bool force = false;
};

// The CSV's header, its first line: the mark of a file that simulate may replace.
constexpr std::string_view kCsvHeader = "t,x1,x2,v1,v2,mode";

std::string StateJson(const State& x) {
  return fmt::format("[{}, {}, {}, {}]", x(0), x(1), x(2), x(3));
}

// The events as one JSON object, printed event by event (a long simulation has millions). The
// printed times are the paper's absolute t: the simulation after a transient of t0 counts its
// time from t0 (the forcing has the same phase there), and t0 is added back.
void PrintEventsJson(const SimulationResult& result, double t0) {
  fmt::print("{{\"events\": [");
  for (std::size_t i = 0; i < result.events.size(); ++i) {
    const Event& e = result.events[i];
    fmt::print("{}{{\"t\": {}, \"kind\": \"{}\", \"mode_after\": \"{}\", \"state\": {}}}",
               i == 0 ? "" : ", ", t0 + e.t, ToString(e.kind), ToString(e.mode_after), StateJson(e.state));
  }
  fmt::print("]}}\n");
}

void PrintEventTable(const SimulationResult& result, double t0) {
  fmt::print("{:>22} {:<14} {:<6} {:>22} {:>22} {:>22} {:>22}\n", "t", "event", "after", "x1", "x2", "x1'", "x2'");
  for (const Event& e : result.events) {
    const std::string kind =
        e.IsAbnormalStop() ? std::string("abnormal-stop") : std::string(ToString(e.kind));
    fmt::print("{:>22.15g} {:<14} {:<6} {:>22.15g} {:>22.15g} {:>22.15g} {:>22.15g}\n", t0 + e.t, kind,
               ToString(e.mode_after), e.state(0), e.state(1), e.state(2), e.state(3));
  }
}

// The largest --max-events: the events and segments a simulation keeps take about 150 bytes each.
constexpr int kMaxEventsLimit = 10000000;

int RunSimulate(const SimulateArgs& args) {
  if (args.csv_given) {
    const OutputMarker marker{"stickslip simulate", [](std::string_view line) { return line == kCsvHeader; }};
    CheckReplaceableOutputFile(args.csv_path, "csv", marker, args.force);
  }
  const ModelStart input = BuildModelStart(ToStartInput(args.start));
  const double periods = ParseNumber("periods", args.periods, "0 < periods <= 1e6");
  const double samples_per_period =
      ParseNumber("samples-per-period", args.samples_per_period, "1 <= samples-per-period <= 1e5");
  SimulationOptions options = SimulationOver(input.parameters, periods, samples_per_period, args.csv_given);
  const int transients = ParseCount("transients", args.transients, 0, kMaxTransientPeriods);
  const int max_events = ParseCount("max-events", args.max_events, 1, kMaxEventsLimit);
  const double period = 2.0 * std::numbers::pi / input.parameters.omega;
  const Simulator simulate =
      args.method == "exact"
          ? Simulator(SimulateExact)
          : Simulator([](const Parameters& p, const State& x0, double phi, const SimulationOptions& o) {
              return SimulateOdeint(p, x0, phi, o);
            });
  ProgressLine line("simulate");
  // One line over the transient and the shown periods.
  auto reporting = [&](double offset) -> ProgressCallback {
    if (!line.enabled()) return {};
    return [&line, offset, total = transients + periods](const Progress& p) {
      line.Update({offset + p.done, total, "periods"});
    };
  };
  TransientOptions transient;
  transient.periods = transients;
  transient.simulation.progress = reporting(0.0);
  const Transient settled =
      SimulateTransient(simulate, input.parameters, input.initial_state, input.phi, transient);
  if (!settled.Completed()) {
    line.Clear();
    fmt::print(stderr, "error: simulation incomplete in the transient: {}\n", settled.message);
    return kExitFailure;
  }
  const double t0 = settled.t;
  options.max_events = max_events;
  options.progress = reporting(transients);
  // The time series goes to the file sample by sample (1e6 periods at 1e5 samples each would
  // not fit in memory), and the file appears, whole, once the simulation has ended.
  std::optional<AtomicFileWriter> csv;
  if (args.csv_given) {
    csv.emplace(args.csv_path);
    csv->Write(fmt::format("{}\n", kCsvHeader));
    options.on_sample = [&csv, t0](const TimeSample& s, Mode mode) {
      csv->Write(fmt::format("{},{},{},{},{},{}\n", t0 + s.t, s.state(0), s.state(1), s.state(2), s.state(3),
                             ToString(mode)));
    };
  }
  const SimulationResult result = simulate(input.parameters, settled.state, input.phi, options);
  line.Clear();
  if (csv) csv->Commit();
  if (args.json) {
    PrintEventsJson(result, t0);
  } else {
    const State& x = input.initial_state;
    fmt::print("stickslip simulate{}: {}\n", args.start.preset.empty() ? "" : " " + args.start.preset,
               DescribeParameters(input.parameters));
    fmt::print("start: x10={} x20={} v10={} v20={} phi={}; {} period(s) of 2 pi/omega = {}; "
               "method {}\n",
               x(0), x(1), x(2), x(3), input.phi, periods, period, args.method);
    if (transient.periods > 0) {
      const State& y = settled.state;
      fmt::print("after {} transient period(s), not shown: t={} x1={} x2={} x1'={} x2'={}\n", transient.periods, t0,
                 y(0), y(1), y(2), y(3));
    }
    PrintEventTable(result, t0);
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
  return {cmd, [args] { return RunSimulate(*args); }};
}

}  // namespace stickslip::cli
