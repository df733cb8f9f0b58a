#include "stickslip/orbits/stability.hpp"

#include <algorithm>

#include <Eigen/Eigenvalues>

#include "stickslip/model/events.hpp"
#include "stickslip/model/flows.hpp"
#include "stickslip/orbits/segment_walk.hpp"

namespace stickslip {

Eigen::Matrix4d SaltationMatrix(Mode before, Mode after, const State& x, double phase, const Parameters& p) {
  Eigen::Matrix4d s = Eigen::Matrix4d::Identity();
  if (before == after) return s;  // an abnormal stop: the vector field does not change
  // The two fields differ in x2'' only (x1'' does not feel the friction, eq. 2, 9).
  const double jump = Acceleration(after, x, phase, p)(1) - Acceleration(before, x, phase, p)(1);
  if (before != Mode::kStick) {
    // A stop, h = x2': grad h = e4, dh/dt = 0, grad h . f- = x2'' before the stop.
    s(3, 3) += jump / Acceleration(before, x, phase, p)(1);
    return s;
  }
  // A stick exit, h = chi eta (x2 - x1) - cos(omega t + phi) -+ eta u_r (eq. 11):
  // grad h = chi eta (-1, 1, 0, 0), and grad h . f- + dh/dt = ds/dt with m2 at rest.
  const double rate = StickForceRate(AtRest(x), phase, p);
  s(3, 0) -= jump * p.chi * p.eta / rate;
  s(3, 1) += jump * p.chi * p.eta / rate;
  return s;
}

Stability StabilityOf(const Orbit& orbit) {
  const Parameters& p = orbit.parameters;
  Stability result;
  // The whole period: the listed segments, then their mirror images for an antisymmetric orbit,
  // flowed from the actual states (the symmetry is not assumed).
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  int visited = 0;
  WalkSegments(orbit, Extent::kFullPeriod, PhaseRule::kAccumulated, [&](const SegmentVisit<double>& s) {
    result.one_sided = result.one_sided || s.spec.end == SegmentEndKind::kAbnormalStop;
    m = SaltationMatrix(s.spec.mode, s.spec.next, s.end, s.end_phase, p) * TransitionMatrix(s.spec.mode, s.duration, p) * m;
    if (++visited == orbit.signature.size() && orbit.signature.antisymmetric()) {
      result.symmetry_test = (Eigen::Matrix4d::Identity() - m).determinant();
    }
  });
  result.monodromy = m;
  const Eigen::EigenSolver<Eigen::Matrix4d> eigen(m, /*computeEigenvectors=*/false);
  for (int k = 0; k < 4; ++k) result.multipliers[k] = eigen.eigenvalues()(k);
  std::sort(result.multipliers.begin(), result.multipliers.end(), [](const auto& a, const auto& b) {
    if (std::abs(a) != std::abs(b)) return std::abs(a) > std::abs(b);
    return a.imag() > b.imag();
  });
  result.stable = std::abs(result.multipliers[0]) < 1.0;
  result.fold_test = (m - Eigen::Matrix4d::Identity()).determinant();
  result.flip_test = (m + Eigen::Matrix4d::Identity()).determinant();
  std::complex<double> torus = 1.0;
  for (int i = 0; i < 4; ++i) {
    for (int j = i + 1; j < 4; ++j) torus *= result.multipliers[i] * result.multipliers[j] - 1.0;
  }
  result.torus_test = torus.real();
  return result;
}

}  // namespace stickslip
