// An orbit as the problem a curve's condition asks (orbits/orbit_problem.hpp): single shooting
// with every full variable an unknown, so that the problem's unknowns are the orbit's full
// variables (ov::Pack for the paper's model) and a test can differentiate in each.
#pragma once

#include <numeric>
#include <vector>

#include "stickslip/orbits/model_orbit_problem.hpp"
#include "stickslip/orbits/orbit.hpp"

namespace stickslip {

template <OscillatorModel Model>
ModelOrbitProblem<Model> ProblemAt(const Model& model, const BasicOrbit<Model>& orbit) {
  const BasicPeriodicityEquations<Model> equations(model, orbit.signature, Shooting::kSingle);
  std::vector<int> every(static_cast<std::size_t>(equations.FullCount()));
  std::iota(every.begin(), every.end(), 0);
  return ModelOrbitProblem<Model>(BasicOrbitSystem<Model>(equations, VariablesOf(equations, orbit), every, false));
}
inline ModelOrbitProblem<Pascal2014> ProblemAt(const Orbit& orbit) { return ProblemAt(Pascal2014{}, orbit.OnModel()); }

}  // namespace stickslip
