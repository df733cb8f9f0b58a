#include "stickslip/orbits/floquet_gradients.hpp"

namespace stickslip {

MonodromyGradient MonodromyGradients(const Orbit& orbit) { return MonodromyGradients(Pascal2014{}, orbit.OnModel()); }

}  // namespace stickslip
