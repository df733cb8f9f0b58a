#include "stickslip/continuation/branch_switching.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/SVD>
#include <fmt/format.h>

namespace stickslip {

Eigen::VectorXd UnitDirection(const Eigen::VectorXd& v) {
  const double squared = v.squaredNorm();
  if (squared >= std::numeric_limits<double>::min() && std::isfinite(squared)) return v / std::sqrt(squared);
  return v.stableNormalized();
}

BranchPointDirections SecondBranchDirection(const NonlinearSystem& problem, const Eigen::VectorXd& u,
                                            const Eigen::VectorXd& known_tangent) {
  const int n = problem.EquationCount();
  if (problem.UnknownCount() != n + 1 || n < 1 || u.size() != n + 1 || known_tangent.size() != n + 1) {
    throw std::invalid_argument(fmt::format(
        "branch switching needs n >= 1 equations in n + 1 unknowns and a point and tangent of that size: {} "
        "equations, {} unknowns, point {}, tangent {}",
        n, problem.UnknownCount(), u.size(), known_tangent.size()));
  }
  if (!(known_tangent.allFinite() && known_tangent.cwiseAbs().maxCoeff() > 0.0)) {
    throw std::invalid_argument("branch switching needs a finite nonzero tangent of the known branch");
  }
  Eigen::VectorXd residual;
  JacobianMatrix jacobian;
  problem.Evaluate(u, &residual, &jacobian);
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(ToDense(jacobian), Eigen::ComputeFullV);
  // The right singular vectors of the two smallest singular values (the (n+1)-th is zero: J has
  // one column more than rows) span the null space at a branch point.
  const Eigen::VectorXd a = svd.matrixV().col(n - 1), b = svd.matrixV().col(n);
  const Eigen::VectorXd t = UnitDirection(known_tangent);
  // The known tangent is (to rounding) alpha a + beta b; the second direction is orthogonal to it
  // in that plane.
  const double alpha = a.dot(t), beta = b.dot(t);
  if (!(std::hypot(alpha, beta) > 0.5)) {
    throw std::invalid_argument(fmt::format(
        "branch switching: the known tangent lies off the null space of the Jacobian (its part there is {:.3g}): "
        "no branch point of this branch",
        std::hypot(alpha, beta)));
  }
  BranchPointDirections result;
  result.second = (-beta * a + alpha * b).normalized();
  const Eigen::VectorXd& sigma = svd.singularValues();
  result.singularity = sigma(0) > 0.0 ? sigma(n - 1) / sigma(0) : 0.0;
  return result;
}

}  // namespace stickslip
