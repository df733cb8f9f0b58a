// Damped Newton's method for a square system F(u) = 0 with an exact Jacobian. It knows nothing
// of orbits: the orbit solver and the continuation corrector both use it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "stickslip/numerics/linear_solver.hpp"

namespace stickslip {

// A smooth system F: R^UnknownCount -> R^EquationCount with its Jacobian. Newton solves square
// ones; the continuation engine continues ones with one unknown more than equations.
class NonlinearSystem {
 public:
  virtual ~NonlinearSystem() = default;
  virtual int EquationCount() const = 0;
  virtual int UnknownCount() const = 0;
  // F(u), and J(u) (EquationCount x UnknownCount) when `jacobian` is not null. F(u) must not
  // depend on whether J is asked for: Newton takes a full step's residual from the evaluation
  // with its Jacobian and a damped step's from one without. (The closed-form flows give the same
  // numbers both ways; an integrator whose derivative path shares its error control does not
  // quite: the benchmark's Odeint evaluator.)
  virtual void Evaluate(const Eigen::VectorXd& u, Eigen::VectorXd* residual,
                        JacobianMatrix* jacobian) const = 0;
  // Why u lies outside the domain where F is defined (an invalid physical parameter, ...). A
  // query, not the error convention: Newton asks it of every trial point and steps back when it
  // answers; a caller's bad input is InvalidInput, thrown before solving.
  virtual std::optional<std::string> DomainError(const Eigen::VectorXd& u) const {
    (void)u;
    return std::nullopt;
  }
};

struct NewtonOptions {
  int max_iterations = 30;
  double residual_tolerance = 1e-12;  // converged when max|F| <= this
  double step_tolerance = 1e-13;      // ... or when the step is this small relative to |u| and
  double stagnation_residual = 1e-9;  //     max|F| is below this, or no step lowers a max|F|
                                      //     below this (the rounding floor near a singularity)
  double min_damping = 1.0 / 1024.0;  // smallest step fraction of the backtracking line search
  LinearSolverType linear_solver = LinearSolverType::kDenseLu;
  bool estimate_condition = true;     // condition number of the final Jacobian (an SVD)
};

enum class NewtonTermination {
  kConverged,
  kMaxIterations,
  kSingularJacobian,
  kDiverged,          // a non-finite residual
  kLeftDomain,        // an iterate left the system's domain
  kLineSearchFailed,  // no damped step reduced |F|
};
const char* ToString(NewtonTermination t);

struct NewtonSummary {
  NewtonTermination termination = NewtonTermination::kMaxIterations;
  std::string message;
  int iterations = 0;
  std::vector<double> residual_norms;  // max|F| at each iterate, the start included
  double condition_number = 0.0;       // of the Jacobian at the final iterate
  bool Converged() const { return termination == NewtonTermination::kConverged; }
  std::string BriefReport() const;
};

struct NewtonResult {
  Eigen::VectorXd solution;  // the last iterate (the root when converged)
  NewtonSummary summary;
  // Set only when converged, and only where the Jacobian at `solution` was evaluated anyway (at
  // the guess, or with a full step's residual; not after a damped step without the condition
  // number): what a caller would otherwise evaluate again at the root.
  std::optional<JacobianMatrix> jacobian;
};

NewtonResult SolveNewton(const NonlinearSystem& system, const Eigen::VectorXd& guess,
                         const NewtonOptions& options = {});

}  // namespace stickslip
