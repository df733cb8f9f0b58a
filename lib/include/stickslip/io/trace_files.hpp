// The result files of a trace (branches/trace.hpp), results/<output>/, and their one writer and one
// reader:
//   branch-<k>/   one ordinary run directory per branch of the chain (result_files.hpp: branch.csv,
//                 special-points.csv, summary.json with output "branch-<k>"), k = 1, 2, ...: the
//                 down chain first, then the up chain, each in chain order. `check`, a restart
//                 (--results results/<output> --point branch-<k>:LABEL) and `export --auto` work
//                 on each as on any run.
//   trace.csv     one row per point of every branch: branch (k), signature, pt, label, the
//                 continued parameter, phi, period, the start state (x10, x20, v10 for the
//                 paper's model; a [model]'s names), stable, admissible
//   trace.json    the run file, version, output, parameter and start signature (and, for a run
//                 file's [model], "model": "linear-oscillator" and its slip's natural
//                 frequencies, "natural_frequencies"); per direction its
//                 end, message and branches (their k); per branch its name, direction, signature,
//                 points, how it began (start, margin, and for a switch the bifurcation, the edit,
//                 the adjacent signature, persists or a nonsmooth fold, from the orbit past the
//                 boundary), its end and message, and the branches met at its BP, PD and SB
//                 (label, type, parameter, the leaving branch's signature, the singularity there,
//                 and, where it was followed, its directory)
//   branch-<k>-<label>/  the branch followed from the special point <label> of branch k (an ordinary
//                 run directory)
// Numbers in shortest round-trip form, no time or host: the same trace gives the same bytes.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "stickslip/branches/trace.hpp"
#include "stickslip/io/stored_run.hpp"

namespace stickslip {

// How a branch of a stored trace began at a confirmed switch (or, followed past, at one that
// confirmed nothing: bifurcation empty).
struct StoredSwitch {
  std::string status;       // ToString(TypeSwitchStatus)
  std::string bifurcation;  // "crossing-sliding", ...; "" when not confirmed
  std::string edit;         // ToString(TypeEdit); "" when not confirmed
  std::string adjacent;     // the new signature; "" when not confirmed
  bool persists = false;    // else a nonsmooth fold (the new branch turns back)
  bool from_past = false;   // the branch starts from the orbit past the boundary (a singular start)
};

// A branch met at a BP, PD or SB of a trace's branch (BifurcationMet): recorded, not followed.
struct StoredBifurcation {
  std::string label;      // the special point's label in the branch's directory ("PD2")
  std::string type;       // "BP", "PD" or "SB"
  double lambda = 0.0;
  std::string signature;  // the type of the branch that leaves it; "" where its start failed
  double singularity = 0.0;
  std::string message;
  std::string followed;   // the followed branch's directory ("branch-2-PD3"), "" if recorded only
};

struct StoredTraceBranch {
  std::string name;       // "branch-<k>", its directory
  std::string chain;      // "down" or "up": the chain it belongs to
  std::string direction;  // "down" or "up": the parameter's way at its start
  std::string signature;
  std::size_t points = 0;
  std::string start;      // ToString(LinkStart)
  std::string margin;     // the previous branch's margin it began at ("" for the trace's start)
  bool has_switch = false;
  StoredSwitch type_switch;  // when has_switch
  std::string end;        // ToString(TraceEnd)
  std::string message;
  std::vector<StoredBifurcation> bifurcations;
};

struct StoredTraceDirection {
  std::string direction;  // "down" or "up"
  std::string end;        // ToString(TraceEnd)
  std::string message;
  std::vector<std::size_t> branches;  // 1-based k of its branches, in chain order
};

// One row of trace.csv.
struct StoredTracePoint {
  std::size_t branch = 0;  // k
  std::string signature;
  int pt = 0;
  std::string label;
  double lambda = 0.0;
  double phi = 0.0;
  double period = 0.0;
  NamedValues start{};  // the orbit's start state by name (x10, x20, v10 for the paper's model)
  bool stable = false;
  bool admissible = false;
};

struct StoredTrace {
  std::string run_file;
  std::string stickslip_version;
  std::string output;
  std::string parameter;
  std::string signature;  // the start's
  std::string model;      // StoredSummary::model: "" for the paper's
  // A [model]'s undamped natural frequencies of its slip (rad/s, increasing), that a figure over
  // omega marks; empty for the paper's (eq. 56 gives them from chi and eta) and where unknown.
  std::vector<double> natural_frequencies;
  std::vector<StoredTraceDirection> directions;  // down, then up
  std::vector<StoredTraceBranch> branches;       // branch-1, branch-2, ...
  std::vector<StoredRun> runs;                   // one per branch, its directory's files
  std::vector<StoredRun> followed_runs;          // one per followed bifurcation, in the order listed
  std::vector<StoredTracePoint> points;          // trace.csv
};

// The stored form of a trace just computed from `run`.
StoredTrace RecordTrace(const RunFile& run, const TraceResult& trace);
// Any model's: `identity` gives the run file, the output and the model (StoredSummary), and each
// branch's parameter. Compiled for the paper's model and DynamicLinearOscillator.
template <OscillatorModel Model>
StoredTrace RecordTrace(const Model& model, const StoredSummary& identity, const BasicTraceResult<Model>& trace);

struct TraceFiles {
  std::string trace_csv;
  std::string trace_json;
};
TraceFiles FormatTraceFiles(const StoredTrace& trace);

// Throws InvalidInput as CheckOutputDirectory (result_files.hpp), except that a directory holding
// a trace (its trace.json reads as one) may be replaced too.
void CheckTraceOutputDirectory(const std::filesystem::path& results_root, const std::string& output);

// Writes results_root/<trace.output>/ as a whole (into a temporary directory first, which then
// replaces the old one); other files of the old directory move into the new one, and their names are
// returned, sorted.
std::vector<std::string> WriteTraceFiles(const std::filesystem::path& results_root, const StoredTrace& trace);

// Reads results_root/<output>/: trace.json, trace.csv and every branch's directory. Throws
// InvalidInput naming the file and the key, line or column of the first problem (also counts that
// differ between the files).
StoredTrace ReadTraceFiles(const std::filesystem::path& trace_directory);

// Whether `directory` holds a trace (a trace.json), for the front ends that take a run or a trace.
bool IsTraceDirectory(const std::filesystem::path& directory);

// Whether `output` under `results_root` is a part of a trace there: results_root holds a trace and
// `output` is a name it writes (trace.csv, trace.json, branch-<k>, branch-<k>-<label>). A run or a
// trace written there would replace the trace's own branch and leave its trace.json naming a run
// that no longer exists.
bool IsPartOfTrace(const std::filesystem::path& results_root, const std::string& output);

}  // namespace stickslip
