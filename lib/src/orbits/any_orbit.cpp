#include "stickslip/orbits/any_orbit.hpp"

namespace stickslip {

double OrbitDistance(const Orbit& a, const Orbit& b) {
  return OrbitDistance(Pascal2014{}, AsBasicOrbit(a), AsBasicOrbit(b));
}

}  // namespace stickslip
