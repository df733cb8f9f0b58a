// Den Hartog's one-mass oscillator (Trans. ASME APM 53 (1931) 107) as the library's linear
// oscillator with one coordinate (model/linear_oscillator.hpp): m = k = 1, the forcing amplitude 1,
//   x'' + x = cos(omega t + phi) + F,  F = -beta sign(x') in a slip, |F| <= beta_static in a stick,
// so that omega is the frequency ratio r and F_k, F_s are the force ratios beta, beta_static of
// den_hartog_orbit.hpp's closed form. It replaced the model-interface issue's test-only toy model;
// the tests written for that model run on it unchanged.
#pragma once

#include <Eigen/Core>

#include "stickslip/model/linear_oscillator.hpp"

namespace stickslip {

inline LinearOscillatorData DenHartogData() {
  LinearOscillatorData data;
  data.mass = Eigen::MatrixXd::Ones(1, 1);
  data.stiffness = Eigen::MatrixXd::Ones(1, 1);
  data.forcing = Eigen::VectorXd::Ones(1);
  data.coordinates = {"x"};
  data.name = "den-hartog-1930";
  return data;
}

// The library's one-mass oscillator itself, not a type of its own.
using DenHartogOscillator = LinearOscillator<1>;
inline DenHartogOscillator DenHartogModel() { return DenHartogOscillator(DenHartogData()); }

}  // namespace stickslip
