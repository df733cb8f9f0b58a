// A continuation or a trace from a labelled point of a stored run of a run file's [model] (a branch
// of `find --model --trace`, of `atlas --model`, or of a run restarted from one): the model read
// from the run file the stored run's summary names, the orbit at the label from its stored variables
// (OrbitOf, the columns' inverse), and the continuation's setup from the run's keys, as MakeSetup
// (io/run.hpp) gives the paper's. One way in for `continue --point`, `trace --point` and a run
// file's [start.restart].
//
//   if (const std::optional<ModelRunSetup> s = MakeModelSetup(run, "results")) ContinueOrbit(s->setup);
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "stickslip/branches/orbit_continuation.hpp"
#include "stickslip/branches/trace.hpp"
#include "stickslip/io/model_file_start.hpp"
#include "stickslip/io/run_file.hpp"
#include "stickslip/io/stored_run.hpp"
#include "stickslip/io/trace_files.hpp"

namespace stickslip {

// Whether results_root/<run> holds a stored run of a [model] (its summary.json names one). False
// where it holds none, or none that can be read: the paper's restart reports those.
bool HoldsModelRun(const std::filesystem::path& results_root, const std::string& run);

// A one-off run's start point "RUN:LABEL" where it names a [model]'s run (HoldsModelRun): its run
// and label, which the run's [start.restart] takes unread (MakeModelSetup reads them with the run);
// nullopt for an empty point or any other, which the paper's start reads. Throws InvalidInput naming
// "restart" for a text that is not RUN:LABEL.
std::optional<std::pair<std::string, std::string>> ModelPointOf(const std::filesystem::path& results_root,
                                                                std::string_view point);

// The [model]'s run file a stored run (in run_directory) was computed for, as its summary names it:
// absolute, or relative to a directory above run_directory (the project's root, where tools/run.sh
// writes results/; the nearest that holds it), else to the working directory. Throws InvalidInput
// naming "run" for a run made from the command line with --set (no run file holds its model).
std::filesystem::path ModelFileOf(const StoredRun& run, const std::filesystem::path& run_directory);
// That file's model (ReadModelFileStart: throws as it does).
ModelFileStart ModelOfStoredRun(const StoredRun& run, const std::filesystem::path& run_directory);
// Throws InvalidInput naming "run_file" where `file` declares other units than `run`'s: what
// writes the run's numbers again under them (a restart, a map) would relabel every number.
void CheckUnitsUnchanged(const StoredRun& run, const ModelFileStart& file);

// The stored orbit at `label` of `run` at `samples` equally spaced times over its period by the
// model's closed forms (SampleOrbit), the last its start again. Throws InvalidInput naming
// "run_file" where it does not come back to its start (to 1e-6 of its size): the file no longer
// describes the run's model (changed since the run, or another file at the run's path).
std::vector<DynamicLinearOscillator::State> SampledStoredOrbit(const ModelFileStart& file,
                                                               const BasicOrbit<DynamicLinearOscillator>& orbit,
                                                               int samples, const StoredRun& run, const std::string& label);

struct ModelLabel {
  ModelFileStart file;   // the model, its parameters the label's
  std::string run_file;  // the model's run file, as the stored run's summary names it
  BasicOrbit<DynamicLinearOscillator> orbit;
  StoredSpecialPoint special;  // the label's special point: its type and test function
};

// The orbit at `label` of the stored [model]'s run results_root/<run> (OrbitOf), with its model
// (ModelOfStoredRun). Throws InvalidInput naming "restart" ("restart = 'RUN:LABEL' cannot be used:
// <why>") where the run, the label or the model cannot be read, the run's columns are not the
// model's, or its orbit is no periodic orbit of the model (SampledStoredOrbit), or the run file's
// units are no longer the run's.
ModelLabel ReadModelLabel(const std::filesystem::path& results_root, const std::string& run, const std::string& label);

struct ModelRunSetup {
  ModelFileStart file;   // the model (its run file's parameters replaced by the label's)
  std::string run_file;  // that file, as the stored run's summary names it
  BasicOrbitContinuationSetup<DynamicLinearOscillator> setup;
  // The summary's identity of `run`'s results: the model's run file, where its own restarts and
  // exports read the model.
  StoredSummary Identity(const RunFile& run) const {
    return {.run_file = run_file, .output = run.output, .parameter = run.parameter};
  }
  // `run`'s branch or trace from this setup, recorded as every front end writes it (RecordRun,
  // RecordTrace with the model's slip frequencies, which a figure over omega marks).
  StoredRun Recorded(const RunFile& run, const BasicOrbitBranch<DynamicLinearOscillator>& branch) const;
  StoredTrace Recorded(const RunFile& run, const BasicTraceResult<DynamicLinearOscillator>& trace) const;
};

// `orbit` written so that it can be continued in the model's parameter `parameter`: an antisymmetric
// orbit over its whole period where that is the surface's speed (the mirror of a stick on a moving
// surface moves the other way: CheckSymmetryHolds); otherwise as it is.
BasicOrbit<DynamicLinearOscillator> ContinuableIn(BasicOrbit<DynamicLinearOscillator> orbit, int parameter);

// nullopt when run.restart_run is no [model]'s run (HoldsModelRun). Otherwise the setup at the
// label, in run.parameter (any of the model's parameters its forcing lets vary) over run.range with
// run's continuation keys; with start.restart.switch_branch the branch that leaves the label (a PD
// or an SB: switched_restart.hpp); with start.restart.boundary the curve in two parameters through
// it (CurveOfRestart). Throws RunFileError at the key: start.restart (no such label, the model's run
// file missing or no longer the run's model), continuation.parameter, continuation.range (not
// holding the label's value), as SwitchedAtLabel and CurveOfRestart do, start.restart.boundary (no
// parameter the model varies; the belt's speed in a curve of an antisymmetric orbit), and for the
// keys only the paper's model takes (start.set, start.guess, unknowns.*).
std::optional<ModelRunSetup> MakeModelSetup(const RunFile& run, const std::filesystem::path& results_root);

}  // namespace stickslip
