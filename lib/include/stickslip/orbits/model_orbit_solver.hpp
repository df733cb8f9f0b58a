// SolveOrbit (orbit_solver.hpp) for any model (model/oscillator_model.hpp): Newton on the orbit's
// periodicity equations in the chosen unknowns, from a guess. The paper's model's is compiled once
// (orbit_solver.cpp); a program or test solving another model's orbits includes this header.
#pragma once

#include <utility>
#include <vector>

#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/orbits/model_orbit_problem.hpp"
#include "stickslip/orbits/orbit_solver.hpp"

namespace stickslip {

// Throws InvalidInput naming "free" if `free` does not make the system square.
template <OscillatorModel Model>
BasicOrbitSolution<Model> SolveOrbit(const Model& model, const OrbitOfModel<Model>& guess, const std::vector<int>& free,
                                     bool tie_static_friction, const OrbitSolverOptions& options = {}) {
  const Shooting shooting =
      ResolveShooting(options.shooting, guess.signature.size(), options.max_single_shooting_segments);
  const BasicPeriodicityEquations<Model> equations(model, guess.signature, shooting);
  const Eigen::VectorXd start = VariablesOf(equations, guess);
  const ModelOrbitProblem<Model> problem(BasicOrbitSystem<Model>(equations, start, free, tie_static_friction));
  if (problem.EquationCount() != problem.UnknownCount()) {
    throw InvalidInput("free", fmt::format("{} unknowns", problem.UnknownCount()),
                       fmt::format("{} unknowns, as many as the equations", problem.EquationCount()));
  }
  NewtonOptions newton = options.newton;
  if (shooting == Shooting::kMultiple && newton.linear_solver == LinearSolverType::kDenseLu) {
    newton.linear_solver = options.sparse_solver;
  }
  NewtonResult result = SolveNewton(problem, problem.Unknowns(start), newton);
  return {problem.OrbitOfModelAt(result.solution), std::move(result.summary), shooting};
}

}  // namespace stickslip
