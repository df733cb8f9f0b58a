// stickslip find: from a simulated motion to its exact periodic orbit (analysis/orbit_finder.hpp):
// the detected period and orbit type, the solved orbit as solve prints it, and the solve command
// line (or a run file) that reproduces it.
#include <cmath>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "cli_common.hpp"
#include "commands.hpp"
#include "orbit_report.hpp"
#include "progress_line.hpp"
#include "start_options.hpp"
#include "stickslip/analysis/orbit_finder.hpp"
#include "stickslip/io/atomic_file.hpp"
#include "stickslip/io/command_options.hpp"
#include "stickslip/io/output_marker.hpp"
#include "stickslip/io/run_file.hpp"

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
  bool force = false;
};

std::string Number(double x) {
  std::string text = fmt::format("{}", x);
  if (text.find_first_of(".en") == std::string::npos) text += ".0";  // a TOML float, and plain to read
  return text;
}

// Six significant digits, for a range to edit.
std::string Rounded(double x) { return Number(std::stod(fmt::format("{:.6g}", x))); }

// The solve command line of a start (StartInputOf): signature, set, guess, free, tie.
std::string SolveCommandLine(const StartInput& start) {
  std::string line = fmt::format("stickslip solve --signature \"{}\"", start.signature);
  for (const auto& [name, value] : start.set) line += fmt::format(" --set {}={}", name, Number(value));
  for (const auto& [name, value] : start.guess) line += fmt::format(" --guess {}={}", name, Number(value));
  for (const std::string& name : start.free) line += " --free " + name;
  if (start.tie_u_r) line += " --tie-u_r";
  return line;
}

// The first line of the run file find writes: the mark of a file that find may replace (a committed
// run file, the user's, has none).
constexpr std::string_view kRunFileMarker = "# written by stickslip find: the orbit it found, as a start";

// A run file `stickslip run` takes: the start, and a continuation in omega over 10% on either
// side, upwards, for the user to edit.
std::string RunFileText(const StartInput& start, const std::filesystem::path& path) {
  const std::string stem = path.stem().string();
  const std::string output = IsRunName(stem) ? stem : "found-orbit";
  auto table = [](const NamedValues& values) {
    std::string text;
    for (const auto& [name, value] : values) text += fmt::format("{}{} = {}", text.empty() ? "" : ", ", name, Number(value));
    return "{ " + text + " }";
  };
  double omega = 0.0;
  for (const auto& [name, value] : start.set) {
    if (name == "omega") omega = value;
  }
  std::string text = fmt::format("{}\noutput = \"{}\"\n", kRunFileMarker, output);
  text += fmt::format("[start]\nsignature = \"{}\"\nset = {}\nguess = {}\n", start.signature, table(start.set),
                      table(start.guess));
  text += "[unknowns]\nfree = [";
  for (std::size_t i = 0; i < start.free.size(); ++i) text += fmt::format("{}\"{}\"", i == 0 ? "" : ", ", start.free[i]);
  text += fmt::format("]\ntie_u_r = {}\n", start.tie_u_r);
  text += fmt::format("[continuation]                         # edit: the parameter, direction and range\n"
                      "parameter = \"omega\"\ndirection = \"up\"\nrange = [{}, {}]\n",
                      Rounded(std::max(kMinOmega, 0.9 * omega)), Rounded(std::min(kMaxOmega, 1.1 * omega)));
  return text;
}

int ExitCode(FindOrbitStatus status) {
  switch (status) {
    case FindOrbitStatus::kFound: return kExitOk;
    case FindOrbitStatus::kNotPeriodic:
    case FindOrbitStatus::kNoOrbitType: return kExitNotPeriodic;
    case FindOrbitStatus::kSimulationIncomplete: return kExitFailure;
    case FindOrbitStatus::kSolveFailed: return kExitNoConvergence;
    case FindOrbitStatus::kNotAMotion: break;
  }
  return kExitNotAMotion;
}

