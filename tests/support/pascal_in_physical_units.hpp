// M. Pascal's two masses in physical units, as the general linear oscillator
// (model/linear_oscillator.hpp): m1 = eta m2, k1 + k2 = S, k2 = chi S, forcing F0 cos on mass 2
// and the contact on mass 2 with mu_k N = u_s eta F0, mu_s N = u_r eta F0. The paper's scaling
// (../shared/FRICTION-LITERATURE.md): t = t~ / Omega with Omega = sqrt(S/m1), omega~ = omega Omega,
// y = eta F0 x / S.
#pragma once

#include <cmath>

#include <Eigen/Core>

#include "stickslip/model/linear_oscillator.hpp"
#include "stickslip/orbits/orbit.hpp"

namespace stickslip {

struct PhysicalTwoMasses {
  double m2 = 2.0, stiffness_sum = 5.0, f0 = 3.0;

  LinearOscillatorData Data(const Parameters& p) const {
    LinearOscillatorData data;
    data.mass = Eigen::Vector2d(p.eta * m2, m2).asDiagonal();
    const double k2 = p.chi * stiffness_sum;
    data.stiffness = (Eigen::Matrix2d() << stiffness_sum, -k2, -k2, k2).finished();
    data.forcing = Eigen::Vector2d(0.0, f0);
    return data;
  }
  double Omega(const Parameters& p) const { return std::sqrt(stiffness_sum / (p.eta * m2)); }
  double Length(const Parameters& p) const { return p.eta * f0 / stiffness_sum; }
  template <typename Model = LinearOscillator<2>>
  typename Model::Parameters Of(const Parameters& p) const {
    return {p.omega * Omega(p), p.u_s * p.eta * f0, p.u_r * p.eta * f0};
  }
};

// The paper's orbit in the physical units of `physical`, as an orbit of the model at a fixed size
// or at a size read with its data (DynamicLinearOscillator).
template <typename Model = LinearOscillator<2>>
BasicOrbit<Model> InPhysicalUnits(const Orbit& o, const PhysicalTwoMasses& physical) {
  const Parameters& p = o.parameters;
  const double length = physical.Length(p), omega = physical.Omega(p);
  BasicOrbit<Model> converted{o.signature, physical.Of<Model>(p), typename Model::State(length * o.InitialState()),
                              o.phi, {}};
  converted.start.tail(2) *= omega;
  for (double d : o.durations) converted.durations.push_back(d / omega);
  return converted;
}

}  // namespace stickslip
