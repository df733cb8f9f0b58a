#include "stickslip/numerics/linear_solver.hpp"

#include <cmath>
#include <limits>

#include <Eigen/LU>
#include <Eigen/SVD>
#include <Eigen/SparseLU>
#include <Eigen/KLUSupport>
#include <Eigen/UmfPackSupport>

namespace stickslip {

int Rows(const JacobianMatrix& j) {
  return std::visit([](const auto& m) { return static_cast<int>(m.rows()); }, j);
}

Eigen::MatrixXd ToDense(const JacobianMatrix& j) {
  if (const auto* dense = std::get_if<Eigen::MatrixXd>(&j)) return *dense;
  return Eigen::MatrixXd(std::get<SparseMatrix>(j));
}

const char* ToString(LinearSolverType type) {
  switch (type) {
    case LinearSolverType::kDenseLu: return "dense";
    case LinearSolverType::kKlu: return "klu";
    case LinearSolverType::kUmfpack: break;
  }
  return "umfpack";
}

std::optional<LinearSolverType> LinearSolverFromString(std::string_view text) {
  for (auto t : {LinearSolverType::kDenseLu, LinearSolverType::kKlu, LinearSolverType::kUmfpack}) {
    if (text == ToString(t)) return t;
  }
  return std::nullopt;
}

namespace {

SparseMatrix ToSparse(const JacobianMatrix& j) {
  if (const auto* sparse = std::get_if<SparseMatrix>(&j)) return *sparse;
  return std::get<Eigen::MatrixXd>(j).sparseView();
}

// Reciprocal condition below this counts as singular: beyond it a Newton step has no correct
// digit left.
constexpr double kSingularRcond = 1e-15;

class DenseLuSolver final : public LinearSolver {
 public:
  bool Factorize(const JacobianMatrix& matrix) override {
    lu_.compute(ToDense(matrix));
    // The pivots' spread bounds the condition from below; cheaper than an rcond estimate, which
    // would double the cost of the small systems solved at every continuation step.
    const auto pivots = lu_.matrixLU().diagonal().cwiseAbs();
    const double largest = pivots.maxCoeff();
    return std::isfinite(largest) && largest > 0.0 && pivots.minCoeff() > kSingularRcond * largest;
  }
  Eigen::VectorXd Solve(const Eigen::VectorXd& rhs) const override { return lu_.solve(rhs); }
  int DeterminantSign() const override {
    const double det = lu_.determinant();
    return det > 0.0 ? 1 : (det < 0.0 ? -1 : 0);
  }

 private:
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
};

// The two SuiteSparse solvers differ only in the Eigen wrapper; the determinant sign comes from
// Eigen's SparseLU, which both lack in a form that keeps the sign.
template <typename Factorization>
class SuiteSparseSolver final : public LinearSolver {
 public:
  bool Factorize(const JacobianMatrix& matrix) override {
    matrix_ = ToSparse(matrix);
    matrix_.makeCompressed();
    factorization_.compute(matrix_);
    if (factorization_.info() != Eigen::Success) return false;
    // SuiteSparse accepts nearly singular matrices; check the solution of a probe instead.
    const Eigen::VectorXd probe = Eigen::VectorXd::Ones(matrix_.rows());
    const Eigen::VectorXd x = factorization_.solve(probe);
    return x.allFinite() && x.norm() < 1.0 / kSingularRcond;
  }
  Eigen::VectorXd Solve(const Eigen::VectorXd& rhs) const override {
    return const_cast<Factorization&>(factorization_).solve(rhs);
  }
  int DeterminantSign() const override {
    Eigen::SparseLU<SparseMatrix> lu;
    lu.compute(matrix_);
    if (lu.info() != Eigen::Success) return 0;
    return static_cast<int>(lu.signDeterminant());
  }

 private:
  SparseMatrix matrix_;
  Factorization factorization_;
};

}  // namespace

std::unique_ptr<LinearSolver> LinearSolver::Create(LinearSolverType type) {
  switch (type) {
    case LinearSolverType::kDenseLu: return std::make_unique<DenseLuSolver>();
    case LinearSolverType::kKlu:
      return std::make_unique<SuiteSparseSolver<Eigen::KLU<SparseMatrix>>>();
    case LinearSolverType::kUmfpack: break;
  }
  return std::make_unique<SuiteSparseSolver<Eigen::UmfPackLU<SparseMatrix>>>();
}

double ConditionNumber(const JacobianMatrix& matrix) {
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(ToDense(matrix));
  const auto& s = svd.singularValues();
  if (s.size() == 0 || s(s.size() - 1) == 0.0) return std::numeric_limits<double>::infinity();
  return s(0) / s(s.size() - 1);
}

}  // namespace stickslip
