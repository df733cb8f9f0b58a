// A run file's [model] (model_table.hpp) read for a run: the oscillator at its parameters (the
// file's, then `set` over them) and the motion's start, read and checked once, before any work.
// Light on purpose: what every front end that names a model includes (find, trace, sweep, maps,
// atlas, restarts), without the finder's simulators.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "stickslip/model/linear_oscillator.hpp"
#include "stickslip/named_values.hpp"

namespace stickslip {

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

}  // namespace stickslip
