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
#include <span>
#include <vector>

#include <Eigen/Core>

#include "stickslip/model/events.hpp"
#include "stickslip/model/flows.hpp"
#include "stickslip/orbits/orbit.hpp"
#include "stickslip/orbits/segment_walk.hpp"

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
// `after`, at state x (x2' = 0) and forcing phase `phase`. Templated, as the monodromy below.
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

// The monodromy matrix of an orbit from its walk: the products of the segments' transition
// matrices and the saltation matrices at their ends. Templated on the scalar: forward-mode AD
// through it gives its exact derivatives (orbits/floquet_gradients.hpp).
template <typename T>
struct MonodromyT {
  Matrix4<T> period = Matrix4<T>::Identity();  // over the whole period
  // Over the listed segments: the half-period map of an antisymmetric orbit (the period's for the others).
  Matrix4<T> listed = Matrix4<T>::Identity();
  bool one_sided = false;  // an abnormal stop on the way (Stability::one_sided)
};
template <typename T>
MonodromyT<T> Monodromy(const Signature& signature, const StateT<T>& x0, const T& phi, std::span<const T> durations,
                        const BasicParameters<T>& p) {
  MonodromyT<T> result;
  // The whole period: the listed segments, then their mirror images for an antisymmetric orbit,
  // flowed from the actual states (the symmetry is not assumed).
  const std::vector<SegmentSpec> plan = SegmentPlan(signature, Extent::kFullPeriod);
  WalkSegments<T>(plan, x0, phi, durations, p, PhaseRule::kAccumulated, [&](const SegmentVisit<T>& s) {
    result.one_sided = result.one_sided || s.spec.end == SegmentEndKind::kAbnormalStop;
    result.period = SaltationMatrix(s.spec.mode, s.spec.next, s.end, s.end_phase, p) *
                    TransitionMatrix(s.spec.mode, s.duration, p) * result.period;
    if (s.index + 1 == signature.size()) result.listed = result.period;
  });
  return result;
}

Stability StabilityOf(const Orbit& orbit);

}  // namespace stickslip
