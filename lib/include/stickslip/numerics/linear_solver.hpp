// Linear solves for Newton and continuation: a small strategy with a dense LU for small systems
// and SuiteSparse (KLU, UMFPACK) for the block-sparse Jacobians of multiple shooting.
#pragma once

#include <memory>
#include <optional>
#include <string_view>
#include <variant>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace stickslip {

using SparseMatrix = Eigen::SparseMatrix<double>;
// A Jacobian is dense or sparse; each linear solver accepts both.
using JacobianMatrix = std::variant<Eigen::MatrixXd, SparseMatrix>;

int Rows(const JacobianMatrix& j);
Eigen::MatrixXd ToDense(const JacobianMatrix& j);

enum class LinearSolverType { kDenseLu, kKlu, kUmfpack };
const char* ToString(LinearSolverType type);  // "dense", "klu", "umfpack"
std::optional<LinearSolverType> LinearSolverFromString(std::string_view text);

class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  // Factorizes a square matrix; false if it is singular to working precision.
  virtual bool Factorize(const JacobianMatrix& matrix) = 0;
  virtual Eigen::VectorXd Solve(const Eigen::VectorXd& rhs) const = 0;
  // Sign of the determinant of the factorized matrix (+1, -1; 0 if singular), as needed to
  // detect branch points.
  virtual int DeterminantSign() const = 0;

  static std::unique_ptr<LinearSolver> Create(LinearSolverType type);
};

// Estimate of the 2-norm condition number sigma_max/sigma_min (SVD of the dense matrix; the
// systems here have at most a few dozen unknowns). Infinity when singular.
double ConditionNumber(const JacobianMatrix& matrix);

}  // namespace stickslip
