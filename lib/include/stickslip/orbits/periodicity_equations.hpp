// The periodicity equations of an orbit type for any model (model/oscillator_model.hpp): the
// segment plan walked in variational form, the end condition of each segment and the closing of
// the orbit, with the exact Jacobian. periodicity.hpp states the equations and holds the paper's
// model's instance with its orbit system.
//
// Variables ("full variable vector"), for a model with a state of S components and P parameters
// and n listed segments: the start state's first S - 1 components (the last, the contact's
// velocity, is zero at the origin, which is a stop), the forcing phase phi, the durations d1..dn
// and the parameters in the model's order: S + n + P values. Multiple shooting appends the start
// state of each segment after the first (S values each).
#pragma once

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>

#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include "stickslip/model/oscillator_model.hpp"
#include "stickslip/orbits/segment_plan.hpp"
#include "stickslip/orbits/signature.hpp"

namespace stickslip {

enum class Shooting { kSingle, kMultiple };
const char* ToString(Shooting s);  // "single", "multiple"

// How the equations evaluate one mode's flow, alone (for residuals) and with its derivatives
// (for Jacobians): the model's closed form where a pointer is null; the benchmark swaps in a
// numerical integration.
template <OscillatorModel Model>
struct BasicFlowEvaluator {
  using State = typename Model::State;
  using Parameters = typename Model::Parameters;
  State (*state)(Mode, const State&, const double& phase, const double& s, const Parameters&) = nullptr;
  typename Model::FlowDerivatives (*derivatives)(Mode, const State&, double phase, double s,
                                                 const Parameters&) = nullptr;
};

namespace periodicity {

// A scalar equation and its gradient with respect to the state at the segment end, the forcing
// phase there and the parameters.
template <typename Model>
struct LocalGradient {
  double value = 0.0;
  Eigen::Matrix<double, Model::kStateSize, 1> d_state;
  double d_phase = 0.0;
  Eigen::Matrix<double, 1, Model::kParameterCount> d_parameters;
};

// An end condition and its exact gradient: forward-mode AD through its template, one direction
// per state component, the phase and each parameter.
template <typename Model>
LocalGradient<Model> Linearize(const Model& model, EndCondition condition, Mode mode, const typename Model::State& x,
                               double phase, const typename Model::Parameters& p) {
  constexpr int P = Model::kParameterCount;
  constexpr int kDirections = Model::kStateSize == Eigen::Dynamic ? Eigen::Dynamic : Model::kStateSize + 1 + P;
  using Dual = Eigen::AutoDiffScalar<Eigen::Matrix<double, kDirections, 1>>;
  const int S = model.StateSize(), directions = S + 1 + P;
  typename Model::template StateT<Dual> x_dual(S);
  for (int k = 0; k < S; ++k) x_dual(k) = Dual(x(k), directions, k);
  typename Model::template ParametersT<Dual> p_dual;
  for (int k = 0; k < P; ++k) Model::ParameterAt(p_dual, k) = Dual(Model::ParameterAt(p, k), directions, S + 1 + k);
  const Dual g = EndConditionValue(model, condition, mode, x_dual, Dual(phase, directions, S), p_dual);
  return {g.value(), g.derivatives().head(S), g.derivatives()(S), g.derivatives().template tail<P>().transpose()};
}

// The state and forcing phase along the orbit with their derivatives with respect to every
// variable: the variational form of the segment walk.
template <typename Model>
struct Variational {
  typename Model::State x;
  Eigen::Matrix<double, Model::kStateSize, Eigen::Dynamic> dx;
  double phase = 0.0;
  Eigen::RowVectorXd dphase;
  bool with_derivatives = false;
  // The next segment's dx is built here and swapped in: no allocation per segment.
  Eigen::Matrix<double, Model::kStateSize, Eigen::Dynamic> next_dx{};
};

// The rows of the residual and, with derivatives, of the Jacobian, filled in order.
struct EquationRows {
  Eigen::VectorXd* residual;
  Eigen::MatrixXd* jacobian;
  int row = 0;

  template <typename Model>
  void Add(const LocalGradient<Model>& g, const Variational<Model>& w, int first_parameter) {
    (*residual)(row) = g.value;
    if (jacobian) {
      jacobian->row(row) = g.d_state.transpose() * w.dx + g.d_phase * w.dphase;
      jacobian->row(row).segment(first_parameter, Model::kParameterCount) += g.d_parameters;
    }
    ++row;
  }
};

}  // namespace periodicity

template <OscillatorModel Model>
class BasicPeriodicityEquations {
 public:
  static constexpr int kParameterCount = Model::kParameterCount;
  using State = typename Model::State;
  using Parameters = typename Model::Parameters;

