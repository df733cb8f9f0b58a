// The files of an orbit-type map (branches/orbit_type_map.hpp), results/maps/<name>/, and the trace
// it is built from:
//   curves.csv     one row per point of every curve: curve (its id), kind (its condition: "LP",
//                  "margin:reversal:1"), from (the trace's special point), direction, signature,
//                  pt, label, the first and second parameters, stable, admissible (apart from the
//                  curve's defining conditions), then the orbit's variables as branch files have
//                  them (the paper's chi, eta, omega, u_s, u_r, phi, x10, x20, v10; a [model]'s
//                  parameters, phi and start state by its names) and durations (d1..dn, ';'-joined:
//                  curves of different types have different counts)
//   curve-<k>/     each curve as an ordinary run directory (result_files.hpp), its special points
//                  (the codimension-two points, folds, ends) labelled: a run file restarts from
//                  them with results root results/maps/<name> and restart.run = "curve-<k>"
//   regions.json   the rectangle, the raster and its cells (one string of region ids per raster
//                  row, j from the bottom; -1 cut, -2 sliver), the regions (interior point,
//                  clearance, label, stable types, every orbit found, failures), the curves (kind,
//                  start, end, their special points), the trace's points that gave no curve, and
//                  the comparison's counts (null without one)
//   comparison.md  the brute-force comparison (analysis/map_comparison.hpp), when there is one
// Numbers in shortest round-trip form, no time or host: the same map gives the same bytes.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "stickslip/analysis/map_comparison.hpp"
#include "stickslip/branches/orbit_type_map.hpp"
#include "stickslip/io/run_file.hpp"
#include "stickslip/io/stored_run.hpp"
#include "stickslip/io/trace_files.hpp"

namespace stickslip {

// The map's input from a stored trace: every branch's points and special points. Each branch's
// unknowns are the trace's start's (run: its preset's, then its [unknowns], as BuildStartProblem
// chooses them; nullptr: the defaults), its step sizes the run file's [continuation] ones. The
// shooting and flow are the defaults.
MapTrace MapTraceOf(const StoredTrace& trace, const RunFile* run);

// A [model]'s trace as the map's input: its model read from the run file the trace names (found as
// ModelFileOf finds it, from `trace_directory`), every branch's points and
// special points, each branch's unknowns its orbits' at fixed parameters, its step sizes and
// max_amplitude `run`'s (nullptr: the defaults). Throws InvalidInput naming "run" (no file holds the
// model: a trace made from the command line) or "run_file" (the file cannot be read, or declares
// other units than the trace's, or its model changed since: the trace's first orbit is no longer
// periodic).
BasicMapTrace<DynamicLinearOscillator> ModelMapTraceOf(const StoredTrace& trace,
                                                       const std::filesystem::path& trace_directory, const RunFile* run);

// The types of the trace's branches (their signatures), for the comparison.
std::vector<std::string> TraceTypes(const StoredTrace& trace);

struct OrbitTypeMapFiles {
  std::string curves_csv;
  std::string regions_json;
  std::string comparison_md;      // empty without a comparison
  std::vector<StoredRun> curves;  // curve-<k>/, each as a run's files
};
// `trace` names the trace directory in the files; `brute_force` the brute-force map file.
OrbitTypeMapFiles FormatOrbitTypeMapFiles(const OrbitTypeMap& map, const std::string& trace,
                                          const MapComparison* comparison, const std::string& brute_force);
// A [model]'s, in its units: its curves' runs name `run_file`, the run file of its [model], which
// their restarts read the model from. Its columns are the model's (SolutionColumns).
OrbitTypeMapFiles FormatOrbitTypeMapFiles(const DynamicLinearOscillator& model, const std::string& run_file,
                                          const BasicOrbitTypeMap<DynamicLinearOscillator>& map, const std::string& trace);

// Writes `directory` whole (the files above and curve-<k>/), into a temporary directory first that
// then replaces the old one. Every other entry of the old directory (a file of the user's, a run
// restarted from a curve) moves into the new one; their names are returned, sorted. Throws
// InvalidInput naming "output" where `directory` exists and is not a map's directory (no
// regions.json), or cannot be written.
std::vector<std::string> WriteOrbitTypeMapFiles(const std::filesystem::path& directory, const OrbitTypeMapFiles& files);

// Throws InvalidInput naming "output" where `directory` could not be written by
// WriteOrbitTypeMapFiles: its name is no run name (IsRunName: one component, no control
// characters, at most 200 bytes), it is a file or a directory that holds no map (a regions.json
// with a map's keys: the user's own regions.json is no map's), or no file can be
// created in it or in its nearest existing ancestor. Touches nothing (but a probe file it removes).
void CheckOrbitTypeMapDirectory(const std::filesystem::path& directory);

}  // namespace stickslip
