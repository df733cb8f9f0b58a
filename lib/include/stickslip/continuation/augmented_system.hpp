// A system extended by more equations in more unknowns: F(u) = 0 and G(u, e) = 0, in (u, e). How
// a curve of codimension-one points is continued in two parameters (AUTO's extra conditions,
// COCO's coco_add_func, BifurcationKit's minimally augmented problems): the extra equations say
// which degeneracy holds, the extra unknowns are what they need besides u (the time of an interior
// extremum, say). The engine continues the whole as any system; it knows nothing of what G means.
#pragma once

#include <optional>
#include <string>

#include <Eigen/Core>

#include "stickslip/numerics/newton.hpp"

namespace stickslip {

class ExtraEquations {
 public:
  virtual ~ExtraEquations() = default;
  virtual int UnknownCount() const = 0;   // the size of e
  virtual int EquationCount() const = 0;  // the size of G
  // G(u, e), and its exact derivatives dG/du (EquationCount x u.size()) and dG/de where the
  // pointers are not null.
  virtual void Evaluate(const Eigen::VectorXd& u, const Eigen::VectorXd& e, Eigen::VectorXd* residual,
                        Eigen::MatrixXd* d_u, Eigen::MatrixXd* d_e) const = 0;
};

// Unknowns (u, e): the base system's, then the extra ones; equations: F's, then G's. The Jacobian
// is dense or sparse as the base system's is. Both references must outlive the system.
class AugmentedSystem final : public NonlinearSystem {
 public:
  AugmentedSystem(const NonlinearSystem& base, const ExtraEquations& extra) : base_(base), extra_(extra) {}

  int EquationCount() const override { return base_.EquationCount() + extra_.EquationCount(); }
  int UnknownCount() const override { return base_.UnknownCount() + extra_.UnknownCount(); }
  void Evaluate(const Eigen::VectorXd& u, Eigen::VectorXd* residual, JacobianMatrix* jacobian) const override;
  std::optional<std::string> DomainError(const Eigen::VectorXd& u) const override;

 private:
  const NonlinearSystem& base_;
  const ExtraEquations& extra_;
};

}  // namespace stickslip
