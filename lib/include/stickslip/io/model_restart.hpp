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

#include "stickslip/branches/orbit_continuation.hpp"
#include "stickslip/io/model_find.hpp"
#include "stickslip/io/run_file.hpp"
#include "stickslip/io/stored_run.hpp"

namespace stickslip {

// Whether results_root/<run> holds a stored run of a [model] (its summary.json names one). False
// where it holds none, or none that can be read: the paper's restart reports those.
bool HoldsModelRun(const std::filesystem::path& results_root, const std::string& run);

// The [model] a stored run was computed for, read from the run file its summary names (a path as
// the run was given it, relative to the working directory). Throws InvalidInput naming "run" for a
// run made from the command line with --set (no run file holds its model), and as ReadModelFileStart.
ModelFileStart ModelOfStoredRun(const StoredRun& run);

struct ModelRunSetup {
  ModelFileStart file;   // the model (its run file's parameters replaced by the label's)
  std::string run_file;  // that file, as the stored run's summary names it
  BasicOrbitContinuationSetup<DynamicLinearOscillator> setup;
};

// nullopt when run.restart_run is no [model]'s run (HoldsModelRun). Otherwise the setup at the
// label, in run.parameter (any of the model's parameters its forcing lets vary) over run.range with
// run's continuation keys. Throws RunFileError at the key: start.restart (no such label, the model's
// run file missing or no longer the run's model), continuation.parameter, continuation.range (not
// holding the label's value), and for the keys only the paper's model takes (start.set, start.guess,
// unknowns.*, continuation.user_values_of, start.restart.switch_branch, start.restart.boundary).
std::optional<ModelRunSetup> MakeModelSetup(const RunFile& run, const std::filesystem::path& results_root);

}  // namespace stickslip
