// An orbit of any model (model/oscillator_model.hpp) as a system in chosen unknowns, for Newton
// and the continuation engine: the full variables listed in `free` (in that order), then the
// multiple-shooting states; every other variable is held at the reference's value. With
// tie_static_friction the static friction level follows the kinetic one (u_r = u_s in the
// paper's model, needed by abnormal stops).
#pragma once

#include <algorithm>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/numerics/newton.hpp"
#include "stickslip/orbits/periodicity_equations.hpp"

namespace stickslip {

template <OscillatorModel Model>
class BasicOrbitSystem : public NonlinearSystem {
 public:
  using Equations = BasicPeriodicityEquations<Model>;

  // `reference`: the variables of Equations (full vector and multiple-shooting states). Throws
  // InvalidInput naming "free" for an index that is no variable, or the static level freed while
  // tied.
  BasicOrbitSystem(Equations equations, Eigen::VectorXd reference, std::vector<int> free, bool tie_static_friction)
      : equations_(std::move(equations)), reference_(std::move(reference)), free_(std::move(free)),
        tie_static_friction_(tie_static_friction) {
    const int full = equations_.FullCount();
    const std::vector<ParameterDescription>& names = equations_.model().Description().parameters;
    const std::string& kinetic = names[Model::kKineticLevelParameter].name;
    const std::string& static_level = names[Model::kStaticLevelParameter].name;
    for (int index : free_) {
      if (index < 0 || index >= full) {
        throw InvalidInput("free", index, fmt::format("a variable index, 0 <= index < {}", full));
      }
      if (tie_static_friction_ && index == StaticLevel()) {
        throw InvalidInput::WithMessage("free", fmt::format("free = '{}' is tied to {} ({} = {}): release {} instead",
                                                            static_level, kinetic, static_level, kinetic, kinetic));
      }
    }
  }

  int EquationCount() const override { return equations_.EquationCount(); }
  int UnknownCount() const override {
    return static_cast<int>(free_.size()) + equations_.VariableCount() - equations_.FullCount();
  }
  // Dense Jacobian for single shooting, sparse for multiple shooting.
  void Evaluate(const Eigen::VectorXd& u, Eigen::VectorXd* residual, JacobianMatrix* jacobian) const override {
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
  // Where the closed-form flows are undefined (the model's ValidateClosedForm).
  std::optional<std::string> DomainError(const Eigen::VectorXd& u) const override {
    if (const auto invalid = equations_.model().ValidateClosedForm(equations_.ParametersOf(Variables(u)))) {
      return invalid->what();
    }
    return std::nullopt;
  }

  // The variables (full vector, then the multiple-shooting states) at the unknowns u, and back.
  Eigen::VectorXd Variables(const Eigen::VectorXd& u) const {
    const int full = equations_.FullCount();
    Eigen::VectorXd v = reference_;
    for (std::size_t k = 0; k < free_.size(); ++k) v(free_[k]) = u(static_cast<int>(k));
    v.tail(v.size() - full) = u.tail(u.size() - static_cast<int>(free_.size()));
    if (tie_static_friction_) v(StaticLevel()) = v(KineticLevel());
    return v;
  }
  Eigen::VectorXd Unknowns(const Eigen::VectorXd& variables) const {
    const int full = equations_.FullCount();
    Eigen::VectorXd u(UnknownCount());
    for (std::size_t k = 0; k < free_.size(); ++k) u(static_cast<int>(k)) = variables(free_[k]);
    u.tail(u.size() - static_cast<int>(free_.size())) = variables.tail(variables.size() - full);
    return u;
  }
  // Derivatives with respect to the full variables (then, for multiple shooting, the segment
  // states, or none of them: a function of the orbit alone) as derivatives with respect to the
  // unknowns (the chain rule of holding, freeing and tying).
  Eigen::MatrixXd ToUnknowns(const Eigen::MatrixXd& d_variables) const {
    const int states = static_cast<int>(d_variables.cols()) - equations_.FullCount();
    Eigen::MatrixXd j = Eigen::MatrixXd::Zero(d_variables.rows(), UnknownCount());
    for (std::size_t k = 0; k < free_.size(); ++k) {
      j.col(static_cast<int>(k)) = d_variables.col(free_[k]);
      if (tie_static_friction_ && free_[k] == KineticLevel()) j.col(static_cast<int>(k)) += d_variables.col(StaticLevel());
    }
    j.rightCols(states) = d_variables.rightCols(states);
    return j;
  }

  const std::vector<int>& free() const { return free_; }
  const Equations& equations() const { return equations_; }

 private:
  int KineticLevel() const { return equations_.Parameter(Model::kKineticLevelParameter); }
  int StaticLevel() const { return equations_.Parameter(Model::kStaticLevelParameter); }

  Equations equations_;
  Eigen::VectorXd reference_;
  std::vector<int> free_;
  bool tie_static_friction_;
};

}  // namespace stickslip
