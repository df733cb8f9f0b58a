// A linear oscillator with one Coulomb contact as an OscillatorModel (oscillator_model.hpp),
// at a fixed number N of coordinates (linear_oscillator_data.hpp gives the equations):
//   M q'' + K q = g cos(omega t + phi) + e_N F,
// slip (q_N' != 0): F = -F_k sign(q_N'); stick (q_N' = 0 held): F is what keeps q_N'' = 0,
// admissible while |F| <= F_s. The state is (q, q'); the contact's velocity is q_N'.
//
// In each mode the motion is exact, written in the mode's modal basis: with eta = P q,
//   eta_i(s) = c_i + d_i s + Q_i cos(omega s + psi) + a_i cos(omega_i s) + b_i sin(omega_i s),
// the static response c (+ d s) to the friction force in a slip or to the held coordinate in a
// stick, the forced response Q_i = (Phi^T g)_i / (omega_i^2 - omega^2), and the free oscillation
// that meets the start; in a stick q_N = q_N(0) + q_N'(0) s besides. The bases are computed once
// per model, so the parameters (omega, F_k, F_s) enter linearly or through Q_i: forward-mode AD
// runs through MotionInMode for every derivative the orbit layer asks for.
// The parameters are omega, F_k and F_s; the matrices are the model's data. Damping, a singular K,
// a belt, autonomous orbits and continuation in the matrices' entries come next.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>
#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/model/flow_derivatives.hpp"
#include "stickslip/model/linear_oscillator_data.hpp"
#include "stickslip/model/mode.hpp"
#include "stickslip/model/model_description.hpp"
#include "stickslip/numerics/sinusoid_sum.hpp"

namespace stickslip {

template <int N>
class LinearOscillator {
 public:
  static constexpr int kStateSize = 2 * N;
  static constexpr int kParameterCount = 3;
  static constexpr int kForcingFrequencyParameter = 0;
  static constexpr int kKineticLevelParameter = 1;
  static constexpr int kStaticLevelParameter = 2;
  static constexpr int kContact = N - 1;  // the coordinate the contact is on
  template <typename T>
  using StateT = Eigen::Matrix<T, 2 * N, 1>;
  template <typename T>
  struct ParametersT {
    T omega{};  // forcing frequency, rad/s
    T F_k{};    // kinetic friction force
    T F_s{};    // static friction force, >= F_k
  };
  using State = StateT<double>;
  using Parameters = ParametersT<double>;
  using FlowDerivatives = BasicFlowDerivatives<2 * N, 3>;
  template <typename T>
  static T& ParameterAt(ParametersT<T>& p, int k) { return k == 0 ? p.omega : k == 1 ? p.F_k : p.F_s; }
  template <typename T>
  static const T& ParameterAt(const ParametersT<T>& p, int k) { return k == 0 ? p.omega : k == 1 ? p.F_k : p.F_s; }

  using Square = Eigen::Matrix<double, N, N>;
  using Vector = Eigen::Matrix<double, N, 1>;
  using Row = Eigen::Matrix<double, 1, N>;
  // A mode's modal basis at fixed size; modes beyond `count` have zero shapes (lambda 1, unused).
  struct Basis {
    Square shapes = Square::Zero(), projector = Square::Zero();
    Vector eigenvalues = Vector::Ones(), frequencies = Vector::Ones();
    Vector forcing = Vector::Zero();     // Phi^T g
    Vector contact = Vector::Zero();     // Phi^T e_N: the friction force's modal load (a slip)
    Vector coupling = Vector::Zero();    // Phi^T K e_N: the held coordinate's load (a stick)
    int count = 0;
  };

  // A motion points at its model's basis: the model must outlive the motions it makes.
  template <typename T>
  struct MotionT {
    const Basis* basis = nullptr;
    bool holds = false;            // a stick: q_N = held_position + held_velocity s
    T omega{}, phase{}, held_position{}, held_velocity{};
    Eigen::Matrix<T, N, 1> constant, slope, forced, a, b;  // per mode, as in the header comment

