// find for a run file's [model] (model_table.hpp), as every front end runs it: the oscillator and
// its parameters (the file's, then `set` over them) read and checked once, before any work
// (ReadModelFileStart); the motion from rest (or the state `set` gives) simulated for `transients` periods (kMinModelTransients to
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
#include "stickslip/model/linear_oscillator.hpp"
#include "stickslip/named_values.hpp"
#include "stickslip/progress.hpp"

namespace stickslip {

// The fewest and the most periods `transients` takes (the period is read from a stop at least one
// period before the end; a forced 50-mass chain simulates about 2000 forcing periods a second).
inline constexpr int kMinModelTransients = 2;
inline constexpr int kMaxModelTransients = 100000;

// A run file's oscillator at its parameters, and the motion's start, read once for find, trace and sweep.
struct ModelFileStart {
  DynamicLinearOscillator model;
  DynamicLinearOscillator::Parameters parameters;
  double slowest_frequency = 0.0;  // of its slip's free oscillations: the time unit without forcing
  // The natural frequencies of its slip (its oscillating free modes', as describe lists them), which
  // a figure over omega marks; read with the model, so that a long run needs the file only at its start.
  std::vector<double> slip_frequencies;
  Eigen::VectorXd state;  // at t = 0: rest unless the file's start or `set` names its components (x1_0, v1_0, ...)
  double phi = 0.0;       // the forcing's phase at t = 0 (the file's or `set`'s phi)
  NamedValues set_parameters;  // the parameters `set` gave over the file's

  // Throws InvalidInput naming "set" when `set` gave `parameter`, which `varies` (a map's axis, an
  // atlas's grid) sets at every value itself: the value would be ignored.
  void RefuseSetOf(const std::string& parameter, std::string_view varies) const;
};

// `set` gives parameters (over the file's) and, over the file's start (StartOf), start-state
// components by their names (ModelDescription::initial_state) and the forcing phase "phi". Throws
// RunFileError or InvalidInput (naming `set` entries by their names) for bad input.
ModelFileStart ReadModelFileStart(const std::filesystem::path& run_file, const NamedValues& set);

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

}  // namespace stickslip
