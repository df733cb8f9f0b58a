// find for a run file's [model] (model_table.hpp), as every front end runs it: the oscillator and
// its parameters (the file's, then `set` over them) read and checked once, before any work
// (ReadModelFileStart, model_file_start.hpp); the motion from rest (or the state `set` gives) simulated for `transients` periods (kMinModelTransients to
// kMaxModelTransients: forcing periods; without forcing, periods of the slowest free oscillation of
// its slip, the stick-slip cycle's time scale), and the orbit it settles on solved and checked
// (analysis/model_orbit_finder.hpp).
//
//   const ModelFindRun run = FindModelOrbitOf(ReadModelFileStart("belt.toml", {{"v_b", 0.4}}), 1000, 8);
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "stickslip/analysis/model_orbit_finder.hpp"
#include "stickslip/io/model_file_start.hpp"
#include "stickslip/model/linear_oscillator.hpp"
#include "stickslip/named_values.hpp"
#include "stickslip/progress.hpp"

namespace stickslip {

// The fewest and the most periods `transients` takes (the period is read from a stop at least one
// period before the end; a forced 50-mass chain simulates about 2000 forcing periods a second).
inline constexpr int kMinModelTransients = 2;
inline constexpr int kMaxModelTransients = 100000;

struct ModelFindRun {
  DynamicLinearOscillator model;
  DynamicLinearOscillator::Parameters parameters;
  ModelFindResult<DynamicLinearOscillator> found;
  std::vector<double> slip_frequencies;  // the start's (ModelFileStart::slip_frequencies)
};

// From the start's state and phase, the least period of 1 to max_multiple forcing periods (1 to
// ModelFindOptions::kMaxMultiple; without forcing the stick-slip cycle's). Throws InvalidInput
// naming "transients" or "max-multiple" out of its range, before any simulation.
ModelFindRun FindModelOrbitOf(const ModelFileStart& start, int transients, int max_multiple,
                              ProgressCallback progress = {});

// The orbit at the label `point` ("RUN:LABEL") of a stored [model]'s run under results_root, solved
// again at the label's parameters from its stored variables (start, phase, durations unknown) and,
// where Newton converges, checked as find checks an orbit: what `solve --point` and Python's
// solve(point=) give. Throws InvalidInput naming "point" where the run, the label or its model
// cannot be read (ReadModelLabel), or where the orbit has an abnormal stop (solved only with a
// friction level released, as continuations from it do).
ModelFindRun SolveAtModelLabel(const std::filesystem::path& results_root, const std::string& point,
                               const OrbitSolverOptions& solver);

}  // namespace stickslip
