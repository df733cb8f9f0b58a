// M. Pascal's two-degree-of-freedom oscillator (Nonlinear Dyn. 77 (2014) 267-276) as an
// OscillatorModel (oscillator_model.hpp): two masses, two springs, Coulomb friction on the second
// mass against a fixed ground, forcing cos(omega t + phi), in the paper's scaled variables
// (eq. 3). The state is (x1, x2, x1', x2'); the contact's velocity is x2'. Its closed forms live
// in pascal_2014/ (flows.hpp, modal.hpp, events.hpp, saltation.hpp); this struct gathers them behind the interface, at the
// fixed size 4 (no allocation, no run-time size).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

#include "stickslip/invalid_input.hpp"
#include "stickslip/model/pascal_2014/events.hpp"
#include "stickslip/model/pascal_2014/flows.hpp"
#include "stickslip/model/model_description.hpp"
#include "stickslip/model/pascal_2014/parameters.hpp"
#include "stickslip/model/pascal_2014/saltation.hpp"

namespace stickslip {

struct Pascal2014 {
  static constexpr int kStateSize = 4;
  static constexpr int StateSize() { return kStateSize; }
  static constexpr int kParameterCount = stickslip::kParameterCount;
  static constexpr int kForcingFrequencyParameter = static_cast<int>(ParameterId::kOmega);
  static constexpr int kKineticLevelParameter = static_cast<int>(ParameterId::kSlidingFriction);
  static constexpr int kStaticLevelParameter = static_cast<int>(ParameterId::kStaticFriction);
  template <typename T>
  using StateT = stickslip::StateT<T>;
  template <typename T>
  using ParametersT = BasicParameters<T>;
  using State = stickslip::State;
  using Parameters = stickslip::Parameters;
  template <typename T>
  using MotionT = ModeMotion<T>;
  using Motion = ModeMotion<double>;
  using FlowDerivatives = stickslip::FlowDerivatives;
  using EventFunction = SinusoidSum;  // undamped: every function along a mode is a sum of sinusoids

  // chi, eta, omega, u_s, u_r (ParameterId order); x1, x2, x1', x2'.
  const ModelDescription& Description() const;
  std::optional<InvalidInput> Validate(const Parameters& p) const { return stickslip::Validate(p); }
  std::optional<InvalidInput> ValidateClosedForm(const Parameters& p) const { return stickslip::ValidateClosedForm(p); }
  template <typename T>
  static T& ParameterAt(ParametersT<T>& p, int k) { return p[kAllParameters[k]]; }
  template <typename T>
  static const T& ParameterAt(const ParametersT<T>& p, int k) { return p[kAllParameters[k]]; }

  template <typename T>
  MotionT<T> MotionInMode(Mode mode, const StateT<T>& start, const T& phase, const ParametersT<T>& p) const {
    return stickslip::MotionInMode(mode, start, phase, p);
  }
  State Flow(Mode mode, const State& start, double phase, double s, const Parameters& p) const {
    return stickslip::Flow(mode, start, phase, s, p);
  }
  FlowDerivatives FlowWithDerivatives(Mode mode, const State& start, double phase, double s,
                                      const Parameters& p) const {
    return stickslip::FlowWithDerivatives(mode, start, phase, s, p);
  }
  // The flow's Jacobian with respect to the start state (flows.hpp), and the saltation matrix at
  // a segment's end (saltation.hpp): the monodromy's factors.
  template <typename T>
  Matrix4<T> TransitionMatrix(Mode mode, const T& s, const ParametersT<T>& p) const {
    return stickslip::TransitionMatrix(mode, s, p);
  }
  template <typename T>
  Matrix4<T> SaltationMatrix(Mode before, Mode after, const StateT<T>& x, const T& phase, const ParametersT<T>& p) const {
    return stickslip::SaltationMatrix(before, after, x, phase, p);
  }
  template <typename T>
  T ForcingFrequency(const ParametersT<T>& p) const { return p.omega; }
  // omega1 < omega2 of a slip (eq. 56), where the forced amplitude is singular.
  std::array<double, 2> NaturalFrequencies(const Parameters& p) const {
    const auto [omega1, omega2] = stickslip::NaturalFrequencies(p.chi, p.eta);
    return {omega1, omega2};
  }
  // Undamped: both.
  std::vector<double> UndampedSlipFrequencies(const Parameters& p) const {
    const std::array<double, 2> omega = NaturalFrequencies(p);
    return {omega[0], omega[1]};
  }

