// The Jacobian of a system's residual by central differences: the independent check of an exact
// Jacobian. `Equations` has Evaluate(v, &residual, nullptr), as the periodicity equations do.
#pragma once

#include <Eigen/Core>

namespace stickslip {

template <typename Equations>
Eigen::MatrixXd CentralDifferenceJacobian(const Equations& equations, const Eigen::VectorXd& v, double h = 1e-6) {
  Eigen::MatrixXd jacobian;
  for (int k = 0; k < v.size(); ++k) {
    Eigen::VectorXd plus = v, minus = v, r_plus, r_minus;
    plus(k) += h;
    minus(k) -= h;
    equations.Evaluate(plus, &r_plus, nullptr);
    equations.Evaluate(minus, &r_minus, nullptr);
    if (k == 0) jacobian.resize(r_plus.size(), v.size());
    jacobian.col(k) = (r_plus - r_minus) / (2 * h);
  }
  return jacobian;
}

}  // namespace stickslip
