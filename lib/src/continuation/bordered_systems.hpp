// The square systems the engine solves with Newton: the start corrected at a fixed parameter, and
// the pseudo-arclength corrector (Keller).
#pragma once

#include <optional>
#include <string>

#include <Eigen/Core>

#include "stickslip/numerics/newton.hpp"

namespace stickslip::detail {

// [J; row^T], dense or sparse as J is.
JacobianMatrix AppendRow(const JacobianMatrix& j, const Eigen::VectorXd& row);

// F with lambda held at its value in `full`: the square system that corrects the start point.
class FixedParameterSystem final : public NonlinearSystem {
 public:
  FixedParameterSystem(const NonlinearSystem& problem, Eigen::VectorXd full, int parameter)
      : problem_(problem), full_(std::move(full)), parameter_(parameter) {}
  int EquationCount() const override { return problem_.EquationCount(); }
  int UnknownCount() const override { return problem_.UnknownCount() - 1; }
  // The unknowns without lambda (Reduce) and back (Expand, with lambda from `full`).
  Eigen::VectorXd Expand(const Eigen::VectorXd& v) const;
  Eigen::VectorXd Reduce(const Eigen::VectorXd& u) const;
  void Evaluate(const Eigen::VectorXd& v, Eigen::VectorXd* residual, JacobianMatrix* jacobian) const override;
  std::optional<std::string> DomainError(const Eigen::VectorXd& v) const override {
    return problem_.DomainError(Expand(v));
  }

 private:
  const NonlinearSystem& problem_;
  Eigen::VectorXd full_;
  int parameter_;
};

// [F(u); t.(u - u_ref) - s]: the pseudo-arclength corrector (Keller).
class BorderedSystem final : public NonlinearSystem {
 public:
  BorderedSystem(const NonlinearSystem& problem, Eigen::VectorXd tangent, Eigen::VectorXd reference, double s)
      : problem_(problem), tangent_(std::move(tangent)), reference_(std::move(reference)), s_(s) {}
  int EquationCount() const override { return problem_.EquationCount() + 1; }
  int UnknownCount() const override { return problem_.UnknownCount(); }
  void Evaluate(const Eigen::VectorXd& u, Eigen::VectorXd* residual, JacobianMatrix* jacobian) const override;
  std::optional<std::string> DomainError(const Eigen::VectorXd& u) const override {
    return problem_.DomainError(u);
  }

 private:
  const NonlinearSystem& problem_;
  Eigen::VectorXd tangent_;
  Eigen::VectorXd reference_;
  double s_;
};

}  // namespace stickslip::detail
