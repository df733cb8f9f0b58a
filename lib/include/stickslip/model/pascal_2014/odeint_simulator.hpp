// The independent cross-check of the closed form (Pascal 2014, eqs. 2-4, 9, 11), for the paper's
// model: eq. (2) integrated numerically mode by mode with Boost.Odeint (odeint_simulation.hpp,
// the simulator for any model), from the vector field and holding force Pascal2014 writes out from
// the equations of motion, with the simulator's own Coulomb decision. It shares no flow or event
// code with flows.hpp / events.hpp, so that an agreement between the two is evidence for both.
//
// Example:
//   const Parameters p{0.3, 4.0, 0.6, 0.1, 0.2996};
//   const SimulationResult exact = SimulateExact(p, x0, phi, {.duration = 50.0});
//   const SimulationResult numeric = SimulateOdeint(p, x0, phi, {.duration = 50.0});
//   // same event sequence; event times and states agree to ~1e-10
#pragma once

#include <string>

#include "stickslip/model/pascal_2014/flows.hpp"
#include "stickslip/model/pascal_2014/parameters.hpp"
#include "stickslip/model/odeint_options.hpp"
#include "stickslip/model/simulation.hpp"

namespace stickslip {

// Reference simulator: eq. (2) integrated mode by mode with a controlled dense-output
// runge_kutta_dopri5; each event located by bisection on the dense output, then the
// integration restarts in the next mode (never across a switch).
//
// Events are found from sign changes of the event function between accepted steps (x2' in a
// slip; s - eta u_r and s + eta u_r in a stick, s of eq. 11), so a zero touched tangentially
// (a grazing, or an abnormal stop) is seen only if rounding happens to make it a crossing.
// Throws InvalidInput for bad input (Validate(p) fails, x0, phi or the options not finite,
// duration <= 0, sample_step < 0, invalid `odeint`). A slip started from rest that does not move
// in its direction ends the simulation with SimulationEnd::kStuckAtRest.
SimulationResult SimulateOdeint(const Parameters& p, const State& x0, double phi,
                                const SimulationOptions& options, const OdeintOptions& odeint = {});

// One mode only, no events: the state after time s from `start` at forcing phase `phase`
// (forcing cos(omega*tau + phase), tau elapsed) — the reference for the closed-form flows.
// The stick integrates eq. (9) as written (x2'' = 0), so x2 drifts if start(3) != 0.
// Throws InvalidInput if s < 0 or s is not finite.
State IntegrateMode(Mode mode, const State& start, double phase, double s, const Parameters& p,
                    const OdeintOptions& odeint = {});

// The flow of one mode and its first derivatives by integrating the variational equations with
// Boost.Odeint (state, 4x4 transition matrix, sensitivities to the phase and the five
// parameters: 44 equations) — the reference for FlowWithDerivatives, and the Odeint path of the
// continuation benchmark. Only the FlowDerivatives type is shared with flows.hpp: the vector
// field is Pascal2014::VectorField (written from eq. 2), its derivatives are written out here.
// d_elapsed is the vector field at the end point; the u_r column of d_parameters is zero (u_r
// enters no mode's equations).
// Throws InvalidInput if s < 0 or s is not finite, or if `odeint` is invalid.
FlowDerivatives IntegrateModeWithDerivatives(Mode mode, const State& start, double phase, double s,
                                             const Parameters& p, const OdeintOptions& odeint = {});

}  // namespace stickslip