int RunFind(const FindArgs& args) {
  if (args.write_run_given) {
    const OutputMarker marker{"stickslip find", [](std::string_view line) { return line == kRunFileMarker; }};
    CheckReplaceableOutputFile(args.write_run, "write-run", marker, args.force);
  }
  const ModelStart input = BuildModelStart(ToStartInput(args.start));
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
  if (found.period_multiple > 0) {
    fmt::print("motion     periodic after {} transient period(s): k = {} forcing period(s), section mismatch {:.3g}{}\n",
               found.transient_periods, found.period_multiple, found.mismatch,
               found.antisymmetric ? fmt::format(", antisymmetric (mismatch {:.3g})", found.antisymmetry_mismatch) : "");
  }
  if (found.start) {
    fmt::print("origin     t = {} after the transient (a segment end)\n", found.origin_time);
  }
  if (found.solution && found.solution->summary.Converged()) {
    const StartInput solved = StartInputOf(found.solution->orbit);
    fmt::print("{}", OrbitReport(*found.solution, found.problem->free, found.problem->unknowns.tie_static_friction,
                                 ToString(options.solver.sparse_solver), found.margins, *found.verification));
    fmt::print("solve it again, or continue from it, with:\n  {}\n", SolveCommandLine(solved));
    if (args.write_run_given) {
      WriteFileAtomically(args.write_run, RunFileText(solved, args.write_run));
      fmt::print("run file   {} (stickslip run {})\n", args.write_run, args.write_run);
    }
  } else if (found.start) {
    fmt::print("the start read off the motion:\n  {}\n", SolveCommandLine(*found.start));
  }
  const int code = ExitCode(found.status);
  if (code != kExitOk) fmt::print(stderr, "error: {}\n", found.message);
  return code;
}

}  // namespace

Command AddFindCommand(CLI::App& app) {
  auto args = std::make_shared<FindArgs>();
  CLI::App* cmd = app.add_subcommand(
      "find",
      "Simulate from a start (as simulate does), detect the period of the motion on the stroboscopic section "
      "(t = n 2 pi/omega), read its orbit type, durations, phase and state off one period, solve the "
      "periodicity equations from there and verify the orbit by both simulators. Prints the orbit as solve "
      "does and the solve command line that gives it. Exit code 0 found and verified, 3 Newton did not "
      "converge, 4 the solution is not a motion or fails its verification, 5 the motion is not periodic "
      "within --max-multiple forcing periods (or has no stop or stick exit), 1 the simulation stopped early.");
  AddStartOptions(*cmd, &args->start, StartOptions::kMotion);
  cmd->add_option("--results", args->start.results, "where the runs of --point are stored")->capture_default_str();
  cmd->add_option("--transients", args->transients,
                  fmt::format("forcing periods 2 pi/omega simulated and discarded first (0 to {}, a whole number); "
                              "while the motion does not repeat, the transient goes on, twice as long each time, "
                              "up to {} more times and {} periods in all",
                              FindOrbitOptions::kMaxTransient, FindOrbitOptions{}.settle_rounds,
                              FindOrbitOptions::kMaxTransient))
      ->type_name("N")
      ->capture_default_str();
  cmd->add_option("--max-multiple", args->max_multiple,
                  fmt::format("the largest period multiple k tried: the motion repeats after k forcing periods "
                              "(1 to {}, a whole number)",
                              FindOrbitOptions::kMaxMultiple))
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
  cmd->add_option("--write-run", args->write_run,
                  "also write a run file for stickslip run with the found orbit as its [start] (a continuation in "
                  "omega over +-10%, to edit); written whole or not at all, checked before the work")
      ->type_name("FILE")
      ->each([args](const std::string&) { args->write_run_given = true; });
  cmd->add_flag("--force", args->force, kForceHelp);
  return {cmd, [args] { return RunFind(*args); }};
}

}  // namespace stickslip::cli
