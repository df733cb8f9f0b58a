// Internal to io/: a trace's directory as a part of a larger result (an atlas's trace-<t>/, io/
// atlas_files.hpp), written and owned as WriteTraceFiles writes and owns a trace's own.
#pragma once

#include <filesystem>

#include "result_directory.hpp"
#include "stickslip/io/trace_files.hpp"

namespace stickslip::detail {

// The entries of a trace's directory that a trace writes (relative to it): trace.csv, trace.json,
// branch-<k>/ and branch-<k>-<label>/ with their run files.
OwnedEntry TraceEntries();
// The entries of the trace's directory `directory` as it stands that its trace wrote: those files,
// and only the branches its trace.json lists (a user's "branch-9/" is the user's).
OwnedEntry TraceEntriesBefore(const std::filesystem::path& directory);

// The trace's files, written into `directory` (which exists).
void WriteTraceInto(const std::filesystem::path& directory, const StoredTrace& trace);

}  // namespace stickslip::detail
