// stickslip run / continue / check: continuation runs described by run files (or by flags), the
// bifurcation data files in results/, and regression checks against them.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "cli_common.hpp"
#include "commands.hpp"
#include "continue_flags.hpp"
#include "trace_run.hpp"
#include "progress_line.hpp"
#include "start_options.hpp"
#include "stickslip/io/check.hpp"
#include "stickslip/io/command_options.hpp"
#include "stickslip/io/model_restart.hpp"
#include "stickslip/io/result_files.hpp"
#include "stickslip/io/run.hpp"

namespace stickslip::cli {

namespace {

struct Executed {
  Branch branch;
  StoredRun stored;
  double seconds = 0.0;  // wall time of the continuation, reported on stdout (not in the files)
};

// Continues `setup` (either model's) with a progress line and records the branch (`record`). A start
// that does not converge is a failed run: exit code 3, nothing written; one outside the range is
// refused (exit 2, nothing written).
template <typename Setup, typename Record>
std::optional<Executed> ContinueAndRecord(const RunFile& run, Setup setup, const Record& record) {
  ProgressLineOptions line_options;
  line_options.value_name = run.parameter;
  ProgressLine line(run.output, line_options);
  setup.options.progress = line.Callback();
  const auto started = std::chrono::steady_clock::now();
  auto branch = ContinueOrbit(setup);
  line.Clear();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  if (branch.branch.end == BranchEnd::kStartFailed) {
    fmt::print(stderr, "error: {}: {}\n", RunInMessages(run), branch.branch.end_message);
    return std::nullopt;
  }
  CheckRangeHoldsFirstPoint(run, branch.branch);
  StoredRun stored = record(branch);
  return Executed{std::move(branch.branch), std::move(stored), seconds};
}

// Runs one run file in memory: from a [model]'s label (MakeModelSetup), or the paper's oscillator.
std::optional<Executed> Execute(const RunFile& run, const std::filesystem::path& results) {
  if (std::optional<ModelRunSetup> model = MakeModelSetup(run, results)) {
    return ContinueAndRecord(run, model->setup,
                             [&](const BasicOrbitBranch<DynamicLinearOscillator>& b) { return model->Recorded(run, b); });
  }
  return ContinueAndRecord(run, MakeSetup(run, results), [&](const OrbitBranch& b) { return RecordRun(run, b); });
}

std::string Report(const RunFile& run, const Executed& e) {
  const Branch& b = e.branch;
  std::string special;
  for (const SpecialPoint& s : b.special_points) {
    if (s.test_function == "start" || s.test_function == ToString(b.end)) continue;
    special += fmt::format(" {}({}={:.10g})", s.type, run.parameter, s.lambda);
  }
  return fmt::format("{}: {} points in {:.3f} s; {}: {};{}", run.output, b.points.size(), e.seconds, ToString(b.end),
                     b.end_message, special.empty() ? " no special points" : special);
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

// A written run's exit code: kExitNoConvergence where the corrector failed before the branch's end
// (its points are written, as a trace's failed branch's are, and the code says so as the trace's
// does), kExitOk otherwise.
int ExitCodeOf(const Branch& branch) { return branch.end == BranchEnd::kStepTooSmall ? kExitNoConvergence : kExitOk; }

// CheckOutputDirectory, with a refused output placed at the run file's key 'output'.
void CheckRunOutput(const RunFile& run, const std::filesystem::path& results) {
  try {
    if (run.trace) {
      CheckTraceOutputDirectory(results, run.output);
    } else {
      CheckOutputDirectory(results, run.output);
    }
  } catch (const InvalidInput& e) {
    if (e.field() != "output") throw;
    throw RunFileError(fmt::format("{}: key 'output' {}", run.Location("output"), e.Predicate()), "output");
  }
}

// For each run, the run of the command whose output it restarts from (none for a restart from
// earlier results, or from its own). A trace's output holds no labels of its own (its branches'
// are under <output>/branch-<k>/), so a restart from a trace of the command could never start:
// refused before anything runs.
std::vector<std::optional<std::size_t>> SourcesOf(const std::vector<RunFile>& runs) {
  std::vector<std::optional<std::size_t>> sources(runs.size());
  for (std::size_t i = 0; i < runs.size(); ++i) {
    for (std::size_t j = 0; j < runs.size(); ++j) {
      if (j == i || runs[j].output != runs[i].restart_run) continue;
      if (runs[j].trace) {
        throw RunFileError(fmt::format("{}: key 'start.restart.run' = '{}' is invalid: valid a run that is no trace ({} "
                                       "is one; restart from one of its branches with --results <results>/{})",
                                       runs[i].Location("start.restart.run"), runs[i].restart_run, runs[j].path,
                                       runs[j].output),
                           "start.restart.run");
      }
      sources[i] = j;
    }
  }
  return sources;
}

// Refuses runs that restart from one another in a cycle, naming one on the cycle and the cycle:
// from any run left unordered, its sources are unordered too, and following them repeats a run
// within as many steps as there are runs.
[[noreturn]] void RefuseCycle(const std::vector<RunFile>& runs, const std::vector<std::optional<std::size_t>>& sources,
                              std::size_t unordered) {
  std::vector<bool> seen(runs.size(), false);
  std::size_t i = unordered;
  for (; !seen[i]; i = *sources[i]) seen[i] = true;
  std::string cycle = runs[i].output;
  for (std::size_t j = *sources[i]; j != i; j = *sources[j]) cycle += " restarts from " + runs[j].output + ", which";
  throw RunFileError(fmt::format("{}: key 'start.restart.run' = '{}' is invalid: valid a run that does not restart "
                                 "from this one through the command's other run files ({} restarts from {})",
                                 runs[i].Location("start.restart.run"), runs[i].restart_run, cycle, runs[i].output),
                     "start.restart.run");
}

// The runs in the order given, except that a run restarting from another run of the command comes
// after it: `run continuation-scripts/*.toml` goes by name, and a restart read before its source
// is written again would start from that source's earlier results. Runs that restart from one
// another in a cycle are refused (their results would depend on which ran first).
std::vector<RunFile> SourcesFirst(const std::vector<RunFile>& runs) {
  const std::vector<std::optional<std::size_t>> sources = SourcesOf(runs);
  std::vector<RunFile> ordered;
  std::vector<bool> placed(runs.size(), false);
  auto ready = [&](std::size_t i) { return !placed[i] && (!sources[i] || placed[*sources[i]]); };
  while (ordered.size() < runs.size()) {  // each pass places one run
    std::size_t i = 0;
    while (i < runs.size() && !ready(i)) ++i;
    if (i == runs.size()) RefuseCycle(runs, sources, std::find(placed.begin(), placed.end(), false) - placed.begin());
    ordered.push_back(runs[i]);
    placed[i] = true;
  }
  return ordered;
}

// Each run's setup built once before any run is computed, so that its input (a label that is not
// there, a range that misses the start, a start fault) is refused before anything is written. A run
// that restarts from a run of this command can be set up only once that run is written.
void CheckSetups(const std::vector<RunFile>& runs, const std::filesystem::path& results) {
  const std::vector<std::optional<std::size_t>> sources = SourcesOf(runs);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (!sources[i] && !MakeModelSetup(runs[i], results)) MakeSetup(runs[i], results);
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
  const std::vector<RunFile> ordered = SourcesFirst(runs);
  CheckSetups(runs, args.results);
  int code = kExitOk;
  // A run that restarts from one this command failed to write is not run: it would start from
  // that run's earlier results.
  std::set<std::string> unwritten;
  for (const RunFile& run : ordered) {
    if (unwritten.contains(run.restart_run)) {
      fmt::print(stderr, "error: {}: not run: it restarts from '{}', which this command did not write\n", run.path,
                 run.restart_run);
      unwritten.insert(run.output);
      code = kExitNoConvergence;
      continue;
    }
    if (run.trace) {
      const TraceRun trace = ExecuteTrace(run, args.results);
      const int traced = trace.stored ? WriteAndReportTrace(*trace.stored, trace.seconds, args.results) : trace.exit_code;
      if (!trace.stored) unwritten.insert(run.output);
      if (code == kExitOk) code = traced;
      continue;
    }
    std::optional<Executed> e = Execute(run, args.results);
    if (!e) {
      unwritten.insert(run.output);
      code = kExitNoConvergence;
      continue;
    }
    WriteAndReport(run, *e, args.results);
    if (code == kExitOk) code = ExitCodeOf(e->branch);
  }
  return code;
}

struct CheckArgs {
  std::vector<std::string> files;
  std::string results = "results";
};

// Prints the differences of one run (or one branch of a trace) under `name`; true if none.
bool ReportDifferences(const std::string& name, const std::vector<Difference>& differences, std::size_t special) {
  if (differences.empty()) {
    fmt::print("check {}: ok ({} special points)\n", name, special);
    return true;
  }
  fmt::print("check {}: {} difference(s)\n{:<20} {:<10} {:<24} {:>24} {:>24}\n", name, differences.size(), "file",
             "point", "column", "stored", "fresh");
  for (const Difference& d : differences) {
    fmt::print("{:<20} {:<10} {:<24} {:>24} {:>24}\n", d.file, d.row, d.column, d.stored, d.fresh);
  }
  return false;
}

// A trace against its stored files: the same chain (each branch's signature, start and end, each
// direction's end), and every branch as `check` compares a run.
bool CheckTrace(const RunFile& run, const StoredTrace& stored, const StoredTrace& fresh) {
  std::vector<Difference> chain;
  auto compare = [&](const std::string& row, const std::string& column, const std::string& a, const std::string& b) {
    if (a != b) chain.push_back({"trace.json", row, column, a, b});
  };
  for (std::size_t k = 0; k < 2; ++k) {
    compare(stored.directions[k].direction, "end", stored.directions[k].end, fresh.directions[k].end);
  }
  compare("trace", "branches", std::to_string(stored.branches.size()), std::to_string(fresh.branches.size()));
  bool ok = true;
  for (std::size_t k = 0; k < std::min(stored.branches.size(), fresh.branches.size()); ++k) {
    const StoredTraceBranch& a = stored.branches[k];
    const StoredTraceBranch& b = fresh.branches[k];
    compare(a.name, "signature", a.signature, b.signature);
    compare(a.name, "start", a.start, b.start);
    compare(a.name, "end", a.end, b.end);
    if (a.signature != b.signature) continue;
    ok = ReportDifferences(run.output + "/" + a.name, CompareWithStored(fresh.runs[k], stored.runs[k]),
                           fresh.runs[k].special_points.size()) && ok;
  }
  return ReportDifferences(run.output + "/trace.json", chain, 0) && ok;
}

int RunCheck(const CheckArgs& args) {
  // Every run file and stored run is read first: a missing one fails before anything is computed.
  struct Stored {
    RunFile run;
    std::optional<StoredRun> branch;
    std::optional<StoredTrace> trace;
  };
  std::vector<Stored> checks;
  for (const std::string& path : args.files) {
    RunFile run = ReadRunFile(path);
    const std::filesystem::path directory = std::filesystem::path(args.results) / run.output;
    if (run.trace) {
      StoredTrace trace = ReadTraceFiles(directory);
      checks.push_back({std::move(run), std::nullopt, std::move(trace)});
    } else {
      StoredRun stored = ReadRunFiles(directory);
      checks.push_back({std::move(run), std::move(stored), std::nullopt});
    }
  }
  int code = kExitOk;
  for (const Stored& c : checks) {
    if (c.trace) {
      const TraceRun fresh = ExecuteTrace(c.run, args.results);
      if (!fresh.stored) return fresh.exit_code;
      if (!CheckTrace(c.run, *c.trace, *fresh.stored)) code = kExitFailure;
      continue;
    }
    std::optional<Executed> e = Execute(c.run, args.results);
    if (!e) return kExitNoConvergence;
    if (!ReportDifferences(c.run.output, CompareWithStored(e->stored, *c.branch), e->branch.special_points.size())) {
      code = kExitFailure;
    }
  }
  return code;
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
  BuildOneOffRun(&args);
  // Every output is checked before anything is computed.
  const std::vector<std::pair<int, std::string>> directions = Directions(args);
  for (const auto& [direction, output] : directions) CheckOutputDirectory(args.start.results, output);
  // Both directions are computed before either is written: input refused on the second (a range
  // that misses the first point of the branch leaving a PD on that side) leaves nothing written.
  std::vector<std::pair<RunFile, std::optional<Executed>>> computed;
  for (const auto& [direction, output] : directions) {
    run.direction = direction;
    run.output = output;
    computed.emplace_back(run, Execute(run, args.start.results));
  }
  int code = kExitOk;
  for (const auto& [one, e] : computed) {
    if (!e) {
      code = kExitNoConvergence;
      continue;
    }
    WriteAndReport(one, *e, args.start.results);
    if (code == kExitOk) code = ExitCodeOf(e->branch);
  }
  return code;
}

}  // namespace

Command AddRunCommand(CLI::App& app) {
  auto args = std::make_shared<RunArgs>();
  CLI::App* cmd = app.add_subcommand(
      "run", "Run continuation run files (TOML, see continuation-scripts/) and write results/<output>/: "
             "branch.csv, special-points.csv, summary.json; or, for a run file with a [trace] table, the trace "
             "(branch-<k>/, trace.csv, trace.json; exit codes as trace's: 0 whatever the ends, 4 when the start is not "
             "a motion and trace.allow_inadmissible is not set). The files run in the order given, except that one "
             "whose start.restart names another's output runs after it. The main job.");
  cmd->add_option("files", args->files, "run files")->required();
  cmd->add_option("--results", args->results, "results directory")->capture_default_str();
  return {cmd, [args] { return RunRuns(*args); }};
}

Command AddCheckCommand(CLI::App& app) {
  auto args = std::make_shared<CheckArgs>();
  CLI::App* cmd = app.add_subcommand(
      "check", "Re-run run files and compare their special points (type, order, parameter to a relative "
               "1e-8, solution to 1e-7) and labelled branch points with the stored results; print the "
               "differences; exit 1 on any. A trace's run file: the chain (each branch's signature, start and end, "
               "each direction's end) and every branch.");
  cmd->add_option("files", args->files, "run files")->required();
  cmd->add_option("--results", args->results, "results directory holding the stored runs")->capture_default_str();
  return {cmd, [args] { return RunCheck(*args); }};
}

Command AddContinueCommand(CLI::App& app) {
  auto args = std::make_shared<ContinueArgs>();
  CLI::App* cmd = app.add_subcommand("continue", "A one-off continuation run from flags (the keys of a run file).");
  AddContinuationFlags(*cmd, args.get());
  AddRestartKindFlags(*cmd, args.get());
  cmd->add_option("--direction", args->direction,
                  "up, down, or both: two runs from the one start, written to results/<output>-down and "
                  "results/<output>-up (each a run of its own, to restart from, check and export)")
      ->type_name("up|down|both")
      ->capture_default_str();
  cmd->add_flag("--continue-past-type-changes", args->run.continue_past_type_changes,
                "go on past orbit-type changes, flagging the points beyond inadmissible");
  AddNumberOption(*cmd, "--max-amplitude", &args->run.max_amplitude, "a finite max-amplitude > 0",
                  "a resonance ends the branch at its first point where max |x1|, |x2| over the orbit (scaled "
                  "displacement, exact) passes this (> 0)");
  return {cmd, [args] { return RunContinue(*args); }};
}

}  // namespace stickslip::cli
