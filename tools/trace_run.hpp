// A trace run (branches/trace.hpp) from a run file with a [trace] table, for `trace`, `run` and
// `check`: computed in memory, then written to results/<output>/ (io/trace_files.hpp).
#pragma once

#include <filesystem>
#include <optional>

#include "stickslip/branches/trace.hpp"
#include "stickslip/io/trace_files.hpp"

namespace stickslip::cli {

struct TraceRun {
  TraceResult result;
  StoredTrace stored;
  double seconds = 0.0;  // wall time, reported on stdout (not in the files)
};

// The trace of `run` (run.trace set). nullopt, with the reason on stderr, when no branch started
// (exit code 3, nothing to write).
std::optional<TraceRun> ExecuteTrace(const RunFile& run, const std::filesystem::path& results);

// 0 when both directions ended at a bound, a loop, a resonance, max-points or max-branches; 3 when
// a branch failed to converge; kExitTraceUnswitched when a direction ended at a change of type
// that switched nowhere.
int TraceExitCode(const TraceResult& trace);

// Writes the trace's files and reports it on stdout; returns TraceExitCode, with the reasons of a
// non-zero code on stderr.
int WriteAndReportTrace(const RunFile& run, const TraceRun& trace, const std::filesystem::path& results);

}  // namespace stickslip::cli
