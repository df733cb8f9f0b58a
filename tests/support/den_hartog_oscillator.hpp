// A second model behind the model interface (model/oscillator_model.hpp), for the tests only: one
// mass on a spring against a fixed ground with Coulomb friction, undamped, forced harmonically
// (Den Hartog, Trans. ASME APM 53 (1931) 107). With m = k = 1 and the forcing amplitude 1:
//   x'' + x = cos(omega t + phi) + F,  F = -beta sign(x') in a slip, |F| <= beta_static in a stick.
// The state is (x, x'); the contact velocity is x'. Written from the equation above, sharing no
// code with the paper's model, so that a simulator or solver that works through the interface
// for both shows the seam is real.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>
#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/model/pascal_2014/flows.hpp"
#include "stickslip/model/mode.hpp"
#include "stickslip/model/model_description.hpp"
#include "stickslip/numerics/sinusoid_sum.hpp"

namespace stickslip {

struct DenHartogOscillator {
  static constexpr int kStateSize = 2;
  static constexpr int kParameterCount = 3;
  static constexpr int kForcingFrequencyParameter = 0;
  static constexpr int kKineticLevelParameter = 1;
  static constexpr int kStaticLevelParameter = 2;
  template <typename T>
  using StateT = Eigen::Matrix<T, 2, 1>;
  template <typename T>
  struct ParametersT {
    T omega{};        // forcing frequency over the natural frequency, r
    T beta{};         // kinetic friction over the forcing amplitude, F/P0
    T beta_static{};  // static friction over the forcing amplitude, >= beta
  };
  using State = StateT<double>;
  using Parameters = ParametersT<double>;
  using FlowDerivatives = BasicFlowDerivatives<2, 3>;
  template <typename T>
  static T& ParameterAt(ParametersT<T>& p, int k) { return k == 0 ? p.omega : k == 1 ? p.beta : p.beta_static; }
  template <typename T>
  static const T& ParameterAt(const ParametersT<T>& p, int k) {
    return k == 0 ? p.omega : k == 1 ? p.beta : p.beta_static;
  }
  // x(s) = offset + drift s + q cos(omega s + phase) + a cos s + b sin s, s the time elapsed in
  // the mode: the particular solution and the free oscillation at frequency 1 (none in a stick).
  template <typename T>
  struct MotionT {
    T offset{}, drift{};
    T omega{}, q{}, phase{};
    T a{}, b{};

    StateT<T> StateAt(const T& s) const {
      using std::cos;
      using std::sin;
      return StateT<T>(offset + drift * s + q * cos(omega * s + phase) + a * cos(s) + b * sin(s),
                       drift - q * omega * sin(omega * s + phase) - a * sin(s) + b * cos(s));
    }
  };
  using Motion = MotionT<double>;

  const ModelDescription& Description() const {
    static const ModelDescription description{
        "den-hartog-1930",
        {{"omega", "forcing frequency ratio r", "1", 0.01, 100.0, "0.01 <= omega <= 100, omega != 1"},
         {"beta", "kinetic friction ratio F/P0", "1", 1e-6, 1000.0, "1e-06 <= beta <= 1000"},
         {"beta_static", "static friction ratio", "1", 1e-6, 1000.0, "beta <= beta_static <= 1000"}},
        {"x"},
        {"x", "x'"},
        {"x0", "v0"}};
    return description;
  }
  // The closed form needs a forcing frequency away from resonance; the friction levels enter
  // linearly and stay meaningful beyond their physical range.
  std::optional<InvalidInput> ValidateClosedForm(const Parameters& p) const {
    if (!(p.omega >= 0.01 && p.omega <= 100.0) || std::abs(p.omega - 1.0) < 1e-9) {
      return InvalidInput("omega", p.omega, Description().parameters[0].range);
    }
    return std::nullopt;
  }
  std::optional<InvalidInput> Validate(const Parameters& p) const {
    if (auto invalid = ValidateClosedForm(p)) return invalid;
    if (!(p.beta >= 1e-6 && p.beta <= 1000.0)) return InvalidInput("beta", p.beta, Description().parameters[1].range);
    if (!(p.beta_static >= p.beta && p.beta_static <= 1000.0)) {
      return InvalidInput("beta_static", p.beta_static, fmt::format("beta = {} <= beta_static <= 1000", p.beta));
    }
    return std::nullopt;
  }

