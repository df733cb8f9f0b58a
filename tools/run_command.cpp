// stickslip run / continue / check: continuation runs described by run files (or by flags), the
// bifurcation data files in results/, and regression checks against them.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "cli_common.hpp"
#include "commands.hpp"
#include "progress_line.hpp"
#include "start_options.hpp"
#include "stickslip/io/check.hpp"
#include "stickslip/io/command_options.hpp"
#include "stickslip/io/result_files.hpp"
#include "stickslip/io/run.hpp"

namespace stickslip::cli {

namespace {

struct Executed {
  OrbitBranch branch;
  StoredRun stored;
  double seconds = 0.0;  // wall time of the continuation, reported on stdout (not in the files)
};

// Runs one run file in memory. A start that does not converge is a failed run: exit code 3,
// nothing written.
std::optional<Executed> Execute(const RunFile& run, const std::filesystem::path& results) {
  OrbitContinuationSetup setup = MakeSetup(run, results);
  ProgressLineOptions line_options;
  line_options.value_name = run.parameter;
  ProgressLine line(run.output, line_options);
  setup.options.progress = line.Callback();
  const auto started = std::chrono::steady_clock::now();
  OrbitBranch branch = ContinueOrbit(setup);
  line.Clear();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  if (branch.branch.end == BranchEnd::kStartFailed) {
    fmt::print(stderr, "error: {}: {}\n", run.path, branch.branch.end_message);
    return std::nullopt;
  }
  StoredRun stored = RecordRun(run, branch);
  return Executed{std::move(branch), std::move(stored), seconds};
}

std::string Report(const RunFile& run, const Executed& e) {
  const OrbitBranch& b = e.branch;
  std::string special;
  for (const SpecialPoint& s : b.branch.special_points) {
    if (s.test_function == "start" || s.test_function == ToString(b.branch.end)) continue;
    special += fmt::format(" {}({}={:.10g})", s.type, run.parameter, s.lambda);
  }
  return fmt::format("{}: {} points in {:.3f} s; {}: {};{}", run.output, b.branch.points.size(), e.seconds,
                     ToString(b.branch.end), b.branch.end_message, special.empty() ? " no special points" : special);
}

// Writes the run's files and reports the run on stdout, and the files of the earlier run's directory
// that were kept (an export's b.<run> and s.<run>, files of the user's), so that none goes unseen.
void WriteAndReport(const RunFile& run, const Executed& e, const std::filesystem::path& results) {
  const std::vector<std::string> kept = WriteRunFiles(results, e.stored);
  fmt::print("{}\n", Report(run, e));
  if (!kept.empty()) {
    fmt::print("{}: kept {} other file(s) of {}: {}\n", run.output, kept.size(), (results / run.output).string(),
               fmt::join(kept, ", "));
  }
}

// CheckOutputDirectory, with a refused output placed at the run file's key 'output'.
void CheckRunOutput(const RunFile& run, const std::filesystem::path& results) {
  try {
    CheckOutputDirectory(results, run.output);
  } catch (const InvalidInput& e) {
    if (e.field() != "output") throw;
    throw RunFileError(fmt::format("{}: key 'output' {}", run.Location("output"), e.Predicate()), "output");
  }
}

struct RunArgs {
  std::vector<std::string> files;
  std::string results = "results";
};

int RunRuns(const RunArgs& args) {
  // Read and check every file first: a bad run file or output fails the command before anything
  // is computed or written.
  std::vector<RunFile> runs;
  for (const std::string& f : args.files) runs.push_back(ReadRunFile(f));
  for (const RunFile& run : runs) CheckRunOutput(run, args.results);
  // Two run files with one output: the second would replace the first's results unseen.
  for (std::size_t i = 1; i < runs.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (runs[j].output != runs[i].output) continue;
      throw RunFileError(fmt::format("{}: key 'output' = '{}' is invalid: valid an output no other run file of the "
                                     "command has ({} has it too)",
                                     runs[i].Location("output"), runs[i].output, runs[j].path),
                         "output");
    }
  }
  int code = kExitOk;
  for (const RunFile& run : runs) {
    std::optional<Executed> e = Execute(run, args.results);
    if (!e) {
      code = kExitNoConvergence;
      continue;
    }
    WriteAndReport(run, *e, args.results);
  }
  return code;
}

struct CheckArgs {
  std::vector<std::string> files;
  std::string results = "results";
};

int RunCheck(const CheckArgs& args) {
  // Every run file and stored run is read first: a missing one fails before anything is computed.
  std::vector<std::pair<RunFile, StoredRun>> checks;
  for (const std::string& path : args.files) {
    RunFile run = ReadRunFile(path);
    StoredRun stored = ReadRunFiles(std::filesystem::path(args.results) / run.output);
    checks.emplace_back(std::move(run), std::move(stored));
  }
  int code = kExitOk;
  for (const auto& [run, stored] : checks) {
    std::optional<Executed> e = Execute(run, args.results);
    if (!e) return kExitNoConvergence;
    const std::vector<Difference> differences = CompareWithStored(e->stored, stored);
    if (differences.empty()) {
      fmt::print("check {}: ok ({} special points)\n", run.output, e->branch.branch.special_points.size());
      continue;
    }
    code = kExitFailure;
    fmt::print("check {}: {} difference(s)\n{:<20} {:<10} {:<24} {:>24} {:>24}\n", run.output, differences.size(),
               "file", "point", "column", "stored", "fresh");
    for (const Difference& d : differences) {
      fmt::print("{:<20} {:<10} {:<24} {:>24} {:>24}\n", d.file, d.row, d.column, d.stored, d.fresh);
    }
  }
  return code;
}

struct ContinueArgs {
  StartFlags start;
  RunFile run;
  std::string range;
  std::string direction = "up";
  std::vector<std::string> user_values;  // NAME=VALUE
  std::string detect_folds = "true";
  std::string detect_branch_points = "true";
  bool linear_solver_given = false;  // refused with --shooting single, where it would be ignored
};

// "true" or "false", as the run file's booleans.
bool ParseSwitch(const char* field, const std::string& text) {
  if (text != "true" && text != "false") throw InvalidInput(field, "'" + text + "'", "true, false");
  return text == "true";
}

// The run's directions and outputs: one run, or with --direction both the two runs
// <output>-down and <output>-up (as AUTO's and BifurcationKit's users run a branch both ways from
// one start, and as continuation-scripts/ names its pairs).
std::vector<std::pair<int, std::string>> Directions(const ContinueArgs& args) {
  const std::string& output = args.run.output;
  if (args.direction == "up") return {{1, output}};
  if (args.direction == "down") return {{-1, output}};
  if (args.direction == "both") return {{-1, output + "-down"}, {1, output + "-up"}};
  throw InvalidInput("direction", "'" + args.direction + "'", "up, down, both");
}

int RunContinue(ContinueArgs args) {
  RunFile& run = args.run;
  run.path = kOneOffRunPath;
  SetRunFileStart(ToStartInput(args.start), &run);
  const auto comma = args.range.find(',');
  if (comma == std::string::npos) throw InvalidInput("range", "'" + args.range + "'", "MIN,MAX");
  run.range_min = ParseNumber("range", args.range.substr(0, comma), "MIN,MAX with MIN < MAX");
  run.range_max = ParseNumber("range", args.range.substr(comma + 1), "MIN,MAX with MIN < MAX");
  CheckOneOffRun(run, args.range);
  CheckLinearSolverIsUsed(args.linear_solver_given ? run.linear_solver : "", run.shooting);
  for (const std::string& text : args.user_values) {
    const auto equals = text.find('=');
    if (equals == std::string::npos || equals == 0) throw InvalidInput("user-value", "'" + text + "'", "NAME=VALUE");
    const std::string name = text.substr(0, equals);
    run.user_values.emplace_back(name, ParseNumber("user-value", text.substr(equals + 1), "a finite number"));
  }
  run.detect_folds = ParseSwitch("detect-folds", args.detect_folds);
  run.detect_branch_points = ParseSwitch("detect-branch-points", args.detect_branch_points);
  // Every output is checked before anything is computed.
  const std::vector<std::pair<int, std::string>> directions = Directions(args);
  for (const auto& [direction, output] : directions) CheckOutputDirectory(args.start.results, output);
  for (const auto& [direction, output] : directions) {
    run.direction = direction;
    run.output = output;
    std::optional<Executed> e;
    try {
      e = Execute(run, args.start.results);
    } catch (const InvalidInput& error) {
      throw AsOption(error);
    }
    if (!e) return kExitNoConvergence;
    WriteAndReport(run, *e, args.start.results);
  }
  return kExitOk;
}

}  // namespace

