// The result files of a continuation run, results/<output>/, and their one writer and one reader
// (as AUTO-07p has parseB and parseS for its b. and s. files):
//   branch.csv          one row per branch point (the columns of StoredPoint)
//   special-points.csv  the special points: the same columns, then type, test_function, located
//   summary.json        run file, version, output, signature, parameter, shooting, number of
//                       points, special points by type, termination and its message
// Numbers are written in shortest round-trip form, and no time or host is recorded: the same run
// gives byte-identical files, and reading then writing them again gives the same bytes.
//
//   WriteRunFiles("results", RecordRun(run_file, branch));
//   const StoredRun stored = ReadRunFiles("results/paper-5.1-omega-up");
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "stickslip/io/stored_run.hpp"

namespace stickslip {

struct RunFiles {
  std::string branch_csv;
  std::string special_points_csv;
  std::string summary_json;
};

// The columns of `point`'s row, "pt" to "step_size" (StoredPoint): the header of branch.csv.
std::vector<std::string> ColumnNames(const StoredPoint& point);

// The three files' text. Throws std::invalid_argument if the run has no branch point or its
// points differ in their columns (a programming error: RecordRun gives neither).
RunFiles FormatRunFiles(const StoredRun& run);

// The run the texts describe; `directory` names the files in messages. Throws InvalidInput naming
// the file, the line and the column (or the JSON key) of the first problem: invalid JSON, a
// missing or unknown key or column, a row with more or fewer fields than its header, a field
// that is not a number, an integer or a 0/1 flag, an invalid signature or parameter, counts in
// summary.json that differ from the tables.
StoredRun ParseRunFiles(const RunFiles& files, const std::filesystem::path& directory);

// Throws InvalidInput naming "results" if results_root is not a directory and cannot be created
// (a file, a path too long, no permission), and InvalidInput naming "output" if
// results_root/<output> exists but is not the directory of a stickslip run (one whose
// summary.json reads as a run's): a file, a symbolic link, a directory of the user's, an
// unreadable one. Touches nothing: a missing results_root is created and removed again, the one
// exact test that it can be. Front ends call it before a run, so that nothing is computed for
// nothing; WriteRunFiles calls it again.
void CheckOutputDirectory(const std::filesystem::path& results_root, const std::string& output);

// Writes results_root/<run.summary.output>/ as a whole: the three files go into a temporary
// directory first, which then replaces the old one. Every other file of the old directory (the
// AUTO export's b.<run> and s.<run>, files of the user's) moves into the new one; returns their
// names, sorted. Throws InvalidInput as CheckOutputDirectory, with nothing touched.
std::vector<std::string> WriteRunFiles(const std::filesystem::path& results_root, const StoredRun& run);

// Reads results_root/<run>/. Throws InvalidInput as ParseRunFiles, and if a file cannot be read.
StoredRun ReadRunFiles(const std::filesystem::path& run_directory);
// The summary alone of the run in run_directory (summary.json), as ReadRunFiles reads it. Throws
// InvalidInput as it does.
StoredSummary ReadRunSummary(const std::filesystem::path& run_directory);

// The special point labelled `label` in results_root/<run>/, for a restart: the orbit's
// variables by name (SolutionColumns) and the run's signature. Throws InvalidInput, also when
// `run` is not a run name (IsRunName) or no special point has that label (listing the labels).
struct LabelledPoint {
  std::string signature;
  NamedValues variables;
  std::string type;           // the special point's: LP, PD, SK, ... (its label's letters, as written)
  std::string test_function;  // the special point's: "margin:reversal:1", "floquet:det(M+I)", ...
};
LabelledPoint ReadLabelledPoint(const std::filesystem::path& results_root, const std::string& run,
                                const std::string& label);

// The special point of `run` (read from run_directory) labelled `label`. Throws InvalidInput naming
// "label" with the labels it has.
const StoredSpecialPoint& SpecialPointLabelled(const StoredRun& run, const std::string& label,
                                               const std::filesystem::path& run_directory);

}  // namespace stickslip
