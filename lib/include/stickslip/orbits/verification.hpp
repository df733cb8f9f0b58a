// Independent verification of a computed orbit: one period simulated from its initial state by
// the exact simulator and by the Boost.Odeint simulator. The event sequence must equal the
// signature, the state must come back, and the events must fall where the orbit says.
#pragma once

#include <string>
#include <vector>

#include "stickslip/model/flows.hpp"
#include "stickslip/orbits/orbit.hpp"

namespace stickslip {

// Odeint locates events by sign changes and cannot see an abnormal stop (a tangency of x2' to
// zero); its sequence is compared with consecutive equal modes merged.
struct SimulatorCheck {
  std::vector<Mode> modes;               // segment modes the simulation went through
  bool sequence_matches = false;         // == the signature over a whole period
  double periodicity_mismatch = 0.0;     // max |X(T) - X(0)|
  double max_event_time_difference = 0.0;  // against the orbit's segment ends (when matching)
};

struct Verification {
  std::vector<Mode> expected;  // the signature over a whole period
  // Why the orbit could not be simulated (parameters outside the physical range, say u_s <= 0
  // where Newton converged past the family's end, or a simulation that stopped early); empty
  // when both simulators ran over the whole period.
  std::string not_simulated;
  SimulatorCheck exact;
  SimulatorCheck odeint;
  // Thresholds: the exact flows carry rounding only; Odeint integrates at 1e-12 tolerances.
  static constexpr double kExactTolerance = 1e-9;
  static constexpr double kOdeintTolerance = 1e-6;
  bool Passed() const;
  std::string Report() const;  // one line per simulator, or why there was no simulation
};

Verification VerifyOrbit(const Orbit& orbit);

}  // namespace stickslip
