#include "stickslip/orbits/margin_gradients.hpp"

namespace stickslip {

std::vector<MarginGradient> MarginGradients(const Orbit& orbit) { return MarginGradients(Pascal2014{}, orbit.OnModel()); }

MarginGradient MarginGradientAt(const Orbit& orbit, const Margin& margin, double tau) {
  return MarginGradientAt(Pascal2014{}, orbit.OnModel(), margin, tau);
}

}  // namespace stickslip