Command AddRunCommand(CLI::App& app) {
  auto args = std::make_shared<RunArgs>();
  CLI::App* cmd = app.add_subcommand(
      "run", "Run continuation run files (TOML, see continuation-scripts/) and write results/<output>/: "
             "branch.csv, special-points.csv, summary.json. The main job.");
  cmd->add_option("files", args->files, "run files")->required();
  cmd->add_option("--results", args->results, "results directory")->capture_default_str();
  return {cmd, [args] { return RunRuns(*args); }};
}

Command AddCheckCommand(CLI::App& app) {
  auto args = std::make_shared<CheckArgs>();
  CLI::App* cmd = app.add_subcommand(
      "check", "Re-run run files and compare their special points (type, order, parameter to a relative "
               "1e-8, solution to 1e-7) and labelled branch points with the stored results; print the "
               "differences; exit 1 on any.");
  cmd->add_option("files", args->files, "run files")->required();
  cmd->add_option("--results", args->results, "results directory holding the stored runs")->capture_default_str();
  return {cmd, [args] { return RunCheck(*args); }};
}

Command AddContinueCommand(CLI::App& app) {
  auto args = std::make_shared<ContinueArgs>();
  CLI::App* cmd = app.add_subcommand("continue", "A one-off continuation run from flags (the keys of a run file).");
  AddStartOptions(*cmd, &args->start, StartOptions::kOrbit);
  cmd->add_option("--parameter", args->run.parameter, "continued variable (omega, u_r, u_s, chi, eta, ...)")->required();
  cmd->add_option("--direction", args->direction,
                  "up, down, or both: two runs from the one start, written to results/<output>-down and "
                  "results/<output>-up (each a run of its own, to restart from, check and export)")
      ->type_name("up|down|both")
      ->capture_default_str();
  cmd->add_option("--range", args->range, "MIN,MAX of the parameter")->type_name("MIN,MAX")->required();
  AddNumberOption(*cmd, "--ds", &args->run.ds, "0 < ds-min <= ds <= ds-max", "initial arclength step (> 0)");
  AddNumberOption(*cmd, "--ds-min", &args->run.ds_min, "0 < ds-min <= ds <= ds-max", "smallest step (> 0)");
  AddNumberOption(*cmd, "--ds-max", &args->run.ds_max, "0 < ds-min <= ds <= ds-max", "largest step");
  AddCountOption(*cmd, "--max-points", &args->run.max_points, 1, kMaxRunPoints, "accepted points (1 to 1e6)");
  cmd->add_option("--user-value", args->user_values,
                  "report a UZ point where the variable NAME (the parameter or another unknown) passes VALUE; "
                  "repeatable (the run file's user_values and user_values_of)")
      ->type_name("NAME=VALUE");
  cmd->add_option("--shooting", args->run.shooting,
                  "single (dense), multiple (block-sparse), or auto (single up to 6 listed segments)")
      ->check(CLI::IsMember({"auto", "single", "multiple"}))
      ->capture_default_str();
  cmd->add_option("--linear-solver", args->run.linear_solver,
                  "sparse solver for multiple shooting (with --shooting multiple or auto; refused with single)")
      ->check(CLI::IsMember({"klu", "umfpack", "dense"}))
      ->capture_default_str()
      ->each([args](const std::string&) { args->linear_solver_given = true; });
  cmd->add_option("--detect-folds", args->detect_folds, "locate folds (LP): true or false")
      ->type_name("true|false")
      ->capture_default_str();
  cmd->add_option("--detect-branch-points", args->detect_branch_points, "locate branch points (BP): true or false")
      ->type_name("true|false")
      ->capture_default_str();
  cmd->add_flag("--continue-past-type-changes", args->run.continue_past_type_changes,
                "go on past orbit-type changes, flagging the points beyond inadmissible");
  cmd->add_option("--output", args->run.output, "results/<output>/")->required();
  cmd->add_option("--results", args->start.results, "results directory: where --point is read and <output>/ written")
      ->capture_default_str();
  return {cmd, [args] { return RunContinue(*args); }};
}

}  // namespace stickslip::cli
