// A motion simulated until it has settled, as the brute-force sweep and map see it: transients
// simulated out with the exact simulator (in chunks, model/transient.hpp), then a record of
// recorded_periods forcing periods whose stroboscopic section (the state at the forcing phase
// phi_section, once per period), stops and sticks per period and period on the section are read.
// The one per-point computation of analysis/sweep.hpp and analysis/brute_force_map.hpp, for the
// paper's model and for a model of the user's (DynamicLinearOscillator), the models it is compiled for.
//
//   const SettledMotion m = SimulateSettled(p, x0, phi, SettleOptions{});
//   if (m.Completed() && m.period > 0) use(m.section);
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "stickslip/model/oscillator_model.hpp"
#include "stickslip/model/pascal_2014.hpp"
#include "stickslip/model/pascal_2014/flows.hpp"
#include "stickslip/model/pascal_2014/parameters.hpp"
#include "stickslip/model/simulation.hpp"

namespace stickslip {

struct SettleOptions {
  // Forcing periods simulated and discarded (0 to kMaxTransientPeriods), in chunks of 1000.
  int transient_periods = 200;
  int recorded_periods = 20;  // forcing periods recorded (>= 1)
  // Section points repeat when |X - Y|_inf <= periodicity_tolerance (absolute; relative_tolerance:
  // times the largest |component| of the section's states or the contact's excursion over the
  // record, for a model in physical units, whose lengths and speeds have a scale of their own).
  double periodicity_tolerance = 1e-6;
  // The simulator's guard against chattering, per simulation (per transient chunk).
  int max_events_per_simulation = 1000000;
  bool relative_tolerance = false;
  // Forcing periods per transient chunk, whose events and segments are held at once (>= 1).
  int chunk_periods = 1000;
  // A model without forcing: the time that counts as a "period" (> 0; the slowest free oscillation's
  // 2 pi/omega_1 for a model of the user's): the transient is transient_periods of it; the record
  // holds recorded_periods stick entries within 10 recorded_periods of it.
  double time_unit = 0.0;
};

template <typename Model>
struct BasicSettledMotion {
  using State = typename Model::State;
  // The section after the transient: the states at t = k 2 pi/omega, k = 1..recorded_periods,
  // time 0 being the end of the transient. Empty when the simulation stopped early.
  std::vector<State> section;
  // Stops and sticks per forcing period, counted over the largest whole number of least periods
  // (`period`) the record holds, so that a motion of period p gives multiples of 1/p; over the
  // whole record when no period was found.
  double stops_per_period = 0.0;
  double sticks_per_period = 0.0;
  // Smallest p <= recorded/2 with section[k + p] == section[k] (to tolerance); 0 if none, or if the
  // section drifts across the record by more than the tolerance (steps below it add up: a large
  // motion that friction wears down by a constant amount per cycle) and not by steps shrinking
  // geometrically towards an orbit no farther than it moved (judged where a phase holds two p-steps
  // or more: p <= (recorded - 1)/2). Reduced to
  // a divisor d of p when the section is contracting onto a period-d motion (a slowly converging
  // orbit whose multiplier is near a (p/d)-th root of unity returns nearer after p periods than
  // after d): the d-step differences shrink, and fit within twice the distance the p-step ones
  // say is still to go (the p-step differences shrinking by 1 % at least across the record).
  int period = 0;
  // That distance still to go (absolute, |.|_inf), where the period was reduced or the section still
  // contracts onto its period by more than the tolerance across the record; 0 otherwise.
  double settling = 0.0;
  // max |q_c(t)| of the contact's coordinate q_c (the paper's x2) over the recorded periods, exact as
  // orbits/orbit_measures.hpp's amplitude: over each recorded segment, the extrema of q_c on its
  // closed form (at its ends or at the zeros of q_c', found by the root finder that cannot miss
  // one); q_c held in a stick. NaN when the simulation stopped early or the search for a zero was
  // cut short.
  double contact_amplitude = std::numeric_limits<double>::quiet_NaN();
  // The recorded periods (events and segments), from the end of the transient at t = 0.
  BasicSimulationResult<Model> record;
  // Where the motion got to: the last section state, or where a simulation stopped early.
  State last = FixedSizeDefault<State>();
  SimulationEnd end = SimulationEnd::kDuration;
  std::string message;  // why a simulation stopped early, if one did
  bool Completed() const { return end == SimulationEnd::kDuration; }
};

using SettledMotion = BasicSettledMotion<Pascal2014>;

// From `start` at t = 0 (forcing phase phi_section) at p. A model without forcing (Autonomous()) is
// read on its stick-entry section: the state at each stick entry, the period in stick-slip cycles,
// stops and sticks per cycle; where the record holds fewer than two stick entries, on the state
// every time_unit with stops and sticks per time unit, and a period only where nothing happens (a
// steady slide, or a contact stuck throughout: its velocity is the belt's; period 1). Preconditions: model.Validate(p) passed, options in range (the callers check
// them); throws InvalidInput for time_unit <= 0 without forcing. A simulation that stops early (max
// events, the event search's bound) is reported in `end` and `message`, not thrown. Compiled for
// Pascal2014 and DynamicLinearOscillator.
template <OscillatorModel Model>
BasicSettledMotion<Model> SimulateSettled(const Model& model, const typename Model::Parameters& p,
                                          const typename Model::State& start, double phi_section,
                                          const SettleOptions& options);

// The paper's model's.
SettledMotion SimulateSettled(const Parameters& p, const State& start, double phi_section, const SettleOptions& options);

}  // namespace stickslip
