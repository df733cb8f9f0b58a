#include "stickslip/orbits/periodicity.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include "stickslip/invalid_input.hpp"
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

namespace {

// The state and forcing phase along the orbit with their derivatives with respect to every
// variable: the variational form of the segment walk.
struct Variational {
  State x;
  Eigen::Matrix<double, 4, Eigen::Dynamic> dx;
  double phase = 0.0;
  Eigen::RowVectorXd dphase;
  bool with_derivatives = false;
};

// The rows of the residual and, with derivatives, of the Jacobian, filled in order.
struct EquationRows {
  Eigen::VectorXd* residual;
  Eigen::MatrixXd* jacobian;
  int row = 0;

  void Add(const LocalGradient& g, const Variational& w, int first_parameter) {
    (*residual)(row) = g.value;
    if (jacobian) {
      jacobian->row(row) = g.d_state.transpose() * w.dx + g.d_phase * w.dphase;
      jacobian->row(row).segment(first_parameter, kParameterCount) += g.d_parameters;
    }
    ++row;
  }
};

// Multiple shooting: the segment starts at its own unknown state, continuous with the last end.
void RestartAt(const Eigen::VectorXd& v, int state_column, Variational* w, EquationRows* rows) {
  const State start = v.segment<4>(state_column);
  rows->residual->segment<4>(rows->row) = start - w->x;
  if (rows->jacobian) {
    rows->jacobian->block(rows->row, 0, 4, rows->jacobian->cols()) = -w->dx;
    rows->jacobian->block<4, 4>(rows->row, state_column) += Eigen::Matrix4d::Identity();
  }
  rows->row += 4;
  w->x = start;
  w->dx.setZero();
  w->dx.block<4, 4>(0, state_column) = Eigen::Matrix4d::Identity();
}

// The flow of one segment of duration d (variable `duration_column`), derivatives carried along.
void Advance(const FlowEvaluator& flow, Mode mode, double d, int duration_column, const Parameters& p, int n,
             Variational* w) {
  const int first_parameter = ov::Parameter(n, ParameterId::kChi);
  if (w->with_derivatives) {
    const FlowDerivatives f = flow.derivatives(mode, w->x, w->phase, d, p);
    Eigen::Matrix<double, 4, Eigen::Dynamic> next = f.d_start * w->dx + f.d_phase * w->dphase;
    next.col(duration_column) += f.d_elapsed;
    next.middleCols(first_parameter, kParameterCount) += f.d_parameters;
    w->dx = next;
    w->x = f.state;
  } else {
    w->x = flow.state(mode, w->x, w->phase, d, p);
  }
  w->dphase(duration_column) += p.omega;
  w->dphase(ov::Parameter(n, ParameterId::kOmega)) += d;
  w->phase += p.omega * d;
}

// (Anti)periodicity of x1, x2, x1' at the end of the listed segments, and the durations summing
// to the covered time.
void CloseOrbit(const Signature& signature, const Orbit& orbit, const Variational& w, EquationRows* rows) {
  const int n = signature.size();
  Eigen::VectorXd& residual = *rows->residual;
  const double sign = signature.antisymmetric() ? -1.0 : 1.0;
  const State x0 = orbit.InitialState();
  for (int j = 0; j < 3; ++j) {
    residual(rows->row) = w.x(j) - sign * x0(j);
    if (rows->jacobian) {
      rows->jacobian->row(rows->row) = w.dx.row(j);
      (*rows->jacobian)(rows->row, j) -= sign;
    }
    ++rows->row;
  }
  const double covered_periods = signature.period_multiple() * signature.CoveredFraction();
  const double omega = orbit.parameters.omega;
  double sum = 0.0;
  for (double d : orbit.durations) sum += d;
  residual(rows->row) = sum - covered_periods * 2.0 * std::numbers::pi / omega;
  if (rows->jacobian) {
    for (int i = 0; i < n; ++i) (*rows->jacobian)(rows->row, ov::Duration(i)) = 1.0;
    (*rows->jacobian)(rows->row, ov::Parameter(n, ParameterId::kOmega)) =
        covered_periods * 2.0 * std::numbers::pi / (omega * omega);
  }
}

}  // namespace

void PeriodicityEquations::Evaluate(const Eigen::VectorXd& v, Eigen::VectorXd* residual,
                                    Eigen::MatrixXd* jacobian) const {
  const int n = signature_.size();
  const int columns = VariableCount();
  const int full = ov::Count(n);
  const Orbit orbit = ov::Unpack(signature_, v.head(full));
  const Parameters& p = orbit.parameters;
  const int first_parameter = ov::Parameter(n, ParameterId::kChi);

  residual->setZero(EquationCount());
  if (jacobian) jacobian->setZero(EquationCount(), columns);
  EquationRows rows{residual, jacobian};

  Variational w{orbit.InitialState(), Eigen::MatrixXd::Zero(4, columns), orbit.phi,
                Eigen::RowVectorXd::Zero(columns), jacobian != nullptr};
  w.dx(0, ov::kX10) = w.dx(1, ov::kX20) = w.dx(2, ov::kV10) = 1.0;
  w.dphase(ov::kPhi) = 1.0;
  for (const SegmentSpec& spec : plan_) {
    const int i = spec.listed;
    if (shooting_ == Shooting::kMultiple && i > 0) RestartAt(v, full + 4 * (i - 1), &w, &rows);
    Advance(flow_, spec.mode, orbit.durations[i], ov::Duration(i), p, n, &w);
    for (EndCondition condition : EndConditionsOf(spec.end)) {
      if (jacobian) {
        rows.Add(Linearize(condition, spec.mode, w.x, w.phase, p), w, first_parameter);
      } else {
        (*residual)(rows.row++) = EndConditionValue(condition, spec.mode, w.x, w.phase, p);
      }
    }
  }
  CloseOrbit(signature_, orbit, w, &rows);
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