  BasicPeriodicityEquations(Model model, Signature signature, Shooting shooting, BasicFlowEvaluator<Model> flow = {})
      : model_(std::move(model)), signature_(std::move(signature)), plan_(SegmentPlan(signature_, Extent::kListed)),
        shooting_(shooting), flow_(flow) {
    for (const SegmentSpec& spec : plan_) end_conditions_ += static_cast<int>(EndConditionsOf(spec.end).size());
  }

  int StateSize() const { return model_.StateSize(); }
  int EquationCount() const { return end_conditions_ + StateSize() + ShootingStates(); }
  // The full variable vector followed, for multiple shooting, by the start state of segments 2..n.
  int VariableCount() const { return FullCount() + ShootingStates(); }
  int FullCount() const { return StateSize() + signature_.size() + kParameterCount; }
  // Positions in the full variable vector.
  int Phi() const { return StateSize() - 1; }
  int Duration(int i) const { return StateSize() + i; }
  int Parameter(int k) const { return StateSize() + signature_.size() + k; }

  // Residual and exact Jacobian (EquationCount x VariableCount) from the flow derivatives.
  void Evaluate(const Eigen::VectorXd& v, Eigen::VectorXd* residual, Eigen::MatrixXd* jacobian) const;

  // The state at the origin: the first S - 1 components from the variables, the contact at rest
  // (its velocity the rest velocity: 0, or a belt's speed).
  State StartState(const Eigen::VectorXd& v) const {
    const int S = StateSize();
    State x0(S);
    x0.head(S - 1) = v.head(S - 1);
    x0(S - 1) = RestVelocity<Model>(ParametersOf(v), 0.0);
    return x0;
  }
  Parameters ParametersOf(const Eigen::VectorXd& v) const {
    Parameters p;
    for (int k = 0; k < kParameterCount; ++k) Model::ParameterAt(p, k) = v(Parameter(k));
    return p;
  }

  const Model& model() const { return model_; }
  const Signature& signature() const { return signature_; }
  Shooting shooting() const { return shooting_; }
  // Names of the equations, for messages: "end:1", "periodicity:x1", "period", "continuity:2:x1".
  std::vector<std::string> EquationNames() const;

 private:
  int ShootingStates() const { return shooting_ == Shooting::kMultiple ? StateSize() * (signature_.size() - 1) : 0; }

  // Multiple shooting: the segment starts at its own unknown state, continuous with the last end.
  void RestartAt(const Eigen::VectorXd& v, int state_column, periodicity::Variational<Model>& w,
                 periodicity::EquationRows& rows) const {
    const int S = StateSize();
    const State start = v.segment(state_column, S);
    rows.residual->segment(rows.row, S) = start - w.x;
    if (rows.jacobian) {
      rows.jacobian->block(rows.row, 0, S, rows.jacobian->cols()) = -w.dx;
      rows.jacobian->block(rows.row, state_column, S, S) += IdentityOfState(model_);
    }
    rows.row += S;
    w.x = start;
    w.dx.setZero();
    w.dx.block(0, state_column, S, S) = IdentityOfState(model_);
  }

  // The flow of one segment of duration d (variable `duration_column`), derivatives carried along.
  void Advance(Mode mode, double d, int duration_column, const Parameters& p, periodicity::Variational<Model>& w) const {
    const double omega = model_.ForcingFrequency(p);
    if (w.with_derivatives) {
      const typename Model::FlowDerivatives f = flow_.derivatives ? flow_.derivatives(mode, w.x, w.phase, d, p)
                                                                  : model_.FlowWithDerivatives(mode, w.x, w.phase, d, p);
      w.next_dx.resize(w.dx.rows(), w.dx.cols());
      w.next_dx.noalias() = f.d_start * w.dx + f.d_phase * w.dphase;
      w.next_dx.col(duration_column) += f.d_elapsed;
      w.next_dx.middleCols(Parameter(0), kParameterCount) += f.d_parameters;
      w.dx.swap(w.next_dx);
      w.x = f.state;
    } else {
      w.x = flow_.state ? flow_.state(mode, w.x, w.phase, d, p) : model_.Flow(mode, w.x, w.phase, d, p);
    }
    w.dphase(duration_column) += omega;
    w.dphase(Parameter(Model::kForcingFrequencyParameter)) += d;
    w.phase += omega * d;
  }

