#include "stickslip/orbits/slip_resonance.hpp"

namespace stickslip {

std::optional<SlipResonance> NearestSlipResonance(const Orbit& orbit) {
  return NearestSlipResonance(Pascal2014{}, orbit.OnModel());
}

}  // namespace stickslip
