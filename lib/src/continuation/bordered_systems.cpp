#include "bordered_systems.hpp"

#include <vector>

namespace stickslip::detail {

namespace {

JacobianMatrix RemoveColumn(const JacobianMatrix& j, int column) {
  if (const auto* dense = std::get_if<Eigen::MatrixXd>(&j)) {
    Eigen::MatrixXd m(dense->rows(), dense->cols() - 1);
    m << dense->leftCols(column), dense->rightCols(dense->cols() - column - 1);
    return m;
  }
  const SparseMatrix& s = std::get<SparseMatrix>(j);
  std::vector<Eigen::Triplet<double>> triplets;
  for (int k = 0; k < s.outerSize(); ++k) {
    if (k == column) continue;
    for (SparseMatrix::InnerIterator it(s, k); it; ++it) {
      triplets.emplace_back(it.row(), k < column ? k : k - 1, it.value());
    }
  }
  SparseMatrix m(s.rows(), s.cols() - 1);
  m.setFromTriplets(triplets.begin(), triplets.end());
  return m;
}

}  // namespace

JacobianMatrix AppendRow(const JacobianMatrix& j, const Eigen::VectorXd& row) {
  if (const auto* dense = std::get_if<Eigen::MatrixXd>(&j)) {
    Eigen::MatrixXd m(dense->rows() + 1, dense->cols());
    m << *dense, row.transpose();
    return m;
  }
  const SparseMatrix& s = std::get<SparseMatrix>(j);
  std::vector<Eigen::Triplet<double>> triplets;
  for (int k = 0; k < s.outerSize(); ++k) {
    for (SparseMatrix::InnerIterator it(s, k); it; ++it) triplets.emplace_back(it.row(), it.col(), it.value());
  }
  for (int c = 0; c < row.size(); ++c) {
    if (row(c) != 0.0) triplets.emplace_back(static_cast<int>(s.rows()), c, row(c));
  }
  SparseMatrix m(s.rows() + 1, s.cols());
  m.setFromTriplets(triplets.begin(), triplets.end());
  return m;
}

Eigen::VectorXd FixedParameterSystem::Expand(const Eigen::VectorXd& v) const {
  Eigen::VectorXd u = full_;
  u.head(parameter_) = v.head(parameter_);
  u.tail(u.size() - parameter_ - 1) = v.tail(v.size() - parameter_);
  return u;
}

Eigen::VectorXd FixedParameterSystem::Reduce(const Eigen::VectorXd& u) const {
  Eigen::VectorXd v(u.size() - 1);
  v << u.head(parameter_), u.tail(u.size() - parameter_ - 1);
  return v;
}

void FixedParameterSystem::Evaluate(const Eigen::VectorXd& v, Eigen::VectorXd* residual,
                                    JacobianMatrix* jacobian) const {
  JacobianMatrix full_jacobian;
  problem_.Evaluate(Expand(v), residual, jacobian ? &full_jacobian : nullptr);
  if (jacobian) *jacobian = RemoveColumn(full_jacobian, parameter_);
}

void BorderedSystem::Evaluate(const Eigen::VectorXd& u, Eigen::VectorXd* residual, JacobianMatrix* jacobian) const {
  Eigen::VectorXd f;
  JacobianMatrix j;
  problem_.Evaluate(u, &f, jacobian ? &j : nullptr);
  residual->resize(f.size() + 1);
  *residual << f, tangent_.dot(u - reference_) - s_;
  if (jacobian) *jacobian = AppendRow(j, tangent_);
}

}  // namespace stickslip::detail
