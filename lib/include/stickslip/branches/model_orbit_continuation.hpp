// MakeOrbitContinuation and ToOrbitBranch (orbit_continuation.hpp) for any model: the model's
// orbit problem built (orbits/model_orbit_problem.hpp) and erased, then assembled as every
// model's is. The paper's model is compiled once, in orbit_continuation.cpp; a program or test
// continuing another model includes this header.
#pragma once

#include <algorithm>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>

#include "stickslip/branches/orbit_continuation.hpp"
#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/orbits/any_orbit.hpp"
#include "stickslip/orbits/model_orbit_problem.hpp"

namespace stickslip {

// An antisymmetric orbit (its second half the mirror -X of its first) is a motion only on a fixed
// surface: the mirror of a stick on a surface moving at v_b moves at -v_b. Throws InvalidInput naming
// "parameter" where the start's surface moves or its speed is continued or released; write the
// orbit over its whole period (signature_edits.hpp, Unfolded(orbit, 1)) to continue it there.
template <OscillatorModel Model>
void CheckSymmetryHolds(const Model& model, const OrbitOfModel<Model>& start, const OrbitContinuationParts& parts) {
  if constexpr (Model::kRestVelocityParameter >= 0) {
    if (!start.signature.antisymmetric()) return;
    const int speed = parts.variables.layout.Parameter(Model::kRestVelocityParameter);
    const bool varies = parts.parameter == speed || std::find(parts.free.begin(), parts.free.end(), speed) != parts.free.end();
    const double v = Model::ParameterAt(AsBasicOrbit(start).parameters, Model::kRestVelocityParameter);
    if (varies || v != 0.0) {
      const std::string name = model.Description().parameters[Model::kRestVelocityParameter].name;
      throw InvalidInput::WithMessage(
          "parameter", fmt::format("parameter: the antisymmetric '{}' is a motion only where {} = 0 (the mirror of a "
                                   "stick on a moving surface moves the other way): continue it written over its whole "
                                   "period",
                                   start.signature.ToString(), name));
    }
  } else {
    static_cast<void>(model), static_cast<void>(start), static_cast<void>(parts);
  }
}

template <OscillatorModel Model>
OrbitContinuationProblem MakeOrbitContinuation(const BasicOrbitContinuationSetup<Model>& setup) {
  CheckResonanceLimits(setup.max_amplitude, setup.resonance_approach);
  const Signature& signature = setup.start.signature;
  OrbitContinuationParts parts(VariableSetOf(setup.model, signature));
  parts.free = FreeIndices(parts.variables, setup.unknowns);
  parts.tie_static_friction = setup.unknowns.tie_static_friction;
  parts.parameter = ContinuedVariable(parts.variables, parts.free, parts.tie_static_friction, setup.parameter);
  CheckSymmetryHolds(setup.model, setup.start, parts);
  std::vector<int> unknowns = parts.free;
  unknowns.push_back(parts.parameter);
  const BasicPeriodicityEquations<Model> equations(setup.model, signature,
                                                   ResolveShooting(setup.shooting, signature.size()), setup.flow);
  parts.start = VariablesOf(equations, setup.start);
  parts.system = std::make_unique<ModelOrbitProblem<Model>>(
      BasicOrbitSystem<Model>(equations, parts.start, std::move(unknowns), parts.tie_static_friction));
  parts.condition = setup.condition;
  if (setup.condition) parts.condition_start = setup.condition->ExtraUnknowns(*parts.system, parts.system->Unknowns(parts.start));
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
