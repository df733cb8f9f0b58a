// Internal to io/: what the writers and readers of result directories share (result_files.cpp for
// a run, trace_files.cpp for a trace): reading a file whole, JSON read with messages naming the file
// and the key, and a directory replaced as a whole.
#pragma once

#include <filesystem>
#include <functional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "stickslip/invalid_input.hpp"

namespace stickslip::detail {

// The whole file; InvalidInput "cannot read '<path>'" if it is no readable regular file.
std::string ReadTextFile(const std::filesystem::path& path);

// "<file>: key '<key>' <what>", naming the key as the field.
InvalidInput KeyError(const std::filesystem::path& file, const std::string& key, const std::string& what);

// The JSON text, keys in their order; InvalidInput "<file>: invalid JSON: ..." naming the line and
// column, or "<file>: is invalid: valid a JSON object" for any other value.
nlohmann::ordered_json ParseJsonObject(const std::string& text, const std::filesystem::path& file);

// Whether `name` is `prefix` and a number (1 to 9 digits), with `labelled` optionally followed by
// '-' and a special point's label (capitals, then digits): the entries a writer owns among the
// user's ("curve-3" of a map; "branch-3" and "branch-3-PD2" of a trace, not "branch-notes.md").
bool IsNumberedName(std::string_view name, std::string_view prefix, bool labelled);

// Whether an entry of a written directory, given by its path relative to that directory
// ("trace.json", "branch-2/summary.json", "branch-2/notes/a.txt"), is the writer's own.
using OwnedEntry = std::function<bool(const std::filesystem::path& relative)>;

// Whether `name` is one of the three files of a run directory (result_files.hpp).
bool IsRunFileName(std::string_view name);

// The entries a run's directory owns: its three files.
bool IsRunEntry(const std::filesystem::path& relative);

// The entries owned by a directory that holds, besides the files `own_file` names, the run
// directories `own_run` names (a trace's branch-<k>, a map's curve-<k>): those directories and their
// three files. Anything else inside them is the user's (an export, notes, a continuation written
// into them).
using OwnedName = std::function<bool(std::string_view name)>;
OwnedEntry EntriesWithRuns(OwnedName own_file, OwnedName own_run);

// The values of `keys`, at any depth, of the JSON object in `index` (a trace.json's branch names,
// a regions.json's curve directories): the run directories an earlier writer listed there, and so
// the only ones of its directory that are its own (a user's "branch-9/" there is the user's). None
// where the file is missing or no JSON object.
std::set<std::string> ListedNames(const std::filesystem::path& index, const std::vector<std::string>& keys);

// Writes results_root/<output>/ as a whole: `write` fills a temporary directory beside it with
// entries for which `ours` is true, which then replaces the old one. Every entry of the old
// directory, at any depth, for which `ours_before` (what its writer made) is false (a file of the
// user's, an export, a directory of the user's, moved whole) moves into the same place in the new
// one first (inside an entry of ours that is a directory); their relative paths are returned,
// sorted. On a failure the old directory stays as it was, and of the temporary one only `ours`
// entries are removed (a file of the user's that could not be moved back stays).
// SIGINT, SIGTERM and SIGHUP while the temporary exists are a failure too, after which the process
// ends by the signal (deferred_signals.hpp). First, the temporaries that earlier writers of the
// output left and that are provably dead are removed, the others listed (stale_temporaries.hpp).
std::vector<std::string> ReplaceDirectory(const std::filesystem::path& results_root, const std::string& output,
                                          const std::function<void(const std::filesystem::path&)>& write,
                                          const OwnedEntry& ours, const OwnedEntry& ours_before);

}  // namespace stickslip::detail
