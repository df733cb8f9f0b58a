#include "stickslip/orbits/stability.hpp"

#include <algorithm>

#include <Eigen/Eigenvalues>

#include "stickslip/model/flows.hpp"

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
  // grad h = chi eta (-1, 1, 0, 0), and grad h . f- + dh/dt = -chi eta x1' + omega sin(phase).
  const double rate = -p.chi * p.eta * x(2) + p.omega * std::sin(phase);
  s(3, 0) -= jump * p.chi * p.eta / rate;
  s(3, 1) += jump * p.chi * p.eta / rate;
  return s;
}

Stability StabilityOf(const Orbit& orbit) {
  const Parameters& p = orbit.parameters;
  const Signature& signature = orbit.signature;
  // The whole period: the listed segments, then their mirror images for an antisymmetric orbit,
  // flowed from the actual states (the symmetry is not assumed).
  std::vector<Mode> modes = signature.FullPeriod();
  const std::vector<double> durations = orbit.FullPeriodDurations();
  Stability result;
  State x = orbit.InitialState();
  double phase = orbit.phi;
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  for (std::size_t i = 0; i < modes.size(); ++i) {
    x = Flow(modes[i], x, phase, durations[i], p);
    phase += p.omega * durations[i];
    const Mode next = modes[(i + 1) % modes.size()];
    result.one_sided = result.one_sided || next == modes[i];
    m = SaltationMatrix(modes[i], next, x, phase, p) * TransitionMatrix(modes[i], durations[i], p) * m;
  }
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
