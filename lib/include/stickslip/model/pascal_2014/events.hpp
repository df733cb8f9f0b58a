// Event functions of the nonsmooth motion (Pascal 2014, eqs. 4, 11, 35): a stop is x2' = 0; a
// stick lasts while the force s = chi eta (x2 - x1) - cos(omega t + phi) satisfies
// |s| < eta u_r, i.e. while G = s + eta u_r and G1 = -s + eta u_r stay positive.
#pragma once

#include <cmath>

#include "stickslip/model/pascal_2014/flows.hpp"
#include "stickslip/numerics/sinusoid_sum.hpp"

namespace stickslip {

// s of eq. (11): eta times the friction force that holds m2 at rest (eq. 4). `phase` is the absolute forcing phase omega t + phi.
template <typename T>
T StickForce(const StateT<T>& x, const T& phase, const BasicParameters<T>& p) {
  using std::cos;
  return p.chi * p.eta * (x(1) - x(0)) - cos(phase);
}

// G and G1 of eq. (35): a stick needs both >= 0. Leaving at G = 0 starts a slip with x2' > 0,
// leaving at G1 = 0 a slip with x2' < 0 (ERRATA, eq. 4 and 11).
template <typename T>
T StickConstraintG(const StateT<T>& x, const T& phase, const BasicParameters<T>& p) {
  return StickForce(x, phase, p) + p.eta * p.u_r;
}
template <typename T>
T StickConstraintG1(const StateT<T>& x, const T& phase, const BasicParameters<T>& p) {
  return -StickForce(x, phase, p) + p.eta * p.u_r;
}

// ds/dt of eq. (11) along a motion: chi eta (x2' - x1') + omega sin(psi). With m2 at rest (a
// stick, a stop) it is the transversality of a stick exit; at an abnormal stop, where x2'' = 0,
// x2''' = -ds/dt (the derivative of x2'' of eq. 2).
template <typename T>
T StickForceRate(const StateT<T>& x, const T& phase, const BasicParameters<T>& p) {
  using std::sin;
  return p.chi * p.eta * (x(3) - x(2)) + p.omega * sin(phase);
}

// The state with x2' = 0: m2 at rest, as during a stick or at a stop, where the equations hold
// x2' at zero and a computed state carries rounding in it.
template <typename T>
StateT<T> AtRest(StateT<T> x) {
  x(3) = T(0.0);
  return x;
}

// Coulomb's law at rest (eq. 4): the mode m2 takes from a state with x2' = 0 at `phase`. It
// sticks while |s| < eta u_r; on the threshold itself it leaves only if s is moving outwards.
Mode ModeFromRest(const State& x, double phase, const Parameters& p);

// Coordinate i of the state (0..3: x1, x2, x1', x2') along a mode motion, as a function of the
// elapsed time.
SinusoidSum CoordinateAlong(const ModeMotion<double>& motion, int i);

// The stick force s of eq. (11) along a mode motion that starts at forcing phase `phase`.
SinusoidSum StickForceAlong(const ModeMotion<double>& motion, double phase, const Parameters& p);

}  // namespace stickslip
