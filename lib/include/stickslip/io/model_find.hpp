// find for a run file's [model] (model_table.hpp), as every front end runs it: the oscillator and
// its parameters (the file's, then `set` over them) read and checked once, before any work
// (ReadModelFileStart); the motion from rest simulated for `transients` periods (kMinModelTransients to
// kMaxModelTransients: forcing periods; without forcing, periods of the slowest free oscillation of
// its slip, the stick-slip cycle's time scale), and the orbit it settles on solved and checked
// (analysis/model_orbit_finder.hpp).
//
//   const ModelFindRun run = FindModelOrbitOf(ReadModelFileStart("belt.toml", {{"v_b", 0.4}}), 1000);
#pragma once

#include <filesystem>

#include "stickslip/analysis/model_orbit_finder.hpp"
#include "stickslip/model/linear_oscillator.hpp"
#include "stickslip/named_values.hpp"
#include "stickslip/progress.hpp"

namespace stickslip {

// The fewest and the most periods `transients` takes (the period is read from a stop at least one
// period before the end; a forced 50-mass chain simulates about 2000 forcing periods a second).
inline constexpr int kMinModelTransients = 2;
inline constexpr int kMaxModelTransients = 100000;

// A run file's oscillator at its parameters, read once for find and trace.
struct ModelFileStart {
  DynamicLinearOscillator model;
  DynamicLinearOscillator::Parameters parameters;
  double slowest_frequency = 0.0;  // of its slip's free oscillations: the time unit without forcing
};

// Throws RunFileError or InvalidInput (naming `set` entries by their names) for bad input.
ModelFileStart ReadModelFileStart(const std::filesystem::path& run_file, const NamedValues& set);

struct ModelFindRun {
  DynamicLinearOscillator model;
  DynamicLinearOscillator::Parameters parameters;
  ModelFindResult<DynamicLinearOscillator> found;
};

// Throws InvalidInput naming "transients" out of its range, before any simulation.
ModelFindRun FindModelOrbitOf(const ModelFileStart& start, int transients, ProgressCallback progress = {});

}  // namespace stickslip