  // In a slip: the particular solution -beta dir + Q cos(omega s + phase), Q = 1/(1 - omega^2),
  // plus the free oscillation at frequency 1 that meets the start. In a stick x stays put.
  template <typename T>
  MotionT<T> MotionInMode(Mode mode, const StateT<T>& start, const T& phase, const ParametersT<T>& p) const {
    using std::cos;
    using std::sin;
    if (mode == Mode::kStick) return MotionT<T>{start(0), start(1), p.omega, T(0.0), phase, T(0.0), T(0.0)};
    const T offset = -p.beta * double(SlipDirection(mode));
    const T q = 1.0 / (1.0 - p.omega * p.omega);
    return MotionT<T>{offset, T(0.0), p.omega, q, phase, start(0) - offset - q * cos(phase),
                      start(1) + q * p.omega * sin(phase)};
  }
  template <typename T>
  StateT<T> Flow(Mode mode, const StateT<T>& start, const T& phase, const T& s, const ParametersT<T>& p) const {
    return MotionInMode(mode, start, phase, p).StateAt(s);
  }
  FlowDerivatives FlowWithDerivatives(Mode mode, const State& start, double phase, double s,
                                      const Parameters& p) const {
    constexpr int kDirections = 2 + 1 + 1 + 3;  // start, phase, elapsed time, parameters
    using Dual = Eigen::AutoDiffScalar<Eigen::Matrix<double, kDirections, 1>>;
    ParametersT<Dual> p_dual;
    for (int k = 0; k < 3; ++k) ParameterAt(p_dual, k) = Dual(ParameterAt(p, k), kDirections, 4 + k);
    const StateT<Dual> end = Flow(mode, StateT<Dual>(Dual(start(0), kDirections, 0), Dual(start(1), kDirections, 1)),
                                  Dual(phase, kDirections, 2), Dual(s, kDirections, 3), p_dual);
    FlowDerivatives d;
    for (int i = 0; i < 2; ++i) {
      d.state(i) = end(i).value();
      d.d_start.row(i) = end(i).derivatives().head<2>().transpose();
      d.d_phase(i) = end(i).derivatives()(2);
      d.d_elapsed(i) = end(i).derivatives()(3);
      d.d_parameters.row(i) = end(i).derivatives().tail<3>().transpose();
    }
    return d;
  }
  // The flow's Jacobian with respect to the start state: a rotation at frequency 1 in a slip,
  // x = x0 + x0' s in a stick.
  template <typename T>
  Eigen::Matrix<T, 2, 2> TransitionMatrix(Mode mode, const T& s, const ParametersT<T>&) const {
    using std::cos;
    using std::sin;
    Eigen::Matrix<T, 2, 2> m;
    if (mode == Mode::kStick) {
      m << T(1.0), s, T(0.0), T(1.0);
    } else {
      m << cos(s), sin(s), -sin(s), cos(s);
    }
    return m;
  }
  // S = I + (f+ - f-) grad(h)^T / (grad(h) . f- + dh/dt) from the equation of motion: the fields
  // differ in x'' only; at a stop h = x', at a stick exit h = x - cos(phase) -+ beta_static.
  template <typename T>
  Eigen::Matrix<T, 2, 2> SaltationMatrix(Mode before, Mode after, const StateT<T>& x, const T& phase,
                                         const ParametersT<T>& p) const {
    Eigen::Matrix<T, 2, 2> s = Eigen::Matrix<T, 2, 2>::Identity();
    if (before == after) return s;  // an abnormal stop
    const T jump = ContactAcceleration(after, x, phase, p) - ContactAcceleration(before, x, phase, p);
    if (before != Mode::kStick) {
      s(1, 1) += jump / ContactAcceleration(before, x, phase, p);
    } else {
      s(1, 0) += jump / StickForceRate(StateT<T>(x(0), T(0.0)), phase, p);
    }
    return s;
  }
  template <typename T>
  T ForcingFrequency(const ParametersT<T>& p) const { return p.omega; }

