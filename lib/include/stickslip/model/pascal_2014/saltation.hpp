// The saltation (jump) matrices of the paper's model at its events (Leine & Nijmeijer, Dynamics
// and Bifurcations of Non-Smooth Mechanical Systems, 2004): at an event h(x, t) = 0 from vector
// field f- to f+,
//   S = I + (f+ - f-) grad(h)^T / (grad(h) . f- + dh/dt).
// At a stop h = x2' (a reversal, or the entry into a stick, where S annihilates the perturbation
// of x2' and a multiplier 0 appears); at a stick exit h = s -+ eta u_r (eq. 11); an abnormal stop
// keeps the vector field, S = I. The monodromy (orbits/stability.hpp) multiplies them with the
// flows' transition matrices (flows.hpp).
#pragma once

#include "stickslip/model/pascal_2014/events.hpp"
#include "stickslip/model/pascal_2014/flows.hpp"
#include "stickslip/model/mode.hpp"
#include "stickslip/model/pascal_2014/parameters.hpp"

namespace stickslip {

// The saltation matrix at the end of a segment with mode `before`, followed by `after`, at state
// x (x2' = 0) and forcing phase `phase`. Templated on the scalar: forward-mode AD through the
// monodromy gives its exact derivatives.
template <typename T>
Matrix4<T> SaltationMatrix(Mode before, Mode after, const StateT<T>& x, const T& phase, const BasicParameters<T>& p) {
  Matrix4<T> s = Matrix4<T>::Identity();
  if (before == after) return s;  // an abnormal stop: the vector field does not change
  // The two fields differ in x2'' only (x1'' does not feel the friction, eq. 2, 9).
  const T jump = Acceleration(after, x, phase, p)(1) - Acceleration(before, x, phase, p)(1);
  if (before != Mode::kStick) {
    // A stop, h = x2': grad h = e4, dh/dt = 0, grad h . f- = x2'' before the stop.
    s(3, 3) += jump / Acceleration(before, x, phase, p)(1);
    return s;
  }
  // A stick exit, h = chi eta (x2 - x1) - cos(omega t + phi) -+ eta u_r (eq. 11):
  // grad h = chi eta (-1, 1, 0, 0), and grad h . f- + dh/dt = ds/dt with m2 at rest.
  const T rate = StickForceRate(AtRest(x), phase, p);
  s(3, 0) -= jump * p.chi * p.eta / rate;
  s(3, 1) += jump * p.chi * p.eta / rate;
  return s;
}

}  // namespace stickslip