    StateT<T> StateAt(const T& s) const {
      using std::cos;
      using std::sin;
      const T zero = omega * 0.0;
      Eigen::Matrix<T, N, 1> eta = Eigen::Matrix<T, N, 1>::Constant(zero), rate = eta;
      const T c = cos(omega * s + phase), sn = sin(omega * s + phase);
      for (int i = 0; i < basis->count; ++i) {
        const double w = basis->frequencies(i);
        const T ci = cos(w * s), si = sin(w * s);
        eta(i) = constant(i) + slope(i) * s + forced(i) * c + a(i) * ci + b(i) * si;
        rate(i) = slope(i) - forced(i) * omega * sn + w * (b(i) * ci - a(i) * si);
      }
      StateT<T> x;
      x.template head<N>() = Times(basis->shapes, eta, zero);
      x.template tail<N>() = Times(basis->shapes, rate, zero);
      if (holds) {
        x(kContact) += held_position + held_velocity * s;
        x(N + kContact) += held_velocity;
      }
      return x;
    }
  };
  using Motion = MotionT<double>;

  // Throws InvalidInput when the data is not a valid model of N coordinates (ModesOf).
  explicit LinearOscillator(const LinearOscillatorData& data) {
    if (data.mass.rows() != N) {
      throw InvalidInput("mass", fmt::format("a {}x{} matrix", data.mass.rows(), data.mass.cols()),
                         fmt::format("{0}x{0} for this model", N));
    }
    const LinearOscillatorModes modes = ModesOf(data);
    description_ = DescribeLinearOscillator(data, modes);
    mass_ = data.mass;
    stiffness_ = data.stiffness;
    forcing_ = data.forcing;
    mass_factor_ = mass_.llt();
    compliance_ = mass_factor_.solve(Square::Identity());
    slip_ = BasisOf(modes.slip, data);
    stick_ = BasisOf(modes.stick, data);
    holding_stiffness_ = modes.holding_stiffness;
    holding_forcing_ = modes.holding_forcing;
  }
  const ModelDescription& Description() const { return description_; }

  // The closed forms need a forcing frequency away from every natural frequency of a slip and of
  // a stick (Q_i has omega_i^2 - omega^2 in its denominator).
  std::optional<InvalidInput> ValidateClosedForm(const Parameters& p) const {
    const ParameterDescription& d = description_.parameters[0];
    if (!(p.omega >= d.minimum && p.omega <= d.maximum)) return InvalidInput("omega", p.omega, d.range);
    for (const Basis* basis : {&slip_, &stick_}) {
      for (int i = 0; i < basis->count; ++i) {
        if (std::abs(p.omega * p.omega - basis->eigenvalues(i)) <= 1e-9 * basis->eigenvalues(i)) {
          return InvalidInput("omega", p.omega,
                              fmt::format("{} away from the natural frequency {:.10g} of a {}", d.range,
                                          basis->frequencies(i), basis == &slip_ ? "slip" : "stick"));
        }
      }
    }
    return std::nullopt;
  }
  std::optional<InvalidInput> Validate(const Parameters& p) const {
    if (auto invalid = ValidateClosedForm(p)) return invalid;
    const ParameterDescription& k = description_.parameters[1];
    if (!(p.F_k >= k.minimum && p.F_k <= k.maximum)) return InvalidInput("F_k", p.F_k, k.range);
    if (!(p.F_s >= p.F_k && p.F_s <= k.maximum)) {
      return InvalidInput("F_s", p.F_s, fmt::format("F_k = {} <= F_s <= {:g}", p.F_k, k.maximum));
    }
    return std::nullopt;
  }

