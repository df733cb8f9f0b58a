// Brute-force bifurcation diagram: a parameter stepped up and then down, each point started
// from the last state of the previous one, transients simulated out with the exact simulator,
// and the stroboscopic section (the state at the forcing phase phi_section, once per forcing
// period) recorded.
#pragma once

#include <string>
#include <vector>

#include "stickslip/model/flows.hpp"
#include "stickslip/model/parameters.hpp"

namespace stickslip {

struct SweepOptions {
  ParameterId parameter = ParameterId::kOmega;
  double from = 0.0;           // first value of the upward sweep (the downward one ends there)
  double to = 0.0;             // last value of the upward sweep
  int steps = 50;              // intervals between from and to (>= 1)
  int transient_periods = 200;  // forcing periods simulated and discarded at each point
  int recorded_periods = 20;    // forcing periods recorded at each point
  double periodicity_tolerance = 1e-6;  // section points this close repeat
};

struct SweepPoint {
  int direction = 1;  // +1 upward, -1 downward
  int step = 0;       // index along the direction
  double value = 0.0;  // the parameter
  std::vector<State> section;  // recorded_periods states at phase phi_section
  double stops_per_period = 0.0;
  double sticks_per_period = 0.0;
  int period = 0;  // smallest p with section[k + p] == section[k] (to tolerance); 0 if none
};

// `start` is the state at forcing phase `phi_section` (time 0) for the first upward point; the
// downward sweep starts from where the upward one ended. Every point needs the previous one's
// state, so the sweep is sequential. Precondition: Validate passes at every swept value.
std::vector<SweepPoint> Sweep(const Parameters& base, const State& start, double phi_section,
                              const SweepOptions& options);

// One CSV row per recorded section point: direction, step, <parameter>, section_phase, k, x1, x2,
// v1, v2, stops_per_period, sticks_per_period, period. Deterministic: shortest round-trip numbers.
std::string SweepCsv(const std::vector<SweepPoint>& points, ParameterId parameter, double phi_section);

}  // namespace stickslip
