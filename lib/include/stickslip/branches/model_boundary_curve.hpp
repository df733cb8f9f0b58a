// BoundaryCurve (boundary_curve.hpp) for any model: the curve's condition made at the start through
// the model's orbit problem (orbits/model_orbit_problem.hpp), then the setup of the branch with the
// second parameter released. The paper's model and a [model]'s are compiled once, in
// boundary_curve.cpp; a program or test following another model's curves includes this header.
#pragma once

#include <string_view>

#include <Eigen/Core>

#include "stickslip/branches/boundary_curve.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/orbits/any_orbit.hpp"
#include "stickslip/orbits/model_orbit_problem.hpp"

namespace stickslip {

template <OscillatorModel Model>
BasicOrbitContinuationSetup<Model> BoundaryCurve(const BasicCurveStart<Model>& start,
                                                 const BasicOrbitContinuationSetup<Model>& branch_setup,
                                                 std::string_view second) {
  const BasicOrbit<Model>& orbit = AsBasicOrbit(start.orbit);
  const Model& model = branch_setup.model;
  const OrbitVariableSet variables = VariableSetOf(model, orbit.signature);
  const int unvaried = model.Autonomous() ? variables.layout.Parameter(Model::kForcingFrequencyParameter) : -1;
  CheckSecondParameter(variables.layout, variables.static_level, unvaried, start.unknowns, start.parameter, second);
  // An autonomous orbit's monodromy always has the multiplier 1 (a shift along the orbit in time):
  // M - I is singular along the whole family, and its condition would hold at every orbit.
  if (model.Autonomous() && start.condition == "LP") {
    throw InvalidInput("condition", "LP of an orbit without forcing",
                       "a type change's margin, PD, SB or TR (its fold is no multiplier +1: one always is, the "
                       "shift along the orbit in time)");
  }
  // The condition asks the orbit through a problem at the start with no unknowns: what it keeps
  // depends on the model and the signature only, not on the curve's unknowns.
  const BasicPeriodicityEquations<Model> equations(model, orbit.signature, Shooting::kSingle,
                                                   branch_setup.flow);
  const ModelOrbitProblem<Model> at_start(BasicOrbitSystem<Model>(equations, VariablesOf(equations, orbit), {}, false));
  BasicOrbitContinuationSetup<Model> setup = branch_setup;
  setup.condition = MakeCurveCondition(start.condition, at_start, Eigen::VectorXd());
  setup.start = start.orbit;
  setup.unknowns = start.unknowns;
  setup.unknowns.release.emplace_back(second);
  setup.unknowns.condition_equations = setup.condition->EquationCount() - setup.condition->ExtraUnknownCount();
  setup.parameter = start.parameter;
  // The curve ends where a second margin reaches zero: a codimension-two point.
  setup.options.continue_past_terminal = false;
  return setup;
}

}  // namespace stickslip