  template <typename T>
  MotionT<T> MotionInMode(Mode mode, const StateT<T>& start, const T& phase, const ParametersT<T>& p) const {
    return MotionFrom(mode, start, phase, p, true);
  }
  template <typename T>
  StateT<T> Flow(Mode mode, const StateT<T>& start, const T& phase, const T& s, const ParametersT<T>& p) const {
    return MotionInMode(mode, start, phase, p).StateAt(s);
  }
  FlowDerivatives FlowWithDerivatives(Mode mode, const State& start, double phase, double s, const Parameters& p) const {
    constexpr int kDirections = 2 * N + 2 + 3;  // start, phase, elapsed time, parameters
    using Dual = Eigen::AutoDiffScalar<Eigen::Matrix<double, kDirections, 1>>;
    StateT<Dual> x;
    for (int j = 0; j < 2 * N; ++j) x(j) = Dual(start(j), kDirections, j);
    ParametersT<Dual> p_dual;
    for (int k = 0; k < 3; ++k) ParameterAt(p_dual, k) = Dual(ParameterAt(p, k), kDirections, 2 * N + 2 + k);
    const StateT<Dual> end = Flow(mode, x, Dual(phase, kDirections, 2 * N), Dual(s, kDirections, 2 * N + 1), p_dual);
    FlowDerivatives d;
    for (int i = 0; i < 2 * N; ++i) {
      d.state(i) = end(i).value();
      d.d_start.row(i) = end(i).derivatives().template head<2 * N>().transpose();
      d.d_phase(i) = end(i).derivatives()(2 * N);
      d.d_elapsed(i) = end(i).derivatives()(2 * N + 1);
      d.d_parameters.row(i) = end(i).derivatives().template tail<3>().transpose();
    }
    return d;
  }
  // The flow is affine in the start; its linear part is the motion without forcing or friction.
  template <typename T>
  Eigen::Matrix<T, 2 * N, 2 * N> TransitionMatrix(Mode mode, const T& s, const ParametersT<T>& p) const {
    Eigen::Matrix<T, 2 * N, 2 * N> m;
    for (int j = 0; j < 2 * N; ++j) {
      StateT<T> unit = StateT<T>::Constant(ZeroLike(p));
      unit(j) += 1.0;
      m.col(j) = MotionFrom(mode, unit, ZeroLike(p), p, false).StateAt(s);
    }
    return m;
  }
  // S = I + (f+ - f-) grad(h)^T / (grad(h) . f- + dh/dt) (Leine & Nijmeijer 2004): the fields
  // differ in the accelerations only; h = q_N' at a stop, h = F(q, t) -+ F_s at a stick's end.
  template <typename T>
  Eigen::Matrix<T, 2 * N, 2 * N> SaltationMatrix(Mode before, Mode after, const StateT<T>& x, const T& phase,
                                                 const ParametersT<T>& p) const {
    Eigen::Matrix<T, 2 * N, 2 * N> m = Eigen::Matrix<T, 2 * N, 2 * N>::Constant(ZeroLike(p));
    for (int j = 0; j < 2 * N; ++j) m(j, j) += 1.0;
    if (before == after) return m;  // an abnormal stop
    const Eigen::Matrix<T, N, 1> jump = Acceleration(after, x, phase, p) - Acceleration(before, x, phase, p);
    if (before != Mode::kStick) {
      m.col(N + kContact).template tail<N>() += jump / ContactAcceleration(before, x, phase, p);
    } else {
      StateT<T> at_rest = x;
      at_rest(N + kContact) = ZeroLike(p);
      const T rate = StickForceRate(at_rest, phase, p);
      for (int i = 0; i < N; ++i) {
        for (int j = 0; j < N; ++j) m(N + i, j) += jump(i) * holding_stiffness_(j) / rate;
      }
    }
    return m;
  }
  template <typename T>
  T ForcingFrequency(const ParametersT<T>& p) const { return p.omega; }

  template <typename T>
  T ContactVelocity(const StateT<T>& x) const { return x(N + kContact); }
  // q'' in a mode: M^-1 (g cos psi - K q + e_N F), with F = -F_k sign(q_N') in a slip and the
  // holding force in a stick.
  template <typename T>
  Eigen::Matrix<T, N, 1> Acceleration(Mode mode, const StateT<T>& x, const T& phase, const ParametersT<T>& p) const {
    using std::cos;
    // (Each branch made a T: a conditional between AD expression types would keep a dangling one.)
    const T friction = mode == Mode::kStick ? StickForce(x, phase, p) : T(-double(SlipDirection(mode)) * p.F_k);
    const T zero = ZeroLike(p);
    Eigen::Matrix<T, N, 1> load = Times(Square(-stiffness_), Eigen::Matrix<T, N, 1>(x.template head<N>()), zero);
    for (int i = 0; i < N; ++i) load(i) += forcing_(i) * cos(phase);
    load(kContact) += friction;
    Eigen::Matrix<T, N, 1> q2 = Times(compliance_, load, zero);
    if (mode == Mode::kStick) q2(kContact) = zero;  // exactly, not to rounding
    return q2;
  }
  template <typename T>
  T ContactAcceleration(Mode mode, const StateT<T>& x, const T& phase, const ParametersT<T>& p) const {
    return Acceleration(mode, x, phase, p)(kContact);
  }
  State AtRest(const State& x) const {
    State y = x;
    y(N + kContact) = 0.0;
    return y;
  }
  bool NearRest(const State& x) const {
    return std::abs(x(N + kContact)) <= 1e-12 * (1.0 + x.template head<N>().cwiseAbs().maxCoeff());
  }

