// Executing a run file: the continuation setup it describes (presets, restart from a labelled
// point of earlier results, choice of unknowns) and the bifurcation data files it produces in
// results/<output>/:
//   branch.csv          one row per point: pt, label, chi, eta, omega, u_s, u_r, phi, x10, x20,
//                       v10, d1..dn, margin:<name>..., admissible, newton_iterations, step_size
//   special-points.csv  the labelled points: the same columns plus type and test_function
//   summary.json        run file, version, signature, counts, termination
// Labels are the special-point type and a running number (EP1, LP2, GR3, ...), as AUTO's.
// Numbers are written in shortest round-trip form, and no time or host is recorded: the files
// are byte-identical from run to run.
#pragma once

#include <filesystem>
#include <string>

#include "stickslip/branches/orbit_continuation.hpp"
#include "stickslip/io/run_file.hpp"

namespace stickslip {

// The setup a run file describes. Throws RunFileError naming the file, line and key.
OrbitContinuationSetup MakeSetup(const RunFile& run, const std::filesystem::path& results_root);

struct RunFiles {
  std::string branch_csv;
  std::string special_points_csv;
  std::string summary_json;
};
// The files depend on the run file and the branch only (no time, no host), so the same run file
// gives byte-identical files on the same build.
RunFiles FormatRunFiles(const RunFile& run, const OrbitBranch& branch);

// Writes the three files into results_root/<output>/ as a whole: into a temporary directory
// first, which then replaces the old one.
void WriteRunFiles(const std::filesystem::path& results_root, const std::string& output, const RunFiles& files);

// The CSV row of the labelled point `label` in results_root/<run>/special-points.csv, as
// (column, text) pairs, and the signature from its summary.json. Throws std::runtime_error,
// also when `run` is not a run name (IsRunName).
struct LabelledPoint {
  std::string signature;
  std::vector<std::pair<std::string, std::string>> columns;
};
LabelledPoint ReadLabelledPoint(const std::filesystem::path& results_root, const std::string& run,
                                const std::string& label);

// A CSV file as a header and rows of fields (no quoting: stickslip's files need none).
struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};
CsvTable ParseCsv(const std::string& text);
std::string ReadTextFile(const std::filesystem::path& path);

}  // namespace stickslip