  template <typename T>
  T ContactVelocity(const StateT<T>& x) const { return x(1); }
  template <typename T>
  T ContactAcceleration(Mode mode, const StateT<T>& x, const T& phase, const ParametersT<T>& p) const {
    using std::cos;
    if (mode == Mode::kStick) return T(0.0);
    return -x(0) + cos(phase) - p.beta * double(SlipDirection(mode));
  }
  State AtRest(const State& x) const { return State(x(0), 0.0); }
  bool NearRest(const State& x) const { return std::abs(x(1)) <= 1e-12 * (1.0 + std::abs(x(0))); }

  // The friction force a stick needs, sign as the paper's s: x - cos(phase) > beta_static drives
  // the mass towards negative x.
  template <typename T>
  T StickForce(const StateT<T>& x, const T& phase, const ParametersT<T>&) const {
    using std::cos;
    return x(0) - cos(phase);
  }
  // d/dt of the stick force along a motion at rest.
  template <typename T>
  T StickForceRate(const StateT<T>& x, const T& phase, const ParametersT<T>& p) const {
    using std::sin;
    return x(1) + p.omega * sin(phase);
  }
  template <typename T>
  T StaticThreshold(const ParametersT<T>& p) const { return p.beta_static; }
  bool AbnormalStopsPossible(const Parameters& p) const {
    return std::abs(p.beta_static - p.beta) <= 1e-12 * p.beta_static;
  }
  Mode ModeFromRest(const State& x, double phase, const Parameters& p) const {
    const double s = StickForce(x, phase, p);
    if (s > p.beta_static) return Mode::kSlipNegative;
    if (s < -p.beta_static) return Mode::kSlipPositive;
    return Mode::kStick;
  }

  SinusoidSum ContactVelocityAlong(const Motion& motion) const { return PositionAlong(motion).Derivative(); }
  SinusoidSum CoordinateAlong(const Motion& motion, int) const { return PositionAlong(motion); }
  bool HeldInStick(int) const { return true; }  // a stick holds the mass
  // x - cos(omega s + phase).
  SinusoidSum StickForceAlong(const Motion& motion, double phase, const Parameters& p) const {
    return PositionAlong({motion.offset, motion.drift, p.omega, motion.q - 1.0, phase, motion.a, motion.b});
  }
  static SinusoidSum PositionAlong(const Motion& m) {
    const Sinusoid forced{m.omega, m.q * std::cos(m.phase), -m.q * std::sin(m.phase)};
    return SinusoidSum(m.offset, m.drift, {forced, Sinusoid{1.0, m.a, m.b}});
  }
  // For an integrator (integrable_oscillator_model.hpp), from the equation above alone: in a
  // stick x'' = 0 and x' stays 0.
  State VectorField(Mode mode, const State& x, double phase, const Parameters& p) const {
    if (mode == Mode::kStick) return State(x(1), 0.0);
    return State(x(1), -x(0) + std::cos(phase) - p.beta * SlipDirection(mode));
  }
  // x'' = 0 at rest needs F = x - cos(phase), changing at omega sin(phase) while x' = 0.
  double HoldingForce(const State& x, double phase, const Parameters&) const { return x(0) - std::cos(phase); }
  double HoldingForceRate(const State&, double phase, const Parameters& p) const { return p.omega * std::sin(phase); }
  double HoldingForceScale(const State& x, const Parameters&) const { return std::max(std::abs(x(0)), 1.0); }
};

}  // namespace stickslip
