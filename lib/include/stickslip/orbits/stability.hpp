// Stability of a periodic orbit: the monodromy matrix of the stroboscopic (period) map as the
// product of the closed-form flow Jacobians of the segments and the saltation (jump) matrices
// at each switching event (Leine & Nijmeijer, Dynamics and Bifurcations of Non-Smooth
// Mechanical Systems, 2004), and its Floquet multipliers.
//
// At an event h(x, t) = 0 from vector field f- to f+ the saltation matrix is
//   S = I + (f+ - f-) grad(h)^T / (grad(h) . f- + dh/dt).
// At a stop h = x2' (a reversal, or the entry into a stick, where S annihilates the perturbation
// of x2' and a multiplier 0 appears); at a stick exit h = s -+ eta u_r (eq. 11); an abnormal stop
// keeps the vector field, S = I.
#pragma once

#include <array>
#include <complex>
#include <limits>

#include <Eigen/Core>

#include "stickslip/orbits/orbit.hpp"

namespace stickslip {

struct Stability {
  Eigen::Matrix4d monodromy = Eigen::Matrix4d::Identity();  // from t = 0 to the period
  std::array<std::complex<double>, 4> multipliers{};        // by decreasing modulus
  bool stable = false;                                      // every |multiplier| < 1
  // Test functions of the smooth bifurcations, continuous along a branch:
  double fold_test = 0.0;   // det(M - I): a multiplier through +1 (LP)
  double flip_test = 0.0;   // det(M + I): a multiplier through -1 (PD)
  double torus_test = 0.0;  // prod_{i<j} (mu_i mu_j - 1): a complex pair on the unit circle (TR)
  // Antisymmetric orbits only (NaN for the others): det(I - M_half) = det(H + I), where H =
  // -M_half is the half-period map followed by the mirror X -> -X, and M = H^2. Zero where a
  // multiplier of H passes -1: a symmetry-breaking pitchfork (SB), where the orbit's
  // non-antisymmetric twins branch off. M then has a multiplier +1 without a fold of the branch,
  // and det(M + I) = |det(H - iI)|^2 cannot change sign, so no other test sees it.
  double symmetry_test = std::numeric_limits<double>::quiet_NaN();
  // An abnormal stop is a grazing of x2' = 0: perturbations on one side cross zero and stick
  // for an instant, so the period map has only one-sided derivatives there. The multipliers are
  // those of the side that keeps x2' off zero (S = I at the abnormal stop).
  bool one_sided = false;
};

// The saltation matrix at the end of listed or mirrored segment with mode `before`, followed by
// `after`, at state x (x2' = 0) and forcing phase `phase`.
Eigen::Matrix4d SaltationMatrix(Mode before, Mode after, const State& x, double phase, const Parameters& p);

Stability StabilityOf(const Orbit& orbit);

}  // namespace stickslip
