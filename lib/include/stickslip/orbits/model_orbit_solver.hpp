// SolveOrbit (orbit_solver.hpp) for any model (model/oscillator_model.hpp): Newton on the orbit's
// periodicity equations in the chosen unknowns, from a guess. The paper's model's is compiled once
// (orbit_solver.cpp); a program or test solving another model's orbits includes this header.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/numerics/minimum_norm_newton.hpp"
#include "stickslip/orbits/model_orbit_problem.hpp"
#include "stickslip/orbits/orbit_solver.hpp"

namespace stickslip {

// Whether the converged `found` lies on a family of orbits at fixed parameters: no direction of
// its null space moves a released parameter (the family would run through the parameters: the
// choice of unknowns is short of an equation), and a step along the null space, corrected by
// minimum-norm steps, converges to another orbit there (at an isolated singular orbit, a fold,
// the correction cannot come back along the null space and fails).
template <OscillatorModel Model>
bool FamilyAtFixedParameters(const ModelOrbitProblem<Model>& problem, const MinimumNormNewtonResult& found,
                             const MinimumNormNewtonOptions& options) {
  const int first_parameter = problem.FullCount() - problem.description().ParameterCount();
  const std::vector<int>& free = problem.free();
  for (std::size_t k = 0; k < free.size(); ++k) {
    if (free[k] >= first_parameter && found.null_space.row(static_cast<int>(k)).lpNorm<Eigen::Infinity>() > 1e-8) {
      return false;
    }
  }
  const Eigen::VectorXd& u = found.newton.solution;
  const double step = 1e-4 * (1.0 + u.lpNorm<Eigen::Infinity>());
  const MinimumNormNewtonResult other = SolveMinimumNorm(problem, u + step * found.null_space.col(0), options);
  return other.newton.summary.Converged() && (other.newton.solution - u).norm() > 0.5 * step;
}

// Where Newton met a singular Jacobian: the orbit nearest `guess` on a family of orbits at the
// guess's parameters, if minimum-norm steps converge to one (FamilyAtFixedParameters).
template <OscillatorModel Model>
std::optional<BasicOrbitSolution<Model>> OnAFamily(const ModelOrbitProblem<Model>& problem, const Eigen::VectorXd& guess,
                                                   Shooting shooting, const NewtonOptions& newton) {
  MinimumNormNewtonOptions options;
  options.max_iterations = newton.max_iterations;
  options.residual_tolerance = newton.residual_tolerance;
  MinimumNormNewtonResult family = SolveMinimumNorm(problem, guess, options);
  if (!family.newton.summary.Converged() || family.nullity == 0 || !FamilyAtFixedParameters(problem, family, options)) {
    return std::nullopt;
  }
  family.newton.summary.message = fmt::format(
      "not isolated: one of a {}-dimensional family of orbits at these parameters (the periodicity equations' "
      "Jacobian has nullity {} along it), the one nearest the guess",
      family.nullity, family.nullity);
  return BasicOrbitSolution<Model>{problem.OrbitOfModelAt(family.newton.solution), std::move(family.newton.summary),
                                   shooting, family.nullity};
}

// Throws InvalidInput naming "free" if `free` does not make the system square. Where Newton meets a
// singular Jacobian and the guess is near a family of orbits (not isolated), the family's member
// nearest it, with family_dimension set.
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
  if (result.summary.termination == NewtonTermination::kSingularJacobian) {
    if (std::optional<BasicOrbitSolution<Model>> family = OnAFamily(problem, problem.Unknowns(start), shooting, newton)) {
      return *std::move(family);
    }
  }
  return {problem.OrbitOfModelAt(result.solution), std::move(result.summary), shooting};
}

// The paper's model's, compiled once (orbit_solver.cpp).
extern template OrbitSolution SolveOrbit<Pascal2014>(const Pascal2014& model, const Orbit& guess,
                                                     const std::vector<int>& free, bool tie_static_friction,
                                                     const OrbitSolverOptions& options);

}  // namespace stickslip
