// The orbit found for a user's model (analysis/model_orbit_finder.hpp) as one JSON object: what
// `stickslip find --model --json` prints and the Python module's find(model=...) returns. Keys:
// status, message, signature (read off the motion, or null) and orbit (null unless Newton
// converged): signature, parameters by name, period, phi, start (by the model's start-state names:
// x1_0 and v1_0 for a coordinate x1, m1_0 and v_m1_0 for m1), durations, iterations, residual_norm, margins by name, admissible, multipliers
// ([re, im] pairs), stable, measures (amplitude:<coordinate>, peak-to-peak:<coordinate>,
// stick-fraction, stops, sticks, friction-work, equivalent-damping) and verification
// (VerificationJson). Non-finite numbers are null.
#pragma once

#include <string>

#include "stickslip/analysis/model_orbit_finder.hpp"
#include "stickslip/model/linear_oscillator.hpp"
#include "stickslip/orbits/verification.hpp"

namespace stickslip {

std::string ModelFindJson(const DynamicLinearOscillator& model, const ModelFindResult<DynamicLinearOscillator>& found);

// An orbit's verification by both simulators, of any model: passed, not_simulated, expected, exact
// and odeint (events, sequence_matches, max_mismatch, max_event_time_difference).
std::string VerificationJson(const Verification& verification);

}  // namespace stickslip
