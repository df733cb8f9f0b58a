// stickslip trace: the chain of branches through the changes of orbit type, both ways from one
// start (branches/trace.hpp), from flags as `continue` takes them; written to results/<output>/
// (io/trace_files.hpp).
#include <chrono>
#include <cstdio>
#include <memory>

#include <fmt/format.h>

#include "cli_common.hpp"
#include "commands.hpp"
#include "continue_flags.hpp"
#include "number_text.hpp"
#include "progress_line.hpp"
#include "stickslip/io/command_options.hpp"
#include "stickslip/io/model_restart.hpp"
#include "stickslip/io/run.hpp"
#include "stickslip/io/run_fields.hpp"
#include "trace_run.hpp"

namespace stickslip::cli {

namespace {

// Traces `setup` (either model's) with a progress line and records the trace (`record`).
template <typename Setup, typename Record>
TraceRun TraceAndRecord(const RunFile& run, const Setup& setup, const Record& record) {
  TraceOptions options = *run.trace;
  ProgressLineOptions line_options;
  line_options.value_name = run.parameter;
  ProgressLine line(run.output, line_options);
  options.progress = line.Callback();
  const auto started = std::chrono::steady_clock::now();
  const auto result = TraceOrbits(setup, options);
  line.Clear();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  if (!result.HasBranches()) {
    fmt::print(stderr, "error: {}: {}\n", RunInMessages(run), result.down.message);
    return TraceRun{.exit_code = result.NotAMotion() ? kExitNotAMotion : kExitNoConvergence};
  }
  return TraceRun{.stored = record(result), .seconds = seconds};
}

}  // namespace

TraceRun ExecuteTrace(const RunFile& run, const std::filesystem::path& results) {
  if (const std::optional<ModelRunSetup> model = MakeModelSetup(run, results)) {
    return TraceAndRecord(
        run, model->setup,
        [&](const BasicTraceResult<DynamicLinearOscillator>& trace) { return model->Recorded(run, trace); });
  }
  return TraceAndRecord(
      run, MakeSetup(run, results), [&](const TraceResult& trace) { return RecordTrace(run, trace); });
}

int WriteAndReportTrace(const StoredTrace& trace, double seconds, const std::filesystem::path& results) {
  const std::vector<std::string> kept = WriteTraceFiles(results, trace);
  fmt::print("{}: {} branches in {:.3f} s\n", trace.output, trace.branches.size(), seconds);
  for (const StoredTraceBranch& b : trace.branches) {
    fmt::print("  {} ({} chain) '{}' {} from {}{}: {} points, {}\n", b.name, b.chain, b.signature, b.direction, b.start,
               b.margin.empty() ? "" : " at " + b.margin, b.points, b.end);
  }
  for (const StoredTraceDirection& d : trace.directions) {
    // A resonance's message names it already ("resonance: the amplitude ...").
    fmt::print("  {}: {}\n", d.direction, d.message.starts_with(d.end + ":") ? d.message : d.end + ": " + d.message);
  }
  if (!kept.empty()) {
    fmt::print("{}: kept {} other file(s) of {}: {}\n", trace.output, kept.size(), (results / trace.output).string(),
               fmt::join(kept, ", "));
  }
  int code = kExitOk;
  for (const StoredTraceDirection& d : trace.directions) {
    if (d.end != ToString(TraceEnd::kContinuationFailed)) continue;
    fmt::print(stderr, "{}: the {} chain failed: {}\n", trace.output, d.direction, d.message);
    code = kExitNoConvergence;
  }
  return code;
}

namespace {

struct TraceArgs {
  ContinueArgs continuation;
  TraceOptions options;
};

int RunTrace(TraceArgs args) {
  try {
    args.options.Validate();
  } catch (const InvalidInput& e) {  // named as the options are: trace.max_amplitude is --max-amplitude
    throw e.Renamed(OptionOfKey("trace." + e.field()));
  }
  args.continuation.run.trace = args.options;  // first: the run's checks know it is a trace
  BuildOneOffRun(&args.continuation);
  const RunFile& run = args.continuation.run;
  CheckTraceOutputDirectory(args.continuation.start.results, run.output);
  const TraceRun trace = ExecuteTrace(run, args.continuation.start.results);
  if (!trace.stored) return trace.exit_code;
  return WriteAndReportTrace(*trace.stored, trace.seconds, args.continuation.start.results);
}

}  // namespace

Command AddTraceCommand(CLI::App& app) {
  auto args = std::make_shared<TraceArgs>();
  CLI::App* cmd = app.add_subcommand(
      "trace",
      "Follow the chain of orbit branches through every change of orbit type, both ways from the start, "
      "within --range: at each change the adjacent types are tried and the one confirmed by simulation is "
      "continued. Writes results/<output>/: branch-<k>/ (an ordinary run per branch), trace.csv and trace.json. "
      "Exit 0 when both directions ran to their ends, whatever those were (a range bound, the family's end, a loop, "
      "a resonance, a change of type that switched nowhere, --max-points, --max-branches: written and printed); "
      "3 when a branch does not converge; 4 when the start is not a motion of the system (a margin < 0; nothing "
      "written; --allow-inadmissible traces it).");
  AddContinuationFlags(*cmd, &args->continuation);
  AddCountOption(*cmd, "--max-branches", &args->options.max_branches, 1, kMaxTraceBranches,
                 fmt::format("branches per direction (1 to {})", kMaxTraceBranches));
  AddNumberOption(*cmd, "--max-amplitude", &args->options.max_amplitude, "a finite max-amplitude > 0",
                  "a resonance ends the direction where max |x1|, |x2| over the orbit (scaled displacement, "
                  "exact) passes this (> 0)");
  AddNumberOption(*cmd, "--loop-tolerance", &args->options.loop_tolerance, "0 < loop-tolerance <= 1e-2",
                  "the chain has come back to a point it visited when the signature agrees and the parameter "
                  "(relative), start state, phase and period differ by at most this (0 < tol <= 1e-2)");
  AddCountOption(*cmd, "--follow-bifurcations", &args->options.follow_bifurcations, 0, kMaxTraceBranches,
                 fmt::format("branches met at BP, PD and SB to follow, in the order met, each as one branch into "
                             "branch-<k>-<label>/ (0 to {}); the others are recorded in trace.json only",
                             kMaxTraceBranches));
  cmd->add_flag("--follow-past-unswitched", args->options.follow_past_unswitched,
                "at a change of type that switches nowhere, follow the same type on past it (not a motion there, "
                "admissible = 0) to where it is admissible again, instead of ending the direction");
  cmd->add_flag("--allow-inadmissible", args->options.allow_inadmissible,
                "trace from a start that is not a motion of the system (a margin < 0 there: admissible = 0) "
                "instead of refusing it (exit 4)");
  return {cmd, [args] { return RunTrace(*args); }};
}

}  // namespace stickslip::cli
