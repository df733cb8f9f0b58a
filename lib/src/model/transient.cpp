#include "stickslip/model/transient.hpp"

namespace stickslip {

Transient SimulateTransient(const Simulator& simulate, const Parameters& p, const State& x0, double phi,
                            const TransientOptions& options) {
  return SimulateTransientAt(p.omega, simulate, p, x0, phi, options);
}

}  // namespace stickslip
