#include "stickslip/orbits/periodicity.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include "stickslip/orbits/segment_plan.hpp"

namespace stickslip {

namespace ov = orbit_variables;

const char* ToString(Shooting s) { return s == Shooting::kSingle ? "single" : "multiple"; }

namespace {

// A scalar equation and its gradient with respect to the state at the segment end, the forcing
// phase there and the five parameters.
struct LocalGradient {
  double value = 0.0;
  Eigen::Vector4d d_state = Eigen::Vector4d::Zero();
  double d_phase = 0.0;
  Eigen::Matrix<double, 1, kParameterCount> d_parameters = Eigen::Matrix<double, 1, kParameterCount>::Zero();
};

// An end condition (segment_plan.hpp) and its exact gradient: forward-mode AD through its
// template, one direction per state coordinate, the phase and each parameter.
LocalGradient Linearize(EndCondition condition, Mode mode, const State& x, double phase, const Parameters& p) {
  constexpr int kDirections = 4 + 1 + kParameterCount;
  using Dual = Eigen::AutoDiffScalar<Eigen::Matrix<double, kDirections, 1>>;
  StateT<Dual> x_dual;
  for (int k = 0; k < 4; ++k) x_dual(k) = Dual(x(k), kDirections, k);
  BasicParameters<Dual> p_dual;
  for (int k = 0; k < kParameterCount; ++k) p_dual[kAllParameters[k]] = Dual(p[kAllParameters[k]], kDirections, 5 + k);
  const Dual g = EndConditionValue(condition, mode, x_dual, Dual(phase, kDirections, 4), p_dual);
  LocalGradient out;
  out.value = g.value();
  out.d_state = g.derivatives().head<4>();
  out.d_phase = g.derivatives()(4);
  out.d_parameters = g.derivatives().tail<kParameterCount>().transpose();
  return out;
}

int ShootingStates(const Signature& signature, Shooting shooting) {
  return shooting == Shooting::kMultiple ? 4 * (signature.size() - 1) : 0;
}

}  // namespace

PeriodicityEquations::PeriodicityEquations(Signature signature, Shooting shooting, FlowEvaluator flow)
    : signature_(std::move(signature)), plan_(SegmentPlan(signature_, Extent::kListed)), shooting_(shooting),
      flow_(flow) {
  for (const SegmentSpec& spec : plan_) end_conditions_ += static_cast<int>(EndConditionsOf(spec.end).size());
}

int PeriodicityEquations::EquationCount() const {
  return end_conditions_ + 4 + ShootingStates(signature_, shooting_);
}

int PeriodicityEquations::VariableCount() const {
  return ov::Count(signature_.size()) + ShootingStates(signature_, shooting_);
}

std::vector<std::string> PeriodicityEquations::EquationNames() const {
  std::vector<std::string> names;
  static constexpr const char* kCoordinates[] = {"x1", "x2", "x1'", "x2'"};
  for (const SegmentSpec& spec : plan_) {
    const int i = spec.listed;
    if (shooting_ == Shooting::kMultiple && i > 0) {
      for (const char* c : kCoordinates) names.push_back(fmt::format("continuity:{}:{}", i + 1, c));
    }
    for (EndCondition condition : EndConditionsOf(spec.end)) {
      const char* name = condition == EndCondition::kSlipAccelerationZero ? "abnormal-x2''" : "end";
      names.push_back(fmt::format("{}:{}", name, i + 1));
    }
  }
  for (int j = 0; j < 3; ++j) names.push_back(fmt::format("periodicity:{}", kCoordinates[j]));
  names.push_back("period");
  return names;
}

void PeriodicityEquations::Evaluate(const Eigen::VectorXd& v, Eigen::VectorXd* residual,
                                    Eigen::MatrixXd* jacobian) const {
  const int n = signature_.size();
  const int columns = VariableCount();
  const int full = ov::Count(n);
  const Orbit orbit = ov::Unpack(signature_, v.head(full));
  const Parameters& p = orbit.parameters;
  const int omega_column = ov::Parameter(n, ParameterId::kOmega);
  const int first_parameter = ov::Parameter(n, ParameterId::kChi);

  residual->setZero(EquationCount());
  if (jacobian) jacobian->setZero(EquationCount(), columns);

  // The state and phase along the orbit with their derivatives with respect to every variable.
  State x = orbit.InitialState();
  Eigen::Matrix<double, 4, Eigen::Dynamic> dx = Eigen::MatrixXd::Zero(4, columns);
  dx(0, ov::kX10) = dx(1, ov::kX20) = dx(2, ov::kV10) = 1.0;
  double phase = orbit.phi;
  Eigen::RowVectorXd dphase = Eigen::RowVectorXd::Zero(columns);
  dphase(ov::kPhi) = 1.0;

  int row = 0;
  auto add_equation = [&](const LocalGradient& g) {
    (*residual)(row) = g.value;
    if (jacobian) {
      jacobian->row(row) = g.d_state.transpose() * dx + g.d_phase * dphase;
      jacobian->row(row).segment(first_parameter, kParameterCount) += g.d_parameters;
    }
    ++row;
  };

  for (const SegmentSpec& spec : plan_) {
    const int i = spec.listed;
    const Mode mode = spec.mode;
    if (shooting_ == Shooting::kMultiple && i > 0) {
      const int state_column = full + 4 * (i - 1);
      const State start = v.segment<4>(state_column);
      residual->segment<4>(row) = start - x;  // continuity
      if (jacobian) {
        jacobian->block(row, 0, 4, columns) = -dx;
        jacobian->block<4, 4>(row, state_column) += Eigen::Matrix4d::Identity();
      }
      row += 4;
      x = start;
      dx.setZero();
      dx.block<4, 4>(0, state_column) = Eigen::Matrix4d::Identity();
    }
    const double d = orbit.durations[i];
    if (jacobian) {
      const FlowDerivatives f = flow_.derivatives(mode, x, phase, d, p);
      Eigen::Matrix<double, 4, Eigen::Dynamic> next = f.d_start * dx + f.d_phase * dphase;
      next.col(ov::Duration(i)) += f.d_elapsed;
      next.middleCols(first_parameter, kParameterCount) += f.d_parameters;
      dx = next;
      x = f.state;
    } else {
      x = flow_.state(mode, x, phase, d, p);
    }
    dphase(ov::Duration(i)) += p.omega;
    dphase(omega_column) += d;
    phase += p.omega * d;

    for (EndCondition condition : EndConditionsOf(spec.end)) {
      if (jacobian) {
        add_equation(Linearize(condition, mode, x, phase, p));
      } else {
        (*residual)(row++) = EndConditionValue(condition, mode, x, phase, p);
      }
    }
  }

  // (Anti)periodicity of x1, x2, x1'.
  const double sign = signature_.antisymmetric() ? -1.0 : 1.0;
  const State x0 = orbit.InitialState();
  for (int j = 0; j < 3; ++j) {
    (*residual)(row) = x(j) - sign * x0(j);
    if (jacobian) {
      jacobian->row(row) = dx.row(j);
      (*jacobian)(row, j) -= sign;
    }
    ++row;
  }
  // Durations sum to the covered time.
  const double covered_periods = signature_.period_multiple() * signature_.CoveredFraction();
  double sum = 0.0;
  for (double d : orbit.durations) sum += d;
  (*residual)(row) = sum - covered_periods * 2.0 * std::numbers::pi / p.omega;
  if (jacobian) {
    for (int i = 0; i < n; ++i) (*jacobian)(row, ov::Duration(i)) = 1.0;
    (*jacobian)(row, omega_column) = covered_periods * 2.0 * std::numbers::pi / (p.omega * p.omega);
  }
}

Eigen::VectorXd PeriodicityEquations::Variables(const Orbit& orbit) const {
  Eigen::VectorXd v(VariableCount());
  const int full = ov::Count(signature_.size());
  v.head(full) = ov::Pack(orbit);
  if (shooting_ == Shooting::kMultiple) {
    const std::vector<State> states = orbit.SegmentStates();
    for (int i = 1; i < signature_.size(); ++i) v.segment<4>(full + 4 * (i - 1)) = states[i];
  }
  return v;
}

OrbitSystem::OrbitSystem(const Orbit& reference, std::vector<int> free, bool tie_static_friction,
                         Shooting shooting, FlowEvaluator flow)
    : equations_(reference.signature, shooting, flow), reference_(equations_.Variables(reference)),
      free_(std::move(free)), tie_static_friction_(tie_static_friction) {
  const int n = reference.signature.size();
  for (int index : free_) {
    if (index < 0 || index >= ov::Count(n)) throw std::invalid_argument("free variable out of range");
    if (tie_static_friction_ && index == ov::Parameter(n, ParameterId::kStaticFriction)) {
      throw std::invalid_argument("u_r cannot be free while it is tied to u_s");
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
  const int n = equations_.signature().size();
  const int full = ov::Count(n);
  const int states = equations_.VariableCount() - full;
  const int u_s = ov::Parameter(n, ParameterId::kSlidingFriction);
  const int u_r = ov::Parameter(n, ParameterId::kStaticFriction);
  Eigen::MatrixXd j(full_jacobian.rows(), UnknownCount());
  for (std::size_t k = 0; k < free_.size(); ++k) {
    j.col(static_cast<int>(k)) = full_jacobian.col(free_[k]);
    if (tie_static_friction_ && free_[k] == u_s) j.col(static_cast<int>(k)) += full_jacobian.col(u_r);
  }
  j.rightCols(states) = full_jacobian.rightCols(states);
  if (equations_.shooting() == Shooting::kMultiple) {
    *jacobian = SparseMatrix(j.sparseView());
  } else {
    *jacobian = std::move(j);
  }
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
