// The brute force of an oscillator of the user's (model/linear_oscillator.hpp) along one of its
// parameters: at every value of a grid, runs from rest and from scattered starts (a fixed sweep:
// every value from each start afresh) and from the neighbouring value's end both ways (a chained
// sweep from rest, up then down: analysis/sweep.hpp). The runs that end on the same section orbit
// (the same period, the same section points under a cyclic shift, to the tolerance times their
// size: the model's units are its own) are one attractor; the runs that settle on none are one
// "not-settled" entry, those whose simulation stopped early (a motion growing without bound) one
// "incomplete" entry. A model without forcing is read on its stick-entry section.
//
// The first stage of the model's atlas (model_atlas.hpp) and each row of its brute-force map
// (model_brute_force_map.hpp).
//
//   ModelBruteForceOptions o;   // 300 transient periods, 12 recorded, rest + 4 scattered starts
//   const auto cells = ModelBruteForce(model, parameters, ModelAxis{"omega", 0.3, 0.95, 26}, o);
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "stickslip/analysis/brute_force_map.hpp"  // AttractorStatus
#include "stickslip/model/linear_oscillator.hpp"
#include "stickslip/progress.hpp"

namespace stickslip {

// One parameter of a model by name over steps + 1 values from `from` to `to`, evenly spaced.
struct ModelAxis {
  std::string parameter = "omega";
  double from = 0.0;
  double to = 0.0;
  int steps = 20;

  int Count() const { return steps + 1; }
  double ValueAt(int index) const;  // GridValueAt
  // The parameter's index in the model's description. Throws InvalidInput naming `field` when the
  // model has no such parameter, or it is omega and the model has no forcing.
  int IndexIn(const DynamicLinearOscillator& model, const char* field) const;
};

struct ModelBruteForceOptions {
  // Per run: periods simulated and discarded, then recorded (forcing periods; without forcing,
  // `time_unit`s). Periods up to recorded/2 are detected.
  int transient_periods = 300;  // 0 to kMaxPeriods
  int recorded_periods = 12;    // 2 to kMaxPeriods
  // Besides rest, at every grid value: `centre` (rest where empty), then states drawn from the box
  // |x - centre|_inf <= scatter (in the model's units, 0 to 1e6); scattered_starts in all (0 to
  // kMaxScatteredStarts).
  int scattered_starts = 4;
  Eigen::VectorXd centre;
  double scatter = 1.0;
  std::uint64_t seed = 1;  // of the scattered starts (splitmix64)
  // Section points repeat, and two runs end on one attractor, within this times their size
  // (kMinTolerance to kMaxTolerance).
  double periodicity_tolerance = 1e-6;
  // Without forcing, the time counted as a period (> 0): the slowest free oscillation's 2 pi/omega_1.
  double time_unit = 0.0;
  double section_phase = 0.0;  // with forcing: the forcing phase at the section times (time 0 of every run)
  int threads = 0;             // 0: every hardware thread. The result does not depend on it.
  // Called after every run with unit "points" (done of total, the run's parameter value); the
  // atlas and the map replace it with their own.
  ProgressCallback progress = {};

  static constexpr int kMaxPeriods = 1000000;
  static constexpr int kMaxScatteredStarts = 1000;
  static constexpr double kMinTolerance = 1e-14;
  static constexpr double kMaxTolerance = 1e-2;

  // The runs per grid value: rest, the scattered starts, the chained sweep up and down.
  int RunsPerValue() const { return scattered_starts + 3; }
  // Throws InvalidInput naming the field as the command line's flag ("transients", "periods",
  // "starts", "scatter", "centre", "tolerance", "time-unit", "threads").
  void Validate(const DynamicLinearOscillator& model) const;
};

// What the brute force found at one grid value: an attractor, or every run that settled on none.
struct ModelAttractor {
  AttractorStatus status = AttractorStatus::kNotSettled;
  int period = 0;  // forcing periods (stick-slip cycles without forcing); 0 unless periodic
  double stops_per_period = 0.0;
  double sticks_per_period = 0.0;
  double contact_amplitude = 0.0;  // max |q_c| over the recorded periods
  int starts = 0;                  // the runs that ended on it
  std::vector<Eigen::VectorXd> section;  // periodic: its `period` section points; else where the first run ended
  std::string incomplete;  // kIncomplete: why the first run stopped early (the state it started from is the section's)
};

// The attractors at each value of `axis` (by grid index), in the order the runs found them: the
// fresh starts by start, then the chained sweep's up and down passes. `axis` names one of the
// model's parameters and every grid value is one the model takes (the sweep refuses the others,
// naming "from", "to" or "steps"). Throws InvalidInput (ModelBruteForceOptions::Validate); every
// simulation outcome is recorded.
std::vector<std::vector<ModelAttractor>> ModelBruteForce(const DynamicLinearOscillator& model,
                                                         const DynamicLinearOscillator::Parameters& base,
                                                         const ModelAxis& axis, const ModelBruteForceOptions& options);

}  // namespace stickslip