  // The friction force a stick needs; F > F_s drives the contact towards negative q_N.
  template <typename T>
  T StickForce(const StateT<T>& x, const T& phase, const ParametersT<T>&) const {
    using std::cos;
    return Dot(holding_stiffness_, x.template head<N>()) - holding_forcing_ * cos(phase);
  }
  template <typename T>
  T StickForceRate(const StateT<T>& x, const T& phase, const ParametersT<T>& p) const {
    using std::sin;
    return Dot(holding_stiffness_, x.template tail<N>()) + holding_forcing_ * p.omega * sin(phase);
  }
  template <typename T>
  T StaticThreshold(const ParametersT<T>& p) const { return p.F_s; }
  bool AbnormalStopsPossible(const Parameters& p) const { return std::abs(p.F_s - p.F_k) <= 1e-12 * p.F_s; }
  Mode ModeFromRest(const State& x, double phase, const Parameters& p) const {
    const double f = StickForce(x, phase, p);
    if (f > p.F_s) return Mode::kSlipNegative;
    if (f < -p.F_s) return Mode::kSlipPositive;
    return Mode::kStick;
  }

  SinusoidSum ContactVelocityAlong(const Motion& motion) const { return CoordinateAlong(motion, kContact).Derivative(); }
  SinusoidSum CoordinateAlong(const Motion& motion, int j) const { return Along(motion, Row::Unit(j), 0.0); }
  bool HeldInStick(int j) const { return j == kContact; }
  SinusoidSum StickForceAlong(const Motion& motion, double, const Parameters&) const {
    return Along(motion, holding_stiffness_, -holding_forcing_);
  }

  // For an integrator (integrable_oscillator_model.hpp), from the equations of motion alone: the
  // accelerations by solving with M (in a stick with M's free block, q_N'' = 0), not the modes.
  State VectorField(Mode mode, const State& x, double phase, const Parameters& p) const {
    State dx;
    dx.template head<N>() = x.template tail<N>();
    if (mode == Mode::kStick) {
      dx.template tail<N>() = HeldAcceleration(x, phase);
    } else {
      Vector load = forcing_ * std::cos(phase) - stiffness_ * x.template head<N>();
      load(kContact) -= SlipDirection(mode) * p.F_k;
      dx.template tail<N>() = mass_factor_.solve(load);
    }
    return dx;
  }
  // The contact's row of M q'' + K q = g cos psi + F with the held accelerations.
  double HoldingForce(const State& x, double phase, const Parameters&) const {
    return mass_.row(kContact).dot(HeldAcceleration(x, phase)) + stiffness_.row(kContact).dot(x.template head<N>()) -
           forcing_(kContact) * std::cos(phase);
  }
  double HoldingForceRate(const State& x, double phase, const Parameters& p) const {
    const double omega = p.omega;
    Vector jerk = Vector::Zero();
    if constexpr (N > 1) {
      const Eigen::Matrix<double, N - 1, 1> load =
          -forcing_.template head<N - 1>() * omega * std::sin(phase) - stiffness_.template topRows<N - 1>() * x.template tail<N>();
      jerk.template head<N - 1>() = mass_.template topLeftCorner<N - 1, N - 1>().llt().solve(load);
    }
    return mass_.row(kContact).dot(jerk) + stiffness_.row(kContact).dot(x.template tail<N>()) +
           forcing_(kContact) * omega * std::sin(phase);
  }
  double HoldingForceScale(const State& x, const Parameters& p) const {
    return std::max(stiffness_.row(kContact).cwiseAbs().dot(x.template head<N>().cwiseAbs()) + std::abs(forcing_(kContact)), p.F_s);
  }

