#include "stickslip/orbits/periodicity.hpp"

#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"

namespace stickslip {

namespace ov = orbit_variables;

const char* ToString(Shooting s) { return s == Shooting::kSingle ? "single" : "multiple"; }

Eigen::VectorXd PeriodicityEquations::Variables(const Orbit& orbit) const {
  Eigen::VectorXd v(VariableCount());
  const int full = ov::Count(signature().size());
  v.head(full) = ov::Pack(orbit);
  if (shooting() == Shooting::kMultiple) {
    const std::vector<State> states = orbit.SegmentStates();
    for (int i = 1; i < signature().size(); ++i) v.segment<4>(full + 4 * (i - 1)) = states[i];
  }
  return v;
}

OrbitSystem::OrbitSystem(const Orbit& reference, std::vector<int> free, bool tie_static_friction,
                         Shooting shooting, FlowEvaluator flow)
    : equations_(reference.signature, shooting, flow), reference_(equations_.Variables(reference)),
      free_(std::move(free)), tie_static_friction_(tie_static_friction) {
  const int n = reference.signature.size();
  for (int index : free_) {
    if (index < 0 || index >= ov::Count(n)) {
      throw InvalidInput("free", index, fmt::format("a variable index, 0 <= index < {}", ov::Count(n)));
    }
    if (tie_static_friction_ && index == ov::Parameter(n, ParameterId::kStaticFriction)) {
      throw InvalidInput::WithMessage("free", "free = 'u_r' is tied to u_s (u_r = u_s): release u_s instead");
    }
  }
}

int OrbitSystem::UnknownCount() const {
  return static_cast<int>(free_.size()) + equations_.VariableCount() -
         ov::Count(equations_.signature().size());
}

Eigen::VectorXd OrbitSystem::Variables(const Eigen::VectorXd& u) const {
  const int n = equations_.signature().size();
  const int full = ov::Count(n);
  Eigen::VectorXd v = reference_;
  for (std::size_t k = 0; k < free_.size(); ++k) v(free_[k]) = u(static_cast<int>(k));
  v.tail(v.size() - full) = u.tail(u.size() - static_cast<int>(free_.size()));
  if (tie_static_friction_) {
    v(ov::Parameter(n, ParameterId::kStaticFriction)) = v(ov::Parameter(n, ParameterId::kSlidingFriction));
  }
  return v;
}

void OrbitSystem::Evaluate(const Eigen::VectorXd& u, Eigen::VectorXd* residual,
                           JacobianMatrix* jacobian) const {
  Eigen::MatrixXd full_jacobian;
  equations_.Evaluate(Variables(u), residual, jacobian ? &full_jacobian : nullptr);
  if (!jacobian) return;
  Eigen::MatrixXd j = ToUnknowns(full_jacobian);
  if (equations_.shooting() == Shooting::kMultiple) {
    *jacobian = SparseMatrix(j.sparseView());
  } else {
    *jacobian = std::move(j);
  }
}

Eigen::MatrixXd OrbitSystem::ToUnknowns(const Eigen::MatrixXd& d_variables) const {
  const int n = equations_.signature().size();
  const int full = ov::Count(n);
  const int states = static_cast<int>(d_variables.cols()) - full;  // the multiple-shooting states', if given
  const int u_s = ov::Parameter(n, ParameterId::kSlidingFriction);
  const int u_r = ov::Parameter(n, ParameterId::kStaticFriction);
  Eigen::MatrixXd j = Eigen::MatrixXd::Zero(d_variables.rows(), UnknownCount());
  for (std::size_t k = 0; k < free_.size(); ++k) {
    j.col(static_cast<int>(k)) = d_variables.col(free_[k]);
    if (tie_static_friction_ && free_[k] == u_s) j.col(static_cast<int>(k)) += d_variables.col(u_r);
  }
  j.rightCols(states) = d_variables.rightCols(states);
  return j;
}

std::optional<std::string> OrbitSystem::DomainError(const Eigen::VectorXd& u) const {
  const Orbit orbit = ToOrbit(u);
  if (const auto invalid = ValidateClosedForm(orbit.parameters)) return invalid->what();
  return std::nullopt;
}

Eigen::VectorXd OrbitSystem::Unknowns(const Orbit& orbit) const {
  const Eigen::VectorXd v = equations_.Variables(orbit);
  const int full = ov::Count(orbit.signature.size());
  Eigen::VectorXd u(UnknownCount());
  for (std::size_t k = 0; k < free_.size(); ++k) u(static_cast<int>(k)) = v(free_[k]);
  u.tail(u.size() - static_cast<int>(free_.size())) = v.tail(v.size() - full);
  return u;
}

Orbit OrbitSystem::ToOrbit(const Eigen::VectorXd& u) const {
  const int full = ov::Count(equations_.signature().size());
  return ov::Unpack(equations_.signature(), Variables(u).head(full));
}

}  // namespace stickslip
