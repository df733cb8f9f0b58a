// Den Hartog's undamped forced mass (k = m = 1, force amplitude 1; F_k, F_s and v_b are parameters)
// as a model of the user's at run-time size, whose non-sticking orbit den_hartog_orbit.hpp gives in
// closed form.
#pragma once

#include "stickslip/model/chain.hpp"
#include "stickslip/model/linear_oscillator.hpp"

namespace stickslip {

inline DynamicLinearOscillator DenHartogsMass() {
  Chain chain;
  chain.masses = {1.0};
  chain.springs = {{0, kGround, 1.0}};
  chain.forcing = {1.0};
  return DynamicLinearOscillator(ChainData(chain));
}

}  // namespace stickslip
