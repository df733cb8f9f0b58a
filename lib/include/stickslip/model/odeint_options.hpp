// The Odeint simulators' accuracy (model/odeint_simulation.hpp for any model; the paper's model's
// variational integration in model/pascal_2014/odeint_simulator.hpp).
#pragma once

namespace stickslip {

struct OdeintOptions {
  double relative_tolerance = 1e-12;    // dopri5 error control
  double absolute_tolerance = 1e-12;
  double event_time_tolerance = 1e-12;  // bisection on the dense output
  // Throws InvalidInput naming the first field that is not finite and > 0.
  void CheckValid() const;
};

}  // namespace stickslip
