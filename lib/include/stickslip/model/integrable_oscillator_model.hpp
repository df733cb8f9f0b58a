// What a numerical integrator needs of a model beyond oscillator_model.hpp: the equations of
// motion themselves, and what its own Coulomb decision at rest needs. The closed forms of an
// OscillatorModel solve these equations; an integrator that asks only for what is listed here
// (and the pointwise members: contact velocity, state at rest, static threshold, forcing
// frequency) shares no flow or event code with them, so that the two simulators' agreement is
// evidence for both (odeint_simulation.hpp).
//
// What a model provides in addition, written from its equations of motion:
//   - the vector field in a mode at a state and a forcing phase (the forcing is cos(phase)): the
//     state's derivative, with the kinetic friction in a slip and the contact held at rest in a
//     stick;
//   - the holding force: the friction force a stick needs at a state and phase, the same
//     quantity as StickForce and signed the same way (s > threshold drives a slip with s < 0),
//     derived here from the equations of motion instead of taken from the closed forms' code;
//   - its rate of change while the contact is at rest, which decides on the threshold itself
//     (the stick is left only if s moves outwards);
//   - the size of the terms the holding force sums, against which its rounding is judged.
// The integrator keeps the state in a std::array, or a std::vector for a model whose size comes
// from a file.
#pragma once

#include <concepts>

#include <Eigen/Core>

#include "stickslip/model/mode.hpp"
#include "stickslip/model/oscillator_model.hpp"

namespace stickslip {

template <typename M>
concept IntegrableOscillatorModel =
    OscillatorModel<M> &&
    requires(const M& model, Mode mode, const typename M::State& x, const typename M::Parameters& p, double phase) {
      { model.VectorField(mode, x, phase, p) } -> std::same_as<typename M::State>;
      { model.HoldingForce(x, phase, p) } -> std::same_as<double>;
      { model.HoldingForceRate(x, phase, p) } -> std::same_as<double>;
      { model.HoldingForceScale(x, p) } -> std::same_as<double>;
    };

}  // namespace stickslip
