#include "stickslip/continuation/augmented_system.hpp"

#include <variant>
#include <vector>

namespace stickslip {

void AugmentedSystem::Evaluate(const Eigen::VectorXd& u, Eigen::VectorXd* residual, JacobianMatrix* jacobian) const {
  const int n = base_.UnknownCount();
  const int m = base_.EquationCount();
  const int k = extra_.UnknownCount();
  const int g = extra_.EquationCount();
  const Eigen::VectorXd head = u.head(n);
  const Eigen::VectorXd tail = u.tail(k);
  Eigen::VectorXd f;
  JacobianMatrix base_jacobian;
  base_.Evaluate(head, &f, jacobian ? &base_jacobian : nullptr);
  Eigen::VectorXd extra_residual;
  Eigen::MatrixXd d_u;
  Eigen::MatrixXd d_e;
  extra_.Evaluate(head, tail, &extra_residual, jacobian ? &d_u : nullptr, jacobian ? &d_e : nullptr);
  residual->resize(m + g);
  *residual << f, extra_residual;
  if (!jacobian) return;
  if (const auto* dense = std::get_if<Eigen::MatrixXd>(&base_jacobian)) {
    Eigen::MatrixXd j = Eigen::MatrixXd::Zero(m + g, n + k);
    j.topLeftCorner(m, n) = *dense;
    j.bottomLeftCorner(g, n) = d_u;
    j.bottomRightCorner(g, k) = d_e;
    *jacobian = std::move(j);
    return;
  }
  const SparseMatrix& sparse = std::get<SparseMatrix>(base_jacobian);
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(sparse.nonZeros() + g * (n + k)));
  for (int c = 0; c < sparse.outerSize(); ++c) {
    for (SparseMatrix::InnerIterator it(sparse, c); it; ++it) entries.emplace_back(it.row(), it.col(), it.value());
  }
  for (int r = 0; r < g; ++r) {
    for (int c = 0; c < n; ++c) entries.emplace_back(m + r, c, d_u(r, c));
    for (int c = 0; c < k; ++c) entries.emplace_back(m + r, n + c, d_e(r, c));
  }
  SparseMatrix j(m + g, n + k);
  j.setFromTriplets(entries.begin(), entries.end());
  *jacobian = std::move(j);
}

std::optional<std::string> AugmentedSystem::DomainError(const Eigen::VectorXd& u) const {
  return base_.DomainError(u.head(base_.UnknownCount()));
}

}  // namespace stickslip
