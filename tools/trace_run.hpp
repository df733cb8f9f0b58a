// A trace run (branches/trace.hpp) from a run file with a [trace] table, for `trace`, `run` and
// `check`: computed in memory, then written to results/<output>/ (io/trace_files.hpp).
#pragma once

#include <filesystem>
#include <optional>

#include "stickslip/branches/trace.hpp"
#include "stickslip/io/trace_files.hpp"

#include "cli_common.hpp"

namespace stickslip::cli {

// A trace computed in memory, or the exit code of one that traced nothing (nothing to write then):
// kExitNotAMotion when the start is not a motion (and the trace does not allow it),
// kExitNoConvergence when no branch started.
struct TraceRun {
  std::optional<StoredTrace> stored;  // nullopt: nothing traced
  double seconds = 0.0;               // wall time, reported on stdout (not in the files)
  int exit_code = kExitOk;            // of a trace that traced nothing
};

// The trace of `run` (run.trace set), from a [model]'s label (MakeModelSetup) or of the paper's
// oscillator; when nothing was traced, with the reason on stderr.
TraceRun ExecuteTrace(const RunFile& run, const std::filesystem::path& results);

// Writes the trace's files (any model's, io/trace_files.hpp) and reports it on stdout, `seconds`
// its wall time. Returns kExitOk when both directions ran to their ends, whatever those were (a
// bound, a loop, a resonance, a change of type that switched nowhere, ...: results, written and
// printed), kExitNoConvergence when a branch failed to converge, with the reason on stderr.
int WriteAndReportTrace(const StoredTrace& trace, double seconds, const std::filesystem::path& results);

}  // namespace stickslip::cli