 private:
  Basis BasisOf(const ModalBasis& modal, const LinearOscillatorData& data) const {
    Basis basis;
    basis.count = static_cast<int>(modal.eigenvalues.size());
    basis.shapes.leftCols(basis.count) = modal.shapes;
    basis.projector.topRows(basis.count) = modal.projector;
    basis.eigenvalues.head(basis.count) = modal.eigenvalues;
    basis.frequencies = basis.eigenvalues.cwiseSqrt();
    basis.forcing.head(basis.count) = modal.shapes.transpose() * data.forcing;
    basis.contact.head(basis.count) = modal.shapes.row(kContact).transpose();
    basis.coupling.head(basis.count) = modal.shapes.transpose() * data.stiffness.col(kContact);
    return basis;
  }
  // Forward-mode AD with derivative vectors of run-time size (the orbit layer's gradients) needs
  // every value to carry derivatives of one size: constants are made from a parameter, never T(c),
  // and products with the model's matrices are written out.
  template <typename T>
  static T ZeroLike(const ParametersT<T>& p) { return T(p.omega * 0.0); }
  template <typename T, typename Vec>
  static Eigen::Matrix<T, N, 1> Times(const Square& a, const Vec& v, const T& zero) {
    Eigen::Matrix<T, N, 1> product = Eigen::Matrix<T, N, 1>::Constant(zero);
    for (int i = 0; i < N; ++i) {
      for (int j = 0; j < N; ++j) product(i) += a(i, j) * v(j);
    }
    return product;
  }
  template <typename Vec>
  static auto Dot(const Row& w, const Vec& v) {
    typename Vec::Scalar sum = w(0) * v(0);
    for (int j = 1; j < N; ++j) sum += w(j) * v(j);
    return sum;
  }
  // `loaded`: with the forcing and the friction force (the flow), or without (its linear part).
  template <typename T>
  MotionT<T> MotionFrom(Mode mode, const StateT<T>& start, const T& phase, const ParametersT<T>& p, bool loaded) const {
    using std::cos;
    using std::sin;
    const bool stick = mode == Mode::kStick;
    MotionT<T> m;
    m.basis = stick ? &stick_ : &slip_;
    m.holds = stick;
    m.omega = p.omega;
    m.phase = phase;
    const T zero = ZeroLike(p);
    m.held_position = stick ? start(kContact) : zero;
    m.held_velocity = stick ? start(N + kContact) : zero;
    const Basis& b = *m.basis;
    const T friction = stick || !loaded ? zero : T(-double(SlipDirection(mode)) * p.F_k);
    const Eigen::Matrix<T, N, 1> eta0 = Times(b.projector, Eigen::Matrix<T, N, 1>(start.template head<N>()), zero);
    const Eigen::Matrix<T, N, 1> rate0 = Times(b.projector, Eigen::Matrix<T, N, 1>(start.template tail<N>()), zero);
    for (int i = 0; i < N; ++i) {
      const double lambda = b.eigenvalues(i);
      // A slip's static response to the friction force; a stick's to the held coordinate.
      m.constant(i) = (friction * b.contact(i) - b.coupling(i) * m.held_position) / lambda;
      m.slope(i) = -b.coupling(i) * m.held_velocity / lambda;
      m.forced(i) = loaded ? T(b.forcing(i) / (lambda - p.omega * p.omega)) : zero;
      m.a(i) = eta0(i) - m.constant(i) - m.forced(i) * cos(phase);
      m.b(i) = (rate0(i) - m.slope(i) + m.forced(i) * p.omega * sin(phase)) / b.frequencies(i);
    }
    return m;
  }
  // q'' in a stick from the equations: q_N'' = 0 and M_rr q_r'' = g_r cos psi - (K q)_r.
  Vector HeldAcceleration(const State& x, double phase) const {
    Vector q2 = Vector::Zero();
    if constexpr (N > 1) {
      const Eigen::Matrix<double, N - 1, 1> load =
          forcing_.template head<N - 1>() * std::cos(phase) - stiffness_.template topRows<N - 1>() * x.template head<N>();
      q2.template head<N - 1>() = mass_.template topLeftCorner<N - 1, N - 1>().llt().solve(load);
    }
    return q2;
  }
  // w . q(s) + forcing_weight cos(omega s + psi) along a motion, as a sum the root finder searches.
  SinusoidSum Along(const Motion& m, const Row& w, double forcing_weight) const {
    const Row weights = w * m.basis->shapes;
    const double held = m.holds ? w(kContact) : 0.0;
    const double forced = (weights * m.forced)(0) + forcing_weight;
    std::vector<Sinusoid> terms{{m.omega, forced * std::cos(m.phase), -forced * std::sin(m.phase)}};
    for (int i = 0; i < m.basis->count; ++i) {
      terms.push_back({m.basis->frequencies(i), weights(i) * m.a(i), weights(i) * m.b(i)});
    }
    return SinusoidSum((weights * m.constant)(0) + held * m.held_position, (weights * m.slope)(0) + held * m.held_velocity,
                       std::move(terms));
  }

  ModelDescription description_;
  Square mass_, stiffness_, compliance_;
  Vector forcing_;
  Eigen::LLT<Square> mass_factor_;
  Basis slip_, stick_;
  Row holding_stiffness_;
  double holding_forcing_ = 0.0;
};

}  // namespace stickslip
