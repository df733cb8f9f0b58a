// MakeOrbitContinuation and ToOrbitBranch (orbit_continuation.hpp) for any model: the model's
// orbit problem built (orbits/model_orbit_problem.hpp) and erased, then assembled as every
// model's is. The paper's model is compiled once, in orbit_continuation.cpp; a program or test
// continuing another model includes this header.
#pragma once

#include <memory>
#include <type_traits>
#include <utility>

#include "stickslip/branches/orbit_continuation.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/orbits/model_orbit_problem.hpp"

namespace stickslip {

template <OscillatorModel Model>
OrbitContinuationProblem MakeOrbitContinuation(const BasicOrbitContinuationSetup<Model>& setup) {
  CheckResonanceLimits(setup.max_amplitude, setup.resonance_approach);
  const Signature& signature = setup.start.signature;
  OrbitContinuationParts parts(VariableSetOf(setup.model, signature));
  parts.free = FreeIndices(parts.variables, setup.unknowns);
  parts.tie_static_friction = setup.unknowns.tie_static_friction;
  parts.parameter = ContinuedVariable(parts.variables, parts.free, parts.tie_static_friction, setup.parameter);
  std::vector<int> unknowns = parts.free;
  unknowns.push_back(parts.parameter);
  const BasicPeriodicityEquations<Model> equations(setup.model, signature,
                                                   ResolveShooting(setup.shooting, signature.size()), setup.flow);
  parts.start = VariablesOf(equations, setup.start);
  parts.system = std::make_unique<ModelOrbitProblem<Model>>(
      BasicOrbitSystem<Model>(equations, parts.start, std::move(unknowns), parts.tie_static_friction));
  if constexpr (std::is_same_v<Model, Pascal2014>) {
    parts.condition = setup.condition;
    if (setup.condition) parts.condition_start = setup.condition->ExtraUnknowns(setup.start);
  } else if (setup.condition) {
    throw InvalidInput::WithMessage("condition", "condition: curves in two parameters are continued for the paper's "
                                                 "model only");
  }
  parts.parameter_name = setup.parameter;
  parts.options = setup.options;
  parts.sparse_solver = setup.sparse_solver;
  parts.unwatched = setup.unwatched;
  return AssembleOrbitContinuation(std::move(parts));
}

template <OscillatorModel Model>
BasicOrbitBranch<Model> ToOrbitBranch(const OrbitContinuationProblem& problem, Branch branch) {
  BasicOrbitBranch<Model> result;
  result.shooting = problem.system->shooting();
  result.columns = problem.monitor->Columns();
  result.branch = std::move(branch);
  const ModelOrbitProblem<Model>& system = ModelProblemOf<Model>(*problem.system);
  for (const BranchPoint& p : result.branch.points) result.orbits.push_back(system.OrbitOfModelAt(p.u));
  return result;
}

}  // namespace stickslip
