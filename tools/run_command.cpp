// stickslip run / continue / check: continuation runs described by run files (or by flags), the
// bifurcation data files in results/, and regression checks against them.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <unistd.h>

#include "cli_common.hpp"
#include "commands.hpp"
#include "stickslip/io/check.hpp"
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
  OrbitContinuationSetup setup = [&] {
    try {
      return MakeSetup(run, results);
    } catch (const RunFileError& e) {
      throw InputError(e.what());
    }
  }();
  const bool terminal = ::isatty(STDERR_FILENO) == 1;
  const auto started = std::chrono::steady_clock::now();
  OrbitBranch branch = ContinueOrbit(setup, [&](const Branch& b) {
    if (!terminal) return;
    const BranchPoint& p = b.points.back();
    fmt::print(stderr, "\r{}: {} points, {} = {:.10g}, ds = {:.2e}   ", run.output, b.points.size(),
               run.parameter, p.lambda, p.ds);
  });
  if (terminal) fmt::print(stderr, "\r\033[K");
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

RunFile Read(const std::string& path) {
  try {
    return ReadRunFile(path);
  } catch (const RunFileError& e) {
    throw InputError(e.what());
  }
}

struct RunArgs {
  std::vector<std::string> files;
  std::string results = "results";
};

int RunRuns(const RunArgs& args) {
  // Read every file first: a bad run file fails the command before anything is written.
  std::vector<RunFile> runs;
  for (const std::string& f : args.files) runs.push_back(Read(f));
  int code = kExitOk;
  for (const RunFile& run : runs) {
    std::optional<Executed> e = Execute(run, args.results);
    if (!e) {
      code = kExitNoConvergence;
      continue;
    }
    WriteRunFiles(args.results, e->stored);
    fmt::print("{}\n", Report(run, *e));
  }
  return code;
}

struct CheckArgs {
  std::vector<std::string> files;
  std::string results = "results";
};

int RunCheck(const CheckArgs& args) {
  int code = kExitOk;
  for (const std::string& path : args.files) {
    const RunFile run = Read(path);
    std::optional<Executed> e = Execute(run, args.results);
    if (!e) return kExitNoConvergence;
    const std::vector<Difference> differences =
        CompareWithStored(e->stored, ReadRunFiles(std::filesystem::path(args.results) / run.output));
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
  std::string preset;
  std::string signature;
  std::vector<std::string> set;
  std::vector<std::string> guess;
  RunFile run;
  std::string range;
  std::string direction = "up";
  std::string results = "results";
};

NamedValues Assignments(const std::vector<std::string>& texts, const char* option) {
  NamedValues values;
  for (const std::string& t : texts) {
    const auto equals = t.find('=');
    if (equals == std::string::npos) throw InputError(fmt::format("{} '{}' is not NAME=VALUE", option, t));
    values.emplace_back(t.substr(0, equals), ParseNumber(t.substr(0, equals), t.substr(equals + 1), "any finite number"));
  }
  return values;
}

int RunContinue(ContinueArgs args) {
  RunFile& run = args.run;
  run.path = "(command line)";
  run.preset = args.preset;
  run.signature = args.signature;
  run.set = Assignments(args.set, "--set");
  run.guess = Assignments(args.guess, "--guess");
  if (args.direction != "up" && args.direction != "down") {
    throw InputError(fmt::format("direction = '{}' is invalid: valid up, down", args.direction));
  }
  run.direction = args.direction == "up" ? 1 : -1;
  const auto comma = args.range.find(',');
  if (comma == std::string::npos) throw InputError(fmt::format("range = '{}' is invalid: valid MIN,MAX", args.range));
  run.range_min = ParseNumber("range", args.range.substr(0, comma), "MIN,MAX with MIN < MAX");
  run.range_max = ParseNumber("range", args.range.substr(comma + 1), "MIN,MAX with MIN < MAX");
  if (!(run.range_min < run.range_max)) throw InputError(fmt::format("range = '{}' is invalid: valid MIN,MAX with MIN < MAX", args.range));
  if (!(run.ds_min > 0 && run.ds_min <= run.ds && run.ds <= run.ds_max)) {
    throw InputError(fmt::format("ds = {} is invalid: valid 0 < ds-min ({}) <= ds <= ds-max ({})", run.ds, run.ds_min, run.ds_max));
  }
  if (run.preset.empty() == run.signature.empty()) throw InputError("preset/signature: give exactly one of --preset or --signature");
  if (run.max_points < 1 || run.max_points > 1000000) {
    throw InputError(fmt::format("max-points = {} is invalid: valid range 1 <= max-points <= 1000000", run.max_points));
  }
  if (!IsRunName(run.output)) {
    throw InputError(fmt::format("output = '{}' is invalid: valid {}", run.output, kRunNameRule));
  }
  std::optional<Executed> e = Execute(run, args.results);
  if (!e) return kExitNoConvergence;
  WriteRunFiles(args.results, e->stored);
  fmt::print("{}\n", Report(run, *e));
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
  cmd->add_option("--preset", args->preset, "paper-4.1, paper-4.2, paper-5.1, paper-5.2, paper-6");
  cmd->add_option("--signature", args->signature, "orbit type, as for solve");
  cmd->add_option("--set", args->set, "model data and start: chi, eta, omega, u_s, u_r, x10, x20, v10, phi")->type_name("KEY=VALUE");
  cmd->add_option("--guess", args->guess, "any orbit variable (d1..dn too)")->type_name("NAME=VALUE");
  cmd->add_option("--free", args->run.free, "released variable")->type_name("NAME");
  cmd->add_option("--fix", args->run.fix, "held variable")->type_name("NAME");
  cmd->add_flag("--tie-u_r", args->run.tie_u_r, "hold u_r = u_s");
  cmd->add_option("--parameter", args->run.parameter, "continued variable (omega, u_r, u_s, chi, eta, ...)")->required();
  cmd->add_option("--direction", args->direction, "up or down")->capture_default_str();
  cmd->add_option("--range", args->range, "MIN,MAX of the parameter")->required();
  cmd->add_option("--ds", args->run.ds, "initial arclength step (> 0)")->capture_default_str();
  cmd->add_option("--ds-min", args->run.ds_min, "smallest step (> 0)")->capture_default_str();
  cmd->add_option("--ds-max", args->run.ds_max, "largest step")->capture_default_str();
  cmd->add_option("--max-points", args->run.max_points, "accepted points (1 to 1e6)")->capture_default_str();
  cmd->add_flag("--continue-past-type-changes", args->run.continue_past_type_changes,
                "go on past orbit-type changes, flagging the points beyond inadmissible");
  cmd->add_option("--output", args->run.output, "results/<output>/")->required();
  cmd->add_option("--results", args->results, "results directory")->capture_default_str();
  return {cmd, [args] { return RunContinue(*args); }};
}

}  // namespace stickslip::cli
