// Closed-form flows of the three modes of motion (Pascal 2014, eqs. 5-10) and their exact
// derivatives.
//
// The state is X = (x1, x2, x1', x2'). A flow starts at a state and a forcing phase psi (the
// forcing during the mode is cos(omega s + psi), s the time elapsed in the mode) and advances it
// by s. The absolute phase at absolute time t is omega t + phi, so a segment starting at t0 has
// psi = omega t0 + phi.
#pragma once

#include <array>

#include <Eigen/Core>

#include "stickslip/model/flow_derivatives.hpp"
#include "stickslip/model/pascal_2014/modal.hpp"
#include "stickslip/model/mode.hpp"
#include "stickslip/model/pascal_2014/parameters.hpp"

namespace stickslip {

template <typename T>
using StateT = Eigen::Matrix<T, 4, 1>;
using State = StateT<double>;

// The motion in one mode from a given start, in spectral form:
//   X(s) = offset + drift s + sum_k (cos_k cos(nu_k s) + sin_k sin(nu_k s)).
// For a slip the frequencies are omega1, omega2 (free modes, eq. 55) and omega (forced
// response, eq. 7) and offset = -sign(x2') d0 (eq. 5, 8); this equals the paper's
// Z(t) = H(t)(Z0 - F0) + F(t). For a stick the only frequency is 1 (gamma_2 of eq. 58) and x2
// moves with drift x2'(0) (zero in a real stick).
template <typename T>
struct ModeMotion {
  struct Component {
    T frequency{};
    Vector2<T> cos_coefficient = Vector2<T>::Zero();
    Vector2<T> sin_coefficient = Vector2<T>::Zero();
  };
  Vector2<T> offset = Vector2<T>::Zero();
  Vector2<T> drift = Vector2<T>::Zero();
  std::array<Component, 3> components{};
  int component_count = 0;

  StateT<T> StateAt(const T& s) const {
    using std::cos;
    using std::sin;
    StateT<T> x;
    x.template head<2>() = offset + drift * s;
    x.template tail<2>() = drift;
    for (int k = 0; k < component_count; ++k) {
      const Component& c = components[k];
      const T cs = cos(c.frequency * s);
      const T sn = sin(c.frequency * s);
      x.template head<2>() += c.cos_coefficient * cs + c.sin_coefficient * sn;
      x.template tail<2>() += c.frequency * (c.sin_coefficient * cs - c.cos_coefficient * sn);
    }
    return x;
  }

  Vector2<T> AccelerationAt(const T& s) const {
    using std::cos;
    using std::sin;
    Vector2<T> a = Vector2<T>::Zero();
    for (int k = 0; k < component_count; ++k) {
      const Component& c = components[k];
      a -= c.frequency * c.frequency *
           (c.cos_coefficient * cos(c.frequency * s) + c.sin_coefficient * sin(c.frequency * s));
    }
    return a;
  }
};

template <typename T>
ModeMotion<T> MotionInMode(Mode mode, const StateT<T>& start, const T& phase,
                           const BasicParameters<T>& p) {
  using std::cos;
  using std::sin;
  ModeMotion<T> motion;
  const Vector2<T> x0 = start.template head<2>();
  const Vector2<T> v0 = start.template tail<2>();
  if (mode == Mode::kStick) {
    // x2 = x20 + x2'0 s; x1 - chi x2 oscillates at frequency 1 (Sigma, gamma_2 of eq. 58).
    motion.offset = Vector2<T>(p.chi * x0(1), x0(1));
    motion.drift = Vector2<T>(p.chi * v0(1), v0(1));
    auto& free = motion.components[0];
    free.frequency = T(1.0);
    free.cos_coefficient = Vector2<T>(x0(0) - p.chi * x0(1), T(0.0));
    free.sin_coefficient = Vector2<T>(v0(0) - p.chi * v0(1), T(0.0));
    motion.component_count = 1;
    return motion;
  }
  const double direction = SlipDirection(mode);
  motion.offset = StaticOffset(p.chi, p.u_s) * T(-direction);  // eq. (5), (8)
  const Vector2<T> q = ForcedAmplitude(p.chi, p.eta, p.omega);
  auto& forced = motion.components[0];  // R(s) = Q cos(omega s + psi), eq. (7)
  forced.frequency = p.omega;
  forced.cos_coefficient = q * cos(phase);
  forced.sin_coefficient = -q * sin(phase);
  // Free modes: Z - F = H(s)(Z0 - F0) (eq. 5) expanded on the eigenvectors psi_j (eq. 55).
  const auto [w1, w2] = NaturalFrequencies(p.chi, p.eta);
  const Matrix2<T> lambda = ModalMatrix(p.chi, w1, w2);
  const Matrix2<T> lambda_inv = ModalMatrixInverse(lambda);
  const Vector2<T> a = lambda_inv * (x0 - motion.offset - forced.cos_coefficient);
  const Vector2<T> b = lambda_inv * (v0 - p.omega * forced.sin_coefficient);
  const std::array<T, 2> w = {w1, w2};
  for (int j = 0; j < 2; ++j) {
    auto& c = motion.components[j + 1];
    c.frequency = w[j];
    c.cos_coefficient = lambda.col(j) * a(j);
    c.sin_coefficient = lambda.col(j) * (b(j) / w[j]);
  }
  motion.component_count = 3;
  return motion;
}

// The flow of a mode: the state after time s from `start` at forcing phase `phase`.
template <typename T>
StateT<T> Flow(Mode mode, const StateT<T>& start, const T& phase, const T& s,
               const BasicParameters<T>& p) {
  return MotionInMode(mode, start, phase, p).StateAt(s);
}

// The paper's flow with its derivatives (forward-mode automatic differentiation through the
// closed form above; no finite differences).
using FlowDerivatives = BasicFlowDerivatives<4, kParameterCount>;
FlowDerivatives FlowWithDerivatives(Mode mode, const State& start, double phase, double s,
                                    const Parameters& p);

// dX(s)/dX(0): the flow is affine in the start state, with the transition matrix H(s) of a slip
// (eq. 5, 55) or Gamma(s) of a stick (eq. 10, 58) as its linear part. Templated: the derivatives
// of the monodromy matrix come from AD through it (orbits/floquet_gradients.hpp).
template <typename T>
Matrix4<T> TransitionMatrix(Mode mode, const T& s, const BasicParameters<T>& p) {
  return mode == Mode::kStick ? StickTransition(p.chi, s) : SlipTransition(p.chi, p.eta, s);
}

// Right-hand side of eq. (2) in a mode, at a state and forcing phase: the accelerations
// (x1'', x2''). In a stick x2'' = 0 (eq. 9).
template <typename T>
Vector2<T> Acceleration(Mode mode, const StateT<T>& x, const T& phase,
                        const BasicParameters<T>& p) {
  using std::cos;
  const T a1 = -x(0) + p.chi * x(1);
  if (mode == Mode::kStick) return Vector2<T>(a1, T(0.0));
  const T friction = -double(SlipDirection(mode)) * p.u_s;  // u of eq. (4)
  return Vector2<T>(a1, -p.chi * p.eta * (x(1) - x(0)) + p.eta * friction + cos(phase));
}

}  // namespace stickslip
