// stickslip find: from a simulated motion to its exact periodic orbit (analysis/orbit_finder.hpp):
// the detected period and orbit type, the solved orbit as solve prints it (or as JSON), the solve
// command line (or a run file) that reproduces it, and at once the trace from it (--trace).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli_common.hpp"
#include "commands.hpp"
#include "continue_flags.hpp"
#include "found_run.hpp"
#include "model_find.hpp"
#include "stickslip/io/model_find.hpp"
#include "orbit_json.hpp"
#include "orbit_report.hpp"
#include "progress_line.hpp"
#include "start_options.hpp"
#include "stickslip/analysis/orbit_finder.hpp"
#include "stickslip/io/atomic_file.hpp"
#include "stickslip/io/command_options.hpp"
#include "stickslip/io/output_marker.hpp"
#include "stickslip/io/run_file.hpp"
#include "stickslip/io/trace_files.hpp"
#include "trace_run.hpp"

namespace stickslip::cli {

namespace {

struct FindArgs {
  StartFlags start;
  std::string transients = std::to_string(FindOrbitOptions{}.transient_periods);
  std::string max_multiple = std::to_string(FindOrbitOptions{}.max_multiple);
  std::string tolerance = fmt::format("{}", FindOrbitOptions{}.periodicity_tolerance);
  std::string confirmations = std::to_string(FindOrbitOptions{}.confirmations);
  std::string write_run;
  bool write_run_given = false;  // --write-run "" is refused, not taken as no --write-run
  std::string run_kind = "continue";  // --as: the run file's kind
  std::string range;                  // --range: the run file's, "LO,HI"
  std::string trace;                  // --trace LO,HI: trace at once
  std::string output;                 // --output: the trace's directory under --results
  bool json = false;
  bool force = false;
  std::string model;  // --model FILE: a user's oscillator (model_find.hpp)
  std::string trace_parameter;  // --trace-parameter, with --model
  BranchSteps steps;  // --ds, --ds-min, --ds-max, --max-points: each branch's, with --trace or --write-run
};

// The step options, taken where find runs branches or writes a run file that does (checked as
// continue checks them).
void CheckStepOptions(const FindArgs& args, const CLI::App& cmd) {
  const bool branches = !args.trace.empty() || (args.write_run_given && cmd.count("--model") == 0);
  for (const char* option : {"--ds", "--ds-min", "--ds-max", "--max-points"}) {
    if (cmd.count(option) == 0 || branches) continue;
    throw InvalidInput(option + 2, cmd.get_option(option)->as<std::string>(),
                       "with --trace or --write-run (the steps of their branches)");
  }
  CheckSteps(args.steps);
}

// The solve command line of a start (StartInputOf): signature, set, guess, free, tie.
std::string SolveCommandLine(const StartInput& start) {
  std::string line = fmt::format("stickslip solve --signature \"{}\"", start.signature);
  for (const auto& [name, value] : start.set) line += fmt::format(" --set {}={}", name, ExactNumber(value));
  for (const auto& [name, value] : start.guess) line += fmt::format(" --guess {}={}", name, ExactNumber(value));
  for (const std::string& name : start.free) line += " --free " + name;
  if (start.tie_u_r) line += " --tie-u_r";
  return line;
}

// Whether `path` lies inside `directory` (both as they resolve, links followed): a run file there
// would be replaced or deleted by the trace that replaces the directory, or would replace its files.
bool IsInside(const std::filesystem::path& path, const std::filesystem::path& directory) {
  namespace fs = std::filesystem;
  const auto resolved = [](const fs::path& given) {
    std::error_code error;  // a path that cannot be resolved is compared as written
    const fs::path canonical = fs::weakly_canonical(fs::absolute(given), error);
    return error ? fs::absolute(given).lexically_normal() : canonical;
  };
  const fs::path file = resolved(path), root = resolved(directory);
  const auto [end, unused] = std::mismatch(root.begin(), root.end(), file.begin(), file.end());
  return end == root.end();
}

// What find writes after the work, checked before it: the trace's directory and the run file, their
// ranges and their combinations. Throws InvalidInput naming the option.
struct FindOutputs {
  std::optional<OmegaRange> trace;  // --trace
  std::optional<OmegaRange> range;  // the run file's --range
};
FindOutputs CheckOutputs(const FindArgs& args) {
  auto refuse = [](const char* field, const std::string& value, const std::string& valid) {
    throw InvalidInput::WithMessage(field, fmt::format("{} = '{}' is invalid: valid {}", field, value, valid));
  };
  if (args.json && !args.trace.empty()) refuse("json", "true", "without --trace (the trace reports in text; its trace.json is JSON)");
  if (!args.write_run_given && args.run_kind != "continue") refuse("as", args.run_kind, "with --write-run");
  if (!args.write_run_given && !args.range.empty()) refuse("range", args.range, "with --write-run");
  if (!args.trace.empty() && !args.range.empty()) refuse("range", args.range, "left out with --trace (the run file takes its range)");
  if (args.trace.empty() && !args.output.empty() && !args.write_run_given) refuse("output", args.output, "with --trace or --write-run");
  FindOutputs outputs;
  if (!args.trace.empty()) {
    outputs.trace = ParseOmegaRange("trace", args.trace);
    if (args.output.empty()) throw InvalidInput::WithMessage("output", "output is missing: valid a run name, with --trace");
    if (!IsRunName(args.output)) throw InvalidInput("output", "'" + args.output + "'", std::string(kRunNameRule));
    CheckTraceOutputDirectory(args.start.results, args.output);
  }
  if (!args.range.empty()) outputs.range = ParseOmegaRange("range", args.range);
  const std::filesystem::path trace_directory = std::filesystem::path(args.start.results) / args.output;
  if (outputs.trace && args.write_run_given && IsInside(args.write_run, trace_directory)) {
    refuse("write-run", args.write_run,
           fmt::format("a file outside the trace's directory '{}' (the trace replaces it whole)", trace_directory.string()));
  }
  if (args.write_run_given) {
    const OutputMarker marker{"stickslip find", [](std::string_view line) { return line == kFoundRunFileMarker; }};
    CheckReplaceableOutputFile(args.write_run, "write-run", marker, args.force);
  }
  return outputs;
}

// A range that does not hold omega traces nothing from the found orbit: find holds the parameters,
// so the orbit's omega is the start's, and the range is refused before the simulation.
void CheckRangeHolds(const char* field, const std::string& text, const std::optional<OmegaRange>& range, double omega) {
  if (!range || (range->low <= omega && omega <= range->high)) return;
  throw InvalidInput(field, "'" + text + "'", fmt::format("LO,HI that holds the start's omega = {}", omega));
}

// The run file's name for the run: --output, else the file's stem where it is a run name.
std::string RunFileOutput(const FindArgs& args) {
  if (!args.output.empty()) return args.output;
  const std::string stem = std::filesystem::path(args.write_run).stem().string();
  return IsRunName(stem) ? stem : "found-orbit";
}

// The run file and the trace of the found orbit; returns the trace's exit code (kExitOk without one).
int WriteAndTrace(const FindArgs& args, const FindOutputs& outputs, const StartInput& solved, double omega) {
  if (args.write_run_given) {
    const OmegaRange range = outputs.range ? *outputs.range : outputs.trace ? *outputs.trace : RangeAround(omega);
    const RunFile run = FoundRun(solved, range, RunFileOutput(args), args.run_kind == "trace", args.steps);
    WriteFileAtomically(args.write_run, RunFileText(run));
    if (!args.json) fmt::print("run file   {} (stickslip run {})\n", args.write_run, args.write_run);
  }
  if (!outputs.trace) return kExitOk;
  const RunFile run = FoundRun(solved, *outputs.trace, args.output, true, args.steps);
  const TraceRun trace = ExecuteTrace(run, args.start.results);
  return trace.stored ? WriteAndReportTrace(*trace.stored, trace.seconds, args.start.results) : trace.exit_code;
}

// find's outcome as one JSON object, by the names of Python's Found: status, message, the section's
// numbers, the signature read off the motion, and the solved orbit as solve --json gives it (or null).
std::string FindJson(const FindOrbitResult& found) {
  using Json = nlohmann::ordered_json;
  Json out{{"status", ToString(found.status)},
           {"message", found.message},
           {"transient_periods", found.transient_periods},
           {"period_multiple", found.period_multiple},
           {"mismatch", std::isfinite(found.mismatch) ? Json(found.mismatch) : Json(nullptr)},
           {"closest_multiple", found.closest_multiple},
           {"antisymmetric", found.antisymmetric},
           {"signature", found.start ? Json(found.start->signature) : Json(nullptr)},
           {"orbit", nullptr}};
  if (found.solution && found.solution->summary.Converged()) {
    out["orbit"] = OrbitJson(*found.solution, found.problem->free, found.problem->unknowns.tie_static_friction,
                             found.margins, *found.verification);
  }
  return out.dump() + "\n";
}

void PrintFound(const FindOrbitResult& found, const FindOrbitOptions& options) {
  if (found.period_multiple > 0) {
    fmt::print("motion     periodic after {} transient period(s): k = {} forcing period(s), section mismatch {:.3g}{}\n",
               found.transient_periods, found.period_multiple, found.mismatch,
               found.antisymmetric ? fmt::format(", antisymmetric (mismatch {:.3g})", found.antisymmetry_mismatch) : "");
  }
  if (found.start) fmt::print("origin     t = {} after the transient (a segment end)\n", found.origin_time);
  if (found.solution && found.solution->summary.Converged()) {
    fmt::print("{}", OrbitReport(*found.solution, found.problem->free, found.problem->unknowns.tie_static_friction,
                                 ToString(options.solver.sparse_solver), found.margins, *found.verification));
    fmt::print("solve it again, or continue from it, with:\n  {}\n", SolveCommandLine(StartInputOf(found.solution->orbit)));
  } else if (found.start) {
    fmt::print("the start read off the motion:\n  {}\n", SolveCommandLine(*found.start));
  }
}

int RunFind(const FindArgs& args) {
  const FindOutputs outputs = CheckOutputs(args);
  const ModelStart input = BuildModelStart(ToStartInput(args.start));
  CheckRangeHolds("trace", args.trace, outputs.trace, input.parameters.omega);
  CheckRangeHolds("range", args.range, outputs.range, input.parameters.omega);
  // The texts become numbers here; FindOptionsOf checks them, as it does for Python's find.
  auto number = [](const char* field, const std::string& text) { return ParseNumber(field, text, FindOptionRange(field)); };
  FindCommand command;
  command.transients = number("transients", args.transients);
  command.max_multiple = number("max-multiple", args.max_multiple);
  command.tolerance = number("tolerance", args.tolerance);
  command.confirmations = number("confirmations", args.confirmations);
  FindOrbitOptions options = FindOptionsOf(command);

  ProgressLine line("find: transient");
  options.progress = line.Callback();
  const FindOrbitResult found = FindOrbit(input.parameters, input.initial_state, input.phi, options);
  line.Clear();
  if (args.json) {
    fmt::print("{}", FindJson(found));
  } else {
    PrintFound(found, options);
  }
  // Only a verified orbit is a start to continue or trace from: otherwise nothing is written.
  if (const int code = FindExitCode(found.status); code != kExitOk) {
    fmt::print(stderr, "error: {}\n", found.message);
    return code;
  }
  const Orbit& orbit = found.solution->orbit;
  return WriteAndTrace(args, outputs, StartInputOf(orbit), orbit.parameters.omega);
}

// find --model: the options of the paper's model's start and of what find writes are refused.
int RunModelFindOf(const FindArgs& args, const CLI::App& cmd) {
  RefuseWithModel(cmd,
                  {"--preset", "--point", "--tolerance", "--confirmations", "--write-run", "--as", "--range", "--force"},
                  "valid with --model are --set, --transients, --max-multiple, --trace, --trace-parameter, --output, "
                  "--results, --ds, --ds-min, --ds-max, --max-points and --json");
  if (cmd.count("--output") != 0 && args.output.empty()) {
    throw InvalidInput("output", "''", std::string(kRunNameRule));
  }
  if (cmd.count("--results") != 0 && cmd.count("--output") == 0) {
    throw InvalidInput("results", "'" + args.start.results + "'", "with --output (where the trace is written)");
  }
  return RunModelFind({args.model, args.start.set, args.transients, args.max_multiple, args.json, args.trace,
                       args.trace_parameter, args.output, args.start.results, args.steps});
}

}  // namespace

Command AddFindCommand(CLI::App& app) {
  auto args = std::make_shared<FindArgs>();
  CLI::App* cmd = app.add_subcommand(
      "find",
      "Simulate from a start (as simulate does), detect the period of the motion on the stroboscopic section "
      "(t = n 2 pi/omega), read its orbit type, durations, phase and state off one period, solve the "
      "periodicity equations from there and verify the orbit by both simulators. Prints the orbit as solve "
      "does (or as JSON) and the solve command line that gives it; with --trace, traces from it at once. Exit "
      "code 0 found and verified (and the trace ran to its ends), 3 Newton did not converge, 4 the solution is "
      "not a motion or fails its verification, 5 the motion is not periodic within --max-multiple forcing periods "
      "(or has no stop or stick exit), 1 the simulation stopped early; unless 0, no file is written.");
  AddStartOptions(*cmd, &args->start, StartOptions::kMotion);
  cmd->add_option("--results", args->start.results,
                  "where the runs of --point are stored, and where --trace writes <output>/")
      ->capture_default_str();
  cmd->add_option("--transients", args->transients,
                  fmt::format("forcing periods 2 pi/omega simulated and discarded first (0 to {}, a whole number); "
                              "while the motion does not repeat, the transient goes on, twice as long each time, "
                              "up to {} more times and {} periods in all (with --model: {} to {}, not prolonged)",
                              FindOrbitOptions::kMaxTransient, FindOrbitOptions{}.settle_rounds,
                              FindOrbitOptions::kMaxTransient, kMinModelTransients, kMaxModelTransients))
      ->type_name("N")
      ->capture_default_str();
  cmd->add_option("--max-multiple", args->max_multiple,
                  fmt::format("the largest period multiple k tried: the motion repeats after k forcing periods "
                              "(1 to {}, a whole number; with --model 1 to {}, the least k that is a period taken)",
                              FindOrbitOptions::kMaxMultiple, ModelFindOptions::kMaxMultiple))
      ->type_name("K")
      ->capture_default_str();
  cmd->add_option("--tolerance", args->tolerance,
                  "section points repeat when |X(t + kT) - X(t)|_inf <= tolerance (1 + |X(t)|_inf), dimensionless "
                  "(1e-12 to 0.01); also the antisymmetry test X(t + kT/2) = -X(t)")
      ->type_name("TOL")
      ->capture_default_str();
  cmd->add_option("--confirmations", args->confirmations,
                  "periods of k T over which the section must repeat (1 to 100, a whole number)")
      ->type_name("N")
      ->capture_default_str();
  cmd->add_option("--trace", args->trace,
                  "then trace from the found orbit in omega over LO,HI (which must hold its omega), as stickslip "
                  "trace does, into <results>/<output>/: the same files, the same report (with --model: in "
                  "--trace-parameter; printed, and written where --output is given)")
      ->type_name("LO,HI");
  cmd->add_option("--output", args->output, "the trace's directory under --results (a run name; with --trace), and "
                                            "the output of the run file --write-run writes");
  cmd->add_option("--write-run", args->write_run,
                  "also write a run file for stickslip run with the found orbit as its [start]; written whole or "
                  "not at all, checked before the work")
      ->type_name("FILE")
      ->each([args](const std::string&) { args->write_run_given = true; });
  cmd->add_option("--as", args->run_kind,
                  "the run file's kind: continue (one branch in omega upwards) or trace (both ways, through the "
                  "changes of type)")
      ->check(CLI::IsMember({"continue", "trace"}))
      ->capture_default_str();
  cmd->add_option("--range", args->range,
                  "the run file's range of omega (default --trace's, else 10% either side of the orbit's omega)")
      ->type_name("LO,HI");
  cmd->add_flag("--json", args->json,
                "print one JSON object: status, message, transient_periods, period_multiple, mismatch, "
                "closest_multiple, antisymmetric, signature (read off the motion) and orbit (as solve --json prints "
                "it, with unknowns and admissible; null unless Newton converged); not with --trace. With --model: "
                "status, message, signature and orbit (signature, parameters, period, phi, start, durations, "
                "margins, multipliers, stable, measures, verification), and with --trace the trace (parameter, "
                "start, completed, down, up: end, message, branches with every point)");
  cmd->add_flag("--force", args->force, kForceHelp);
  cmd->add_option("--model", args->model,
                  "find the orbit of the oscillator in this run file's [model] (see describe) instead of the paper's: "
                  "simulated from rest (or --set's start state by name, x1_0=..., v1_0=..., and phase phi=...) for "
                  "--transients periods (forcing periods; without forcing, periods of its slowest free oscillation), "
                  "its last period (the least of 1 to --max-multiple forcing periods that is one) read from a stop "
                  "(without forcing: between its last two sticks), solved and verified; takes --set NAME=VALUE over "
                  "the file's parameters, --transients, --max-multiple, --trace, --trace-parameter, --output, --results, "
                  "the steps (--ds, --ds-min, --ds-max, --max-points) and --json only")
      ->type_name("FILE");
  cmd->add_option("--trace-parameter", args->trace_parameter,
                  "with --model and --trace: the parameter traced (omega, F_k, F_s or v_b; default omega, or v_b "
                  "without forcing); the trace is printed (the branches, and with --json every point), and written with "
                  "--output")
      ->type_name("NAME");
  AddStepFlags(*cmd, &args->steps, ", of each branch (with --trace or --write-run)");
  return {cmd, [args, cmd] {
            CheckStepOptions(*args, *cmd);
            if (cmd->count("--model") != 0) return RunModelFindOf(*args, *cmd);
            if (cmd->count("--trace-parameter") != 0) {
              throw InvalidInput("trace-parameter", "'" + args->trace_parameter + "'", "with --model (the paper's "
                                 "model's --trace is in omega)");
            }
            return RunFind(*args);
          }};
}

}  // namespace stickslip::cli
