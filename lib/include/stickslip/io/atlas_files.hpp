// The result files of an atlas (analysis/atlas.hpp), results/<output>/, and their one writer:
//   trace-<t>/           the atlas's traces, t = 1, 2, ... in the order they were started: each a
//                        trace's directory (io/trace_files.hpp), so that `plot`, a restart
//                        (--results results/<output>/trace-<t> --point branch-<k>:LABEL) and
//                        `export --auto` work on them as on any trace
//   atlas.json           the run file, version, output, parameter, range, grid, period limit; the
//                        counts (attractors, periodic within the limit, on branches, unexplained,
//                        traces, branches, orbit types); per grid value its attractors (the brute
//                        force's status, period, signature, starts; FindOrbit's status, the exact
//                        orbit's signature and amplitudes; the fate, the branch "trace-<t>/branch-<k>"
//                        and point, or the reason) and the branches its stable motions lie on; per
//                        trace the attractor it started from and how its directions ended
//   atlas-intervals.csv  per branch, its pieces of one stability and admissibility: trace, branch,
//                        signature, from, to (the parameter at the piece's first and last point),
//                        stable, admissible, first_label, last_label, branch_end
//   brute-force.csv      the brute force, as `stickslip map-sweep` writes a map (io/map_file.hpp);
//                        a [model]'s: its attractors (RecordModelAtlas)
// Numbers in shortest round-trip form, no time or host: the same atlas gives the same bytes.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "stickslip/analysis/atlas.hpp"
#include "stickslip/analysis/model_atlas.hpp"
#include "stickslip/io/run_file.hpp"
#include "stickslip/io/trace_files.hpp"

namespace stickslip {

struct AtlasFiles {
  std::string atlas_json;
  std::string intervals_csv;
  std::string brute_force_csv;
};

struct StoredAtlas {
  std::string output;
  std::vector<StoredTrace> traces;  // trace-1, trace-2, ...
  AtlasFiles files;
};

// The stored form of an atlas just computed from `run` (its path, output and parameter) with
// `options` (the range, grid and period limit it records).
StoredAtlas RecordAtlas(const RunFile& run, const Atlas& atlas, const AtlasOptions& options);

// The stored form of a [model]'s atlas (analysis/model_atlas.hpp) from `run` (its path, output):
// the same files, atlas.json with "model": "linear-oscillator" and each attractor's exact orbit's
// amplitudes by coordinate ("amplitude:<q>"), every trace carrying `natural_frequencies` (the
// slip's, as a [model]'s trace: io/model_trace.hpp), brute-force.csv its one-row map as
// `stickslip map-sweep --model` writes one (io/map_file.hpp).
StoredAtlas RecordModelAtlas(const RunFile& run, const ModelAtlas& atlas, const ModelAtlasOptions& options,
                             const std::vector<double>& natural_frequencies);

// Throws InvalidInput naming "output" unless it is a run name (IsRunName) that is new (then as
// CheckOutputDirectory, result_files.hpp) or names a directory holding an atlas (its atlas.json reads
// as one; not a symbolic link) that can be written.
void CheckAtlasOutputDirectory(const std::filesystem::path& results_root, const std::string& output);

// Writes results_root/<atlas.output>/ as a whole (into a temporary directory first, which then
// replaces the old one); every other entry of the old directory, at any depth (notes, an export in
// trace-2/branch-1/), moves into the new one, and their names are returned, sorted.
std::vector<std::string> WriteAtlasFiles(const std::filesystem::path& results_root, const StoredAtlas& atlas);

}  // namespace stickslip
