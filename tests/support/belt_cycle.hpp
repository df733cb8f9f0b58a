// One mass on a moving belt without forcing (autonomous: self-excited stick-slip), its data as the
// general linear oscillator, and its undamped stick-slip cycle in closed form
// (../shared/FRICTION-LITERATURE.md; omega_n = sqrt(k/m), d = (F_s - F_k)/k):
//   T_stick = 2 (F_s - F_k)/(k v_b), T_slip = (pi + 2 atan(v_b/(omega_n d)))/omega_n,
//   the stick from the re-stick at x = (2 F_k - F_s)/k, the slip about F_k/k with radius
//   sqrt(d^2 + (v_b/omega_n)^2).
#pragma once

#include <cmath>
#include <numbers>

#include <Eigen/Core>

#include "stickslip/model/linear_oscillator.hpp"
#include "stickslip/orbits/orbit.hpp"

namespace stickslip {

struct BeltCycle {
  double m = 1.0, k = 1.0, F_s = 1.5, F_k = 1.0, v_b = 0.2;

  double w() const { return std::sqrt(k / m); }
  double d() const { return (F_s - F_k) / k; }
  double Stick() const { return 2.0 * d() / v_b; }
  double Slip() const { return (std::numbers::pi + 2.0 * std::atan(v_b / (w() * d()))) / w(); }
  double Restick() const { return (2.0 * F_k - F_s) / k; }
  double Radius() const { return std::hypot(d(), v_b / w()); }

  // The mass on the belt with viscous damping c (the closed forms above are the undamped ones).
  LinearOscillatorData Data(double c = 0.0) const {
    LinearOscillatorData data;
    data.mass = Eigen::MatrixXd::Constant(1, 1, m);
    data.stiffness = Eigen::MatrixXd::Constant(1, 1, k);
    data.damping = Eigen::MatrixXd::Constant(1, 1, c);
    data.forcing = Eigen::VectorXd::Zero(1);
    return data;
  }
  // The undamped cycle as the orbit 'stick slip-' from the re-stick (omega plays no part: 1).
  BasicOrbit<LinearOscillator<1>> Orbit() const {
    return {Signature::Parse("stick slip-"), {1.0, F_k, F_s, v_b}, {Restick(), v_b}, 0.0, {Stick(), Slip()}};
  }
};

}  // namespace stickslip
