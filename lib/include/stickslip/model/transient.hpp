// Transients simulated out: the state after a whole number of forcing periods, simulated in
// chunks so that neither memory nor any one simulation's max_events grows with their number.
// After k whole periods the forcing cos(omega t + phi) has its phase phi again, so the state at
// t = k 2 pi/omega starts the rest of the motion with the same phi and time counted on from there.
//
//   TransientOptions o;
//   o.periods = 500;
//   const Transient settled = SimulateTransient(SimulateExact, p, x0, phi, o);
//   // settled.state is the state at t = 500 * 2 pi / omega
#pragma once

#include <functional>
#include <string>

#include "stickslip/model/simulation.hpp"

namespace stickslip {

// The largest number of transient periods (as for simulate --periods and sweep --transients).
inline constexpr int kMaxTransientPeriods = 1000000;

struct TransientOptions {
  int periods = 0;  // forcing periods simulated and discarded, 0 to kMaxTransientPeriods
  // At most this many periods per simulation (>= 1): each chunk's events and segments are
  // dropped before the next.
  int chunk_periods = 1000;
  // max_events and zeros per chunk; progress with done and total counted over the whole
  // transient (periods). duration and sample_step are set here.
  SimulationOptions simulation;

  void Validate() const;  // throws InvalidInput naming the first field out of range
};

struct Transient {
  State state = State::Zero();  // at t = periods * 2 pi / omega, or where the simulation stopped
  double t = 0.0;               // ... that time
  SimulationEnd end = SimulationEnd::kDuration;
  std::string message;  // why a chunk stopped early, if one did
  bool Completed() const { return end == SimulationEnd::kDuration; }
};

// SimulateExact or SimulateOdeint.
using Simulator = std::function<SimulationResult(const Parameters&, const State&, double, const SimulationOptions&)>;

// The transient from x0 at t = 0 (forcing phase phi). Throws InvalidInput for options out of
// range; the preconditions of the simulator otherwise.
Transient SimulateTransient(const Simulator& simulate, const Parameters& p, const State& x0, double phi,
                            const TransientOptions& options);

}  // namespace stickslip
