// An orbit of any model with one of its variables moved by h, for central differences: the
// variables in the periodicity equations' order (orbits/periodicity_equations.hpp), the start
// state but the contact's velocity, phi, the durations, then the parameters (for the test model,
// den_hartog_oscillator.hpp: x0, phi, the durations, omega, beta, beta_static, v_b).
#pragma once

#include "stickslip/orbits/orbit.hpp"

namespace stickslip {

template <typename Model>
BasicOrbit<Model> PerturbedOrbit(const Model& model, BasicOrbit<Model> o, int index, double h) {
  const int n = o.signature.size(), start = model.StateSize() - 1;
  double& v = index < start        ? o.start(index)
              : index == start     ? o.phi
              : index < start + 1 + n ? o.durations[index - start - 1]
                                   : Model::ParameterAt(o.parameters, index - start - 1 - n);
  v += h;
  return o;
}

}  // namespace stickslip