  static constexpr int kRestVelocityParameter = -1;  // a fixed ground
  bool Autonomous() const { return false; }
  template <typename T>
  T ContactVelocity(const StateT<T>& x, const ParametersT<T>&) const { return x(3); }
  // x2'' in a mode (eq. 2, 9).
  template <typename T>
  T ContactAcceleration(Mode mode, const StateT<T>& x, const T& phase, const ParametersT<T>& p) const {
    return Acceleration(mode, x, phase, p)(1);
  }
  State AtRest(const State& x, const Parameters&) const { return stickslip::AtRest(x); }
  // x2' within rounding of zero: a sampled state at a stop carries ~1e-15, and a slip started
  // from it would miss the stop that is due at once.
  bool NearRest(const State& x, const Parameters&) const {
    return std::abs(x(3)) <= 1e-12 * (1.0 + x.head<3>().lpNorm<Eigen::Infinity>());
  }

  template <typename T>
  T StickForce(const StateT<T>& x, const T& phase, const ParametersT<T>& p) const {
    return stickslip::StickForce(x, phase, p);
  }
  // ds/dt with m2 at rest (events.hpp).
  template <typename T>
  T StickForceRate(const StateT<T>& x, const T& phase, const ParametersT<T>& p) const {
    return stickslip::StickForceRate(x, phase, p);
  }
  template <typename T>
  T StaticThreshold(const ParametersT<T>& p) const { return p.eta * p.u_r; }  // eq. (4)
  double KineticForce(const Parameters& p) const { return p.eta * p.u_s; }  // eq. (2)
  double FrictionSlope() const { return 0.0; }
  // u_r = u_s (eq. 25, ERRATA): a slip may touch rest and go on.
  bool AbnormalStopsPossible(const Parameters& p) const { return std::abs(p.u_r - p.u_s) <= 1e-12 * p.u_r; }
  Mode ModeFromRest(const State& x, double phase, const Parameters& p) const {
    return stickslip::ModeFromRest(x, phase, p);
  }

  SinusoidSum ContactVelocityAlong(const Motion& motion) const { return CoordinateAlong(motion, 3); }
  // x1 (0) or x2 (1) along a motion; a stick holds x2 (eq. 9).
  SinusoidSum CoordinateAlong(const Motion& motion, int i) const { return stickslip::CoordinateAlong(motion, i); }
  bool HeldInStick(int i) const { return i == 1; }
  SinusoidSum StickForceAlong(const Motion& motion, double phase, const Parameters& p) const {
    return stickslip::StickForceAlong(motion, phase, p);
  }

  // For an integrator (integrable_oscillator_model.hpp), written from the equations of motion and
  // sharing no code with the closed forms above. The state's derivative: eq. (2) in a slip, with
  // u = -u_s sign(x2') (eq. 4); eq. (9) in a stick, where x2'' = 0.
  State VectorField(Mode mode, const State& x, double phase, const Parameters& p) const {
    State dx(x(2), x(3), -x(0) + p.chi * x(1), 0.0);
    if (mode == Mode::kStick) return dx;
    const double friction = -SlipDirection(mode) * p.u_s;
    dx(3) = -p.chi * p.eta * (x(1) - x(0)) + p.eta * friction + std::cos(phase);
    return dx;
  }
  // s of eq. (11): x2'' of eq. (2) is zero with x2' = 0 when eta u = chi eta (x2 - x1) - cos(phase).
  double HoldingForce(const State& x, double phase, const Parameters& p) const {
    return p.chi * p.eta * (x(1) - x(0)) - std::cos(phase);
  }
  // ds/dt with x2' = 0.
  double HoldingForceRate(const State& x, double phase, const Parameters& p) const {
    return -p.chi * p.eta * x(2) + p.omega * std::sin(phase);
  }
  // The spring term and the forcing amplitude 1.
  double HoldingForceScale(const State& x, const Parameters& p) const {
    return std::max(std::abs(p.chi * p.eta * (x(1) - x(0))), 1.0);
  }
};

}  // namespace stickslip
