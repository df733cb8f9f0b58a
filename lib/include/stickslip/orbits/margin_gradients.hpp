// Exact gradients of the admissibility margins (margins.hpp) with respect to every orbit variable,
// the full variable vector of orbit.hpp (x10, x20, v10, phi, d1..dn, chi, eta, omega, u_s, u_r):
// forward-mode AD through the segment walk (segment_walk.hpp) and the margin templates. What a
// two-parameter continuation of a type boundary adds to the periodicity system: margin = 0.
//
// A margin at a segment end depends on the variables through the end state and phase. A margin
// at an interior minimum of a function f(tau) of the time tau elapsed in its segment (velocity:i,
// G:i, G1:i) has, by the envelope theorem, the gradient of f at the fixed tau* (f_tau = 0 there),
// and tau* moves with d tau*/dv = -(d f_tau/dv) / f_tau_tau. A continuation that keeps tau* as an
// unknown adds f_tau = 0: `slope`, its gradient at fixed tau and `curvature` are that equation, at
// any tau (MarginGradientAt; branches/margin_condition.hpp).
#pragma once

#include <vector>

#include <Eigen/Core>

#include "stickslip/orbits/margins.hpp"
#include "stickslip/orbits/orbit.hpp"

namespace stickslip {

struct MarginGradient {
  double value = 0.0;          // the margin, evaluated along the AD walk (AdmissibilityMargins' to rounding)
  Eigen::RowVectorXd d_value;  // d value / d variables
  double t = 0.0;              // where it is attained, from the orbit's origin (Margin::t)
  Eigen::RowVectorXd d_t;      // d t / d variables
  bool interior = false;       // an interior minimum in time: the fields below apply
  double slope = 0.0;          // f_tau at tau*: zero up to rounding
  Eigen::RowVectorXd d_slope;  // d f_tau / d variables at fixed tau
  double curvature = 0.0;      // f_tau_tau at tau*, > 0 at a minimum
};

// One per margin of AdmissibilityMargins(orbit), in its order. Where a margin is +inf (a slip
// with no interior minimum of its velocity) its gradients are zero.
std::vector<MarginGradient> MarginGradients(const Orbit& orbit);

// An interior margin's function at the time `tau` elapsed in its segment, any tau, not only its
// minimum: velocity:i's sign(x2') x2' in slip i, G:i's G = s + eta u_r and G1:i's G1 = -s + eta u_r
// in stick i (eq. 35). value = f(tau), slope = f_tau(tau), curvature = f_tau_tau(tau), d_value and
// d_slope their gradients at fixed tau, t = the segment's start + tau and d_t the start's gradient;
// interior = true. MarginGradients evaluates the same function at the root finder's tau* (and
// corrects d_t for tau*'s motion). `margin` is one of AdmissibilityMargins(o) for an orbit o of
// orbit's signature, of kind kSlipVelocity or kStickConstraint; else std::invalid_argument.
MarginGradient MarginGradientAt(const Orbit& orbit, const Margin& margin, double tau);

}  // namespace stickslip
