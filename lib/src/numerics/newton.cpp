#include "stickslip/numerics/newton.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace stickslip {

const char* ToString(NewtonTermination t) {
  switch (t) {
    case NewtonTermination::kConverged: return "converged";
    case NewtonTermination::kMaxIterations: return "max-iterations";
    case NewtonTermination::kSingularJacobian: return "singular-jacobian";
    case NewtonTermination::kDiverged: return "diverged";
    case NewtonTermination::kLeftDomain: return "left-domain";
    case NewtonTermination::kLineSearchFailed: break;
  }
  return "line-search-failed";
}

std::string NewtonSummary::BriefReport() const {
  // A condition number is >= 1 where it was estimated; 0 is "not estimated" and is left out.
  return fmt::format("{} after {} iteration(s), residual {:.3e}{}{}{}", ToString(termination), iterations,
                     residual_norms.empty() ? 0.0 : residual_norms.back(),
                     condition_number > 0.0 ? fmt::format(", condition {:.3e}", condition_number) : "",
                     message.empty() ? "" : ": ", message);
}

namespace {

double MaxNorm(const Eigen::VectorXd& v) { return v.size() ? v.lpNorm<Eigen::Infinity>() : 0.0; }

// A backtracking line search along a Newton step: its last trial, the largest fraction 1, 1/2, ...
// of the step whose max|F| is below the current one, or damping below min_damping where none is.
struct LineSearch {
  double damping = 1.0;
  Eigen::VectorXd trial;
  Eigen::VectorXd residual;
  double norm = 0.0;
  // The full step's Jacobian, evaluated with its residual: the full step is nearly always taken,
  // and its Jacobian serves the next iteration or the caller at the root, so that no residual is
  // evaluated twice. Empty after a damped trial.
  std::optional<JacobianMatrix> jacobian;
  std::optional<std::string> domain_error;  // of the last trial
};

LineSearch SearchAlong(const NonlinearSystem& system, const Eigen::VectorXd& u, const Eigen::VectorXd& step,
                       double norm, double min_damping) {
  LineSearch s;
  while (true) {
    s.trial = u + s.damping * step;
    s.domain_error = system.DomainError(s.trial);
    if (!s.domain_error) {
      const bool full = s.damping == 1.0;
      JacobianMatrix j;
      system.Evaluate(s.trial, &s.residual, full ? &j : nullptr);
      s.jacobian = full ? std::optional<JacobianMatrix>(std::move(j)) : std::nullopt;
      s.norm = MaxNorm(s.residual);
      if (std::isfinite(s.norm) && s.norm < norm) return s;
    }
    s.damping *= 0.5;
    if (s.damping < min_damping) return s;
  }
}

}  // namespace

NewtonResult SolveNewton(const NonlinearSystem& system, const Eigen::VectorXd& guess,
                         const NewtonOptions& options) {
  if (system.EquationCount() != system.UnknownCount() || guess.size() != system.UnknownCount()) {
    throw std::invalid_argument(fmt::format(
        "Newton needs a square system and a guess of its size: {} equations, {} unknowns, guess {}",
        system.EquationCount(), system.UnknownCount(), guess.size()));
  }
  NewtonResult result{guess, {}, std::nullopt};
  NewtonSummary& summary = result.summary;
  auto finish = [&](NewtonTermination t, std::string message, const JacobianMatrix* jacobian) {
    summary.termination = t;
    summary.message = std::move(message);
    if (options.estimate_condition && jacobian != nullptr) {
      summary.condition_number = ConditionNumber(*jacobian);
    }
    return result;
  };
  if (auto error = system.DomainError(result.solution)) {
    return finish(NewtonTermination::kLeftDomain, *error, nullptr);
  }
  const std::unique_ptr<LinearSolver> solver = LinearSolver::Create(options.linear_solver);
  Eigen::VectorXd residual;
  JacobianMatrix jacobian;
  system.Evaluate(result.solution, &residual, &jacobian);
  double norm = MaxNorm(residual);
  summary.residual_norms.push_back(norm);
  while (true) {
    if (!std::isfinite(norm)) {
      return finish(NewtonTermination::kDiverged, "the residual is not finite", nullptr);
    }
    if (norm <= options.residual_tolerance) {
      result.jacobian = jacobian;
      return finish(NewtonTermination::kConverged, "", &jacobian);
    }
    if (summary.iterations >= options.max_iterations) {
      return finish(NewtonTermination::kMaxIterations,
                    fmt::format("no convergence in {} iterations", options.max_iterations),
                    &jacobian);
    }
    if (!solver->Factorize(jacobian)) {
      return finish(NewtonTermination::kSingularJacobian,
                    "the Jacobian is singular to working precision", &jacobian);
    }
    const Eigen::VectorXd step = -solver->Solve(residual);
    LineSearch search = SearchAlong(system, result.solution, step, norm, options.min_damping);
    ++summary.iterations;
    if (search.damping < options.min_damping) {
      if (search.domain_error) return finish(NewtonTermination::kLeftDomain, *search.domain_error, &jacobian);
      // Near a singular Jacobian (a branch point) rounding stops the descent above the
      // tolerance; a residual this small is still a solution.
      if (norm <= options.stagnation_residual) {
        result.jacobian = jacobian;  // the solution did not move
        return finish(NewtonTermination::kConverged, "at the rounding floor", &jacobian);
      }
      return finish(NewtonTermination::kLineSearchFailed,
                    fmt::format("no step along the Newton direction lowers |F| = {:.3e}", norm),
                    &jacobian);
    }
    result.solution = std::move(search.trial);
    residual = std::move(search.residual);
    norm = search.norm;
    summary.residual_norms.push_back(norm);
    const bool step_below_tolerance =
        MaxNorm(search.damping * step) <= options.step_tolerance * (1.0 + MaxNorm(result.solution)) &&
        norm <= options.stagnation_residual;
    const bool full_step = search.jacobian.has_value();
    if (full_step) jacobian = std::move(*search.jacobian);
    if (norm <= options.residual_tolerance || step_below_tolerance) {
      // The full step brought its Jacobian at the root; a damped one did not, and it is evaluated
      // only for the condition number.
      const bool condition = options.estimate_condition;
      if (condition && !full_step) system.Evaluate(result.solution, &residual, &jacobian);
      if (condition || full_step) result.jacobian = jacobian;
      return finish(NewtonTermination::kConverged, step_below_tolerance ? "step below tolerance" : "",
                    condition || full_step ? &jacobian : nullptr);
    }
    if (!full_step) system.Evaluate(result.solution, &residual, &jacobian);
  }
}

}  // namespace stickslip