  // (Anti)periodicity of the start components at the end of the listed segments (the contact's
  // velocity needs none: the last segment's end condition gives it), and the durations summing
  // to the covered time.
  void CloseOrbit(const Eigen::VectorXd& v, const Parameters& p, const periodicity::Variational<Model>& w,
                  periodicity::EquationRows& rows) const {
    const int n = signature_.size();
    Eigen::VectorXd& residual = *rows.residual;
    const double sign = signature_.antisymmetric() ? -1.0 : 1.0;
    const State x0 = StartState(v);
    for (int j = 0; j < StateSize() - 1; ++j) {
      residual(rows.row) = w.x(j) - sign * x0(j);
      if (rows.jacobian) {
        rows.jacobian->row(rows.row) = w.dx.row(j);
        (*rows.jacobian)(rows.row, j) -= sign;
      }
      ++rows.row;
    }
    if (model_.Autonomous()) {
      // No forcing: the period is the durations' sum, free; the phase means nothing and is pinned.
      residual(rows.row) = v(Phi());
      if (rows.jacobian) (*rows.jacobian)(rows.row, Phi()) = 1.0;
      return;
    }
    const double covered_periods = signature_.period_multiple() * signature_.CoveredFraction();
    const double omega = model_.ForcingFrequency(p);
    double sum = 0.0;
    for (int i = 0; i < n; ++i) sum += v(Duration(i));
    residual(rows.row) = sum - covered_periods * 2.0 * std::numbers::pi / omega;
    if (rows.jacobian) {
      for (int i = 0; i < n; ++i) (*rows.jacobian)(rows.row, Duration(i)) = 1.0;
      (*rows.jacobian)(rows.row, Parameter(Model::kForcingFrequencyParameter)) =
          covered_periods * 2.0 * std::numbers::pi / (omega * omega);
    }
  }

  Model model_;
  Signature signature_;
  std::vector<SegmentSpec> plan_;
  int end_conditions_ = 0;  // equations at the segment ends (one more at each abnormal stop)
  Shooting shooting_;
  BasicFlowEvaluator<Model> flow_;
};

template <OscillatorModel Model>
void BasicPeriodicityEquations<Model>::Evaluate(const Eigen::VectorXd& v, Eigen::VectorXd* residual,
                                                Eigen::MatrixXd* jacobian) const {
  using namespace periodicity;
  const Parameters p = ParametersOf(v);
  residual->setZero(EquationCount());
  if (jacobian) jacobian->setZero(EquationCount(), VariableCount());
  EquationRows rows{residual, jacobian};
  const int S = StateSize();
  Variational<Model> w{StartState(v), Eigen::MatrixXd::Zero(S, VariableCount()), v(Phi()),
                       Eigen::RowVectorXd::Zero(VariableCount()), jacobian != nullptr};
  for (int j = 0; j < S - 1; ++j) w.dx(j, j) = 1.0;
  if constexpr (Model::kRestVelocityParameter >= 0) w.dx(S - 1, Parameter(Model::kRestVelocityParameter)) = 1.0;
  w.dphase(Phi()) = 1.0;
  for (const SegmentSpec& spec : plan_) {
    const int i = spec.listed;
    if (shooting_ == Shooting::kMultiple && i > 0) RestartAt(v, FullCount() + S * (i - 1), w, rows);
    Advance(spec.mode, v(Duration(i)), Duration(i), p, w);
    for (EndCondition condition : EndConditionsOf(spec.end)) {
      if (jacobian) {
        rows.Add(Linearize(model_, condition, spec.mode, w.x, w.phase, p), w, Parameter(0));
      } else {
        (*residual)(rows.row++) = EndConditionValue(model_, condition, spec.mode, w.x, w.phase, p);
      }
    }
  }
  CloseOrbit(v, p, w, rows);
}

template <OscillatorModel Model>
std::vector<std::string> BasicPeriodicityEquations<Model>::EquationNames() const {
  const std::vector<std::string>& components = model_.Description().state_components;
  std::vector<std::string> names;
  for (const SegmentSpec& spec : plan_) {
    const int i = spec.listed;
    if (shooting_ == Shooting::kMultiple && i > 0) {
      for (const std::string& c : components) names.push_back(fmt::format("continuity:{}:{}", i + 1, c));
    }
    for (EndCondition condition : EndConditionsOf(spec.end)) {
      const bool abnormal = condition == EndCondition::kSlipAccelerationZero;
      names.push_back(abnormal ? fmt::format("abnormal-{}':{}", components.back(), i + 1) : fmt::format("end:{}", i + 1));
    }
  }
  for (int j = 0; j < StateSize() - 1; ++j) names.push_back(fmt::format("periodicity:{}", components[j]));
  names.push_back(model_.Autonomous() ? "phase" : "period");
  return names;
}

}  // namespace stickslip
