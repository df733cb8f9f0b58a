// A linear oscillator with one Coulomb contact as an OscillatorModel (oscillator_model.hpp),
// at N coordinates (linear_oscillator_data.hpp gives the equations): fixed at compile time, or
// Eigen::Dynamic for a model whose size comes from a file (DynamicLinearOscillator), which pays
// for its heap-allocated states what a fixed size does not:
//   M q'' + C q' + K q = g cos(omega t + phi) + e_N F,
// the contact against a surface moving at the speed v_b (a belt; 0 for a fixed surface), its
// relative velocity s = q_N' - v_b; slip (s != 0): F = -(F_k + alpha |s|) sign(s), alpha the
// data's friction slope (0: Coulomb's constant level); stick (s = 0 held): F is what keeps
// q_N'' = 0, admissible while |F| <= F_s. The state is (q, q'). Without forcing
// (g = 0) the model is autonomous: its orbits (self-excited stick-slip on a belt) have a period
// that is an unknown.
//
// In each mode the components y of the state that move obey y' = A y + e + f s + b cos(psi),
// psi = omega s + phase (e: the friction force in a slip, the held q_N in a stick; f: the held
// q_N' in a stick), solved exactly as
//   y(s) = alpha + beta s + Re(Z e^{i psi}) + sum_k V_k d_k e^{lambda_k s},
// beta = -A^-1 f, alpha = A^-1 (beta - e), Z = (i omega - A)^-1 b = sum_k V_k (W b)_k / (i omega - lambda_k),
// d = W (y(0) - the particular part at 0). The bases (A's eigenvectors V, W = V^-1) are computed
// once per model, so the parameters (omega, F_k, F_s) enter linearly or through
// 1/(i omega - lambda_k): forward-mode AD runs through MotionInMode for every derivative the orbit
// layer asks for, and every function along a mode is an ExponentialSum for the root finder.
// The parameters are omega, F_k, F_s and v_b; the matrices are the model's data. A singular K, a
// belt speed varying in time and continuation in the matrices' entries come next.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <limits>
#include <optional>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>
#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/model/coulomb_at_rest.hpp"
#include "stickslip/model/flow_derivatives.hpp"
#include "stickslip/model/linear_oscillator_data.hpp"
#include "stickslip/model/mode.hpp"
#include "stickslip/model/model_description.hpp"
#include "stickslip/numerics/exponential_sum.hpp"

namespace stickslip {

template <int N>
class LinearOscillator {
 public:
  static constexpr int kStateSize = N == Eigen::Dynamic ? Eigen::Dynamic : 2 * N;
  static constexpr int kParameterCount = 4;
  static constexpr int kForcingFrequencyParameter = 0;
  static constexpr int kKineticLevelParameter = 1;
  static constexpr int kStaticLevelParameter = 2;
  static constexpr int kRestVelocityParameter = 3;
  template <typename T>
  using StateT = Eigen::Matrix<T, kStateSize, 1>;
  template <typename T>
  using CoordinatesT = Eigen::Matrix<T, N, 1>;  // q, q' or q''
  template <typename T>
  struct ParametersT {
    T omega{};  // forcing frequency, rad/s
    T F_k{};    // kinetic friction force
    T F_s{};    // static friction force, >= F_k
    T v_b{};    // the surface's (belt's) speed
  };
  using State = StateT<double>;
  using Parameters = ParametersT<double>;
  using FlowDerivatives = BasicFlowDerivatives<kStateSize, 4>;
  using EventFunction = ExponentialSum;
  template <typename T>
  static T& ParameterAt(ParametersT<T>& p, int k) { return k == 0 ? p.omega : k == 1 ? p.F_k : k == 2 ? p.F_s : p.v_b; }
  template <typename T>
  static const T& ParameterAt(const ParametersT<T>& p, int k) {
    return k == 0 ? p.omega : k == 1 ? p.F_k : k == 2 ? p.F_s : p.v_b;
  }

  using Real = Eigen::Matrix<double, kStateSize, kStateSize>;
  using Complex = Eigen::Matrix<std::complex<double>, kStateSize, kStateSize>;
  using Vector = Eigen::Matrix<double, kStateSize, 1>;
  using Indices = Eigen::Matrix<int, kStateSize, 1>;
  // A mode's first-order basis at the state's size, on its first `size` entries (FirstOrderBasis).
  struct Basis {
    int size = 0;
    int state_size = 0;        // 2n
    int contact = 0;           // the state's index of q_n, the coordinate the contact is on
    int contact_velocity = 0;  // of q_n'
    Indices component;
    Real inverse;
    Complex shapes, projector;
    Eigen::Matrix<std::complex<double>, kStateSize, 1> eigenvalues;
    Complex forced_shapes;  // column k: V_k (W b)_k
    Vector forcing, friction, held_position, held_velocity;
    // 2 for the first of a complex-conjugate pair (its real part counts twice), 1 for a real
    // eigenvalue, 0 for the second of a pair.
    Indices weight;
  };

  // A motion points at its model's basis: the model must outlive the motions it makes.
  template <typename T>
  struct MotionT {
    const Basis* basis = nullptr;
    bool holds = false;  // a stick: q_N = held_position + held_velocity s
    T omega{}, phase{}, held_position{}, held_velocity{}, rest_velocity{};
    StateT<T> alpha, beta, forced_re, forced_im, d_re, d_im;  // on the basis's components, as in the header

    StateT<T> StateAt(const T& s) const {
      using std::cos;
      using std::exp;
      using std::sin;
      const T psi = omega * s + phase;
      const T c = cos(psi), sn = sin(psi);
      StateT<T> x = StateT<T>::Constant(basis->state_size, omega * 0.0);
      for (int i = 0; i < basis->size; ++i) {
        x(basis->component(i)) = alpha(i) + beta(i) * s + forced_re(i) * c - forced_im(i) * sn;
      }
      for (int k = 0; k < basis->size; ++k) {
        if (basis->weight(k) == 0) continue;
        const std::complex<double> lambda = basis->eigenvalues(k);
        const T growth = exp(lambda.real() * s) * double(basis->weight(k));
        const T p = growth * (d_re(k) * cos(lambda.imag() * s) - d_im(k) * sin(lambda.imag() * s));
        const T q = growth * (d_re(k) * sin(lambda.imag() * s) + d_im(k) * cos(lambda.imag() * s));
        for (int i = 0; i < basis->size; ++i) {
          x(basis->component(i)) += basis->shapes(i, k).real() * p - basis->shapes(i, k).imag() * q;
        }
      }
      if (holds) {
        x(basis->contact) += held_position + held_velocity * s;
        x(basis->contact_velocity) += held_velocity;
      }
      return x;
    }
  };
  using Motion = MotionT<double>;

  // Throws InvalidInput when the data is not a valid model of N coordinates (ModesOf).
  explicit LinearOscillator(const LinearOscillatorData& data) {
    if (N != Eigen::Dynamic && data.mass.rows() != N) {
      throw InvalidInput("mass", fmt::format("a {}x{} matrix", data.mass.rows(), data.mass.cols()),
                         fmt::format("{0}x{0} for this model", N));
    }
    const LinearOscillatorModes modes = ModesOf(data);
    n_ = static_cast<int>(data.mass.rows());
    description_ = DescribeLinearOscillator(data, modes);
    mass_ = data.mass;
    stiffness_ = data.stiffness;
    damping_ = data.damping.size() == 0 ? Square::Zero(n_, n_) : Square(data.damping);
    forcing_ = data.forcing;
    friction_slope_ = data.friction_slope;
    mass_factor_ = mass_.llt();
    compliance_ = mass_factor_.solve(Square::Identity(n_, n_));
    // Always computed: copying an uncomputed Eigen::LLT reads its uninitialised status.
    if (n_ > 1) {
      held_mass_factor_.compute(mass_.topLeftCorner(n_ - 1, n_ - 1));
    } else {
      held_mass_factor_.compute(FreeSquare::Identity(1, 1));
    }
    slip_ = BasisOf(modes.slip);
    stick_ = BasisOf(modes.stick);
    // Undamped, a mode's eigenvalues are +-i omega_k exactly: their rounding-level real parts are
    // dropped, so that its functions are pure sinusoid sums (exponential_sum.hpp's faster search).
    if (damping_.isZero()) stick_.eigenvalues.real().setZero();
    if (UndampedSlip()) slip_.eigenvalues.real().setZero();
    holding_ = modes.holding;
    holding_forcing_ = modes.holding_forcing;
  }

  const ModelDescription& Description() const { return description_; }
  // The data it was built from (C zero where none was given): what a run's fingerprint hashes.
  LinearOscillatorData Data() const {
    return {mass_,          damping_,          stiffness_,       forcing_,
            friction_slope_, description_.coordinates, description_.name, description_.units};
  }
  // The number n of coordinates and the state's size 2n (compile-time constants at a fixed size).
  int Coordinates() const {
    if constexpr (N == Eigen::Dynamic) {
      return n_;
    } else {
      return N;
    }
  }
  int StateSize() const { return 2 * Coordinates(); }
  // The coordinate the contact is on (the last), and its velocity's index in the state.
  int Contact() const { return Coordinates() - 1; }
  int ContactVelocityIndex() const { return 2 * Coordinates() - 1; }
  bool Autonomous() const { return forcing_.isZero(); }
  // Without damping (nor a friction slope, which damps a slip) a slip's eigenvalues are +-i omega_k:
  // the omega_k, each once.
  bool UndampedSlip() const { return damping_.isZero() && friction_slope_ == 0.0; }
  std::vector<double> UndampedSlipFrequencies(const Parameters&) const {
    std::vector<double> omega;
    if (!UndampedSlip()) return omega;
    for (int k = 0; k < slip_.size; ++k) {
      if (slip_.weight(k) == 2) omega.push_back(std::abs(slip_.eigenvalues(k).imag()));
    }
    std::sort(omega.begin(), omega.end());
    return omega;
  }

  // The closed forms need a forcing frequency away from every lightly damped natural frequency of
  // a slip and of a stick: Z has 1/(i omega - lambda_k), and within kResonanceGap (relative) the
  // cancellation between the forced and the free motion would cost more than 1e-10 of the motion.
  static constexpr double kResonanceGap = 1e-6;
  std::optional<InvalidInput> ValidateClosedForm(const Parameters& p) const {
    if (Autonomous()) {  // no forcing: omega plays no part, but is a number
      if (std::isfinite(p.omega) && p.omega > 0.0) return std::nullopt;
      return InvalidInput("omega", p.omega, "a finite value > 0 (without forcing it plays no part)");
    }
    const ParameterDescription& d = description_.parameters[0];
    if (!(p.omega >= d.minimum && p.omega <= d.maximum)) return InvalidInput("omega", p.omega, d.range);
    for (const Basis* basis : {&slip_, &stick_}) {
      for (int k = 0; k < basis->size; ++k) {
        const std::complex<double> lambda = basis->eigenvalues(k);
        if (std::abs(std::complex<double>(0.0, p.omega) - lambda) <= kResonanceGap * std::abs(lambda)) {
          return InvalidInput("omega", p.omega,
                              fmt::format("{:.6g} <= omega <= {:.6g}, at least {:g} (relative) away from the natural "
                                          "frequency {:.10g} of a {}",
                                          d.minimum, d.maximum, kResonanceGap, std::abs(lambda),
                                          basis == &slip_ ? "slip" : "stick"));
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
    const ParameterDescription& v = description_.parameters[3];
    if (!(p.v_b >= v.minimum && p.v_b <= v.maximum)) return InvalidInput("v_b", p.v_b, v.range);
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
    // Directions: the start, the phase, the elapsed time, the parameters.
    constexpr int kDirections = N == Eigen::Dynamic ? Eigen::Dynamic : 2 * N + 2 + 4;
    using Dual = Eigen::AutoDiffScalar<Eigen::Matrix<double, kDirections, 1>>;
    const int S = StateSize(), directions = S + 2 + 4;
    StateT<Dual> x(S);
    for (int j = 0; j < S; ++j) x(j) = Dual(start(j), directions, j);
    ParametersT<Dual> p_dual;
    for (int k = 0; k < 4; ++k) ParameterAt(p_dual, k) = Dual(ParameterAt(p, k), directions, S + 2 + k);
    const StateT<Dual> end = Flow(mode, x, Dual(phase, directions, S), Dual(s, directions, S + 1), p_dual);
    FlowDerivatives d{State(S), Real(S, S), State(S), State(S), typename FlowDerivatives::ParameterMatrix(S, 4)};
    for (int i = 0; i < S; ++i) {
      d.state(i) = end(i).value();
      d.d_start.row(i) = end(i).derivatives().head(S).transpose();
      d.d_phase(i) = end(i).derivatives()(S);
      d.d_elapsed(i) = end(i).derivatives()(S + 1);
      d.d_parameters.row(i) = end(i).derivatives().tail(4).transpose();
    }
    return d;
  }
  // The flow is affine in the start; its linear part is the motion without forcing or friction.
  template <typename T>
  Eigen::Matrix<T, kStateSize, kStateSize> TransitionMatrix(Mode mode, const T& s, const ParametersT<T>& p) const {
    const int S = StateSize();
    Eigen::Matrix<T, kStateSize, kStateSize> m(S, S);
    for (int j = 0; j < S; ++j) {
      StateT<T> unit = StateT<T>::Constant(S, ZeroLike(p));
      unit(j) += 1.0;
      m.col(j) = MotionFrom(mode, unit, ZeroLike(p), p, false).StateAt(s);
    }
    return m;
  }
  // S = I + (f+ - f-) grad(h)^T / (grad(h) . f- + dh/dt) (Leine & Nijmeijer 2004): the fields
  // differ in the accelerations only; h = s at a stop, h = F(q, q', t) -+ F_s at a stick's end.
  template <typename T>
  Eigen::Matrix<T, kStateSize, kStateSize> SaltationMatrix(Mode before, Mode after, const StateT<T>& x, const T& phase,
                                                           const ParametersT<T>& p) const {
    const int n = Coordinates(), S = StateSize();
    Eigen::Matrix<T, kStateSize, kStateSize> m = Eigen::Matrix<T, kStateSize, kStateSize>::Constant(S, S, ZeroLike(p));
    for (int j = 0; j < S; ++j) m(j, j) += 1.0;
    if (before == after) return m;  // an abnormal stop
    const CoordinatesT<T> jump = Acceleration(after, x, phase, p) - Acceleration(before, x, phase, p);
    if (before != Mode::kStick) {
      const T slope = ContactAcceleration(before, x, phase, p);
      for (int i = 0; i < n; ++i) m(n + i, ContactVelocityIndex()) += jump(i) / slope;
    } else {
      StateT<T> at_rest = x;
      at_rest(ContactVelocityIndex()) = p.v_b;
      const T rate = StickForceRate(at_rest, phase, p);
      for (int i = 0; i < n; ++i) {
        for (int j = 0; j < S; ++j) m(n + i, j) += jump(i) * holding_(j) / rate;
      }
    }
    return m;
  }
  template <typename T>
  T ForcingFrequency(const ParametersT<T>& p) const { return p.omega; }

  template <typename T>
  T ContactVelocity(const StateT<T>& x, const ParametersT<T>& p) const { return x(ContactVelocityIndex()) - p.v_b; }
  // The friction force in a slip: -(F_k + alpha |s|) sign(s) = -F_k sign(s) - alpha s.
  template <typename T>
  T SlipForce(Mode mode, const StateT<T>& x, const ParametersT<T>& p) const {
    return T(-double(SlipDirection(mode)) * p.F_k - friction_slope_ * (x(ContactVelocityIndex()) - p.v_b));
  }
  // q'' in a mode: M^-1 (g cos psi - K q - C q' + e_N F), with F = SlipForce in a slip and the
  // holding force in a stick (then q_N'' = 0 exactly).
  template <typename T>
  CoordinatesT<T> Acceleration(Mode mode, const StateT<T>& x, const T& phase, const ParametersT<T>& p) const {
    using std::cos;
    const int n = Coordinates();
    // (Each branch made a T: a conditional between AD expression types would keep a dangling one.)
    const T friction = mode == Mode::kStick ? StickForce(x, phase, p) : SlipForce(mode, x, p);
    CoordinatesT<T> load = CoordinatesT<T>::Constant(n, ZeroLike(p));
    for (int i = 0; i < n; ++i) {
      load(i) += forcing_(i) * cos(phase);
      for (int j = 0; j < n; ++j) load(i) -= stiffness_(i, j) * x(j) + damping_(i, j) * x(n + j);
    }
    load(Contact()) += friction;
    CoordinatesT<T> q2 = CoordinatesT<T>::Constant(n, ZeroLike(p));
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) q2(i) += compliance_(i, j) * load(j);
    }
    if (mode == Mode::kStick) q2(Contact()) = ZeroLike(p);
    return q2;
  }
  template <typename T>
  T ContactAcceleration(Mode mode, const StateT<T>& x, const T& phase, const ParametersT<T>& p) const {
    return Acceleration(mode, x, phase, p)(Contact());
  }
  State AtRest(const State& x, const Parameters& p) const {
    State y = x;
    y(ContactVelocityIndex()) = p.v_b;
    return y;
  }
  bool NearRest(const State& x, const Parameters& p) const {
    return std::abs(x(ContactVelocityIndex()) - p.v_b) <=
           1e-12 * (1.0 + std::abs(p.v_b) + x.head(Coordinates()).cwiseAbs().maxCoeff());
  }

  // The friction force a stick needs; F > F_s drives the contact towards negative q_N.
  template <typename T>
  T StickForce(const StateT<T>& x, const T& phase, const ParametersT<T>&) const {
    using std::cos;
    T force = holding_(0) * x(0);
    for (int j = 1; j < StateSize(); ++j) force += holding_(j) * x(j);
    return force - holding_forcing_ * cos(phase);
  }
  // dF/dt along a stick: the holding weights on (q', q''), q'' the stick's accelerations.
  template <typename T>
  T StickForceRate(const StateT<T>& x, const T& phase, const ParametersT<T>& p) const {
    using std::sin;
    const CoordinatesT<T> q2 = Acceleration(Mode::kStick, x, phase, p);
    const int n = Coordinates();
    T rate = holding_forcing_ * p.omega * sin(phase);
    for (int j = 0; j < n; ++j) rate += holding_(j) * x(n + j) + holding_(n + j) * q2(j);
    return rate;
  }
  template <typename T>
  T StaticThreshold(const ParametersT<T>& p) const { return p.F_s; }
  double KineticForce(const Parameters& p) const { return p.F_k; }
  double FrictionSlope() const { return friction_slope_; }
  bool AbnormalStopsPossible(const Parameters& p) const { return std::abs(p.F_s - p.F_k) <= 1e-12 * p.F_s; }
  Mode ModeFromRest(const State& x, double phase, const Parameters& p) const {
    return CoulombModeAtRest(StickForce(x, phase, p), p.F_s, [&] { return StickForceRate(x, phase, p); });
  }

  ExponentialSum ContactVelocityAlong(const Motion& motion) const {
    return Along(motion, Vector::Unit(StateSize(), ContactVelocityIndex()), 0.0).Affine(1.0, -motion.rest_velocity);
  }
  ExponentialSum CoordinateAlong(const Motion& motion, int j) const {
    return Along(motion, Vector::Unit(StateSize(), j), 0.0);
  }
  bool HeldInStick(int j) const { return j == Contact(); }
  ExponentialSum StickForceAlong(const Motion& motion, double, const Parameters&) const {
    return Along(motion, holding_.transpose(), -holding_forcing_);
  }

  // For an integrator (integrable_oscillator_model.hpp), from the equations of motion alone: the
  // accelerations by solving with M (in a stick with M's free block, q_N'' = 0), not the modes.
  State VectorField(Mode mode, const State& x, double phase, const Parameters& p) const {
    const int n = Coordinates();
    State dx(StateSize());
    dx.head(n) = x.tail(n);
    if (mode == Mode::kStick) {
      dx.tail(n) = HeldAcceleration(x, phase);
    } else {
      CoordinatesT<double> load = Load(x, phase);
      load(Contact()) += SlipForce(mode, x, p);
      dx.tail(n) = mass_factor_.solve(load);
    }
    return dx;
  }
  // The contact's row of M q'' + C q' + K q = g cos psi + F with the held accelerations.
  double HoldingForce(const State& x, double phase, const Parameters&) const {
    return mass_.row(Contact()).dot(HeldAcceleration(x, phase)) - Load(x, phase)(Contact());
  }
  // Its time derivative at rest: the same row differentiated, q''' of the free coordinates from
  // the time derivative of their equations.
  double HoldingForceRate(const State& x, double phase, const Parameters& p) const {
    const int n = Coordinates();
    const CoordinatesT<double> q2 = HeldAcceleration(x, phase);
    const CoordinatesT<double> load_rate = -forcing_ * p.omega * std::sin(phase) - stiffness_ * x.tail(n) - damping_ * q2;
    CoordinatesT<double> q3 = CoordinatesT<double>::Zero(n);
    if (n > 1) q3.head(n - 1) = held_mass_factor_.solve(load_rate.head(n - 1));
    return mass_.row(Contact()).dot(q3) - load_rate(Contact());
  }
  double HoldingForceScale(const State& x, const Parameters& p) const {
    const int n = Coordinates();
    return std::max(stiffness_.row(Contact()).cwiseAbs().dot(x.head(n).cwiseAbs()) +
                        damping_.row(Contact()).cwiseAbs().dot(x.tail(n).cwiseAbs()) + std::abs(forcing_(Contact())),
                    p.F_s);
  }

 private:
  Basis BasisOf(const FirstOrderBasis& b) const {
    const int S = StateSize();
    Basis basis;
    basis.size = static_cast<int>(b.components.size());
    basis.state_size = S;
    basis.contact = Contact();
    basis.contact_velocity = ContactVelocityIndex();
    basis.component = basis.weight = Indices::Zero(S);
    basis.inverse = Real::Zero(S, S);
    basis.shapes = basis.projector = basis.forced_shapes = Complex::Zero(S, S);
    basis.eigenvalues = Eigen::Matrix<std::complex<double>, kStateSize, 1>::Zero(S);
    basis.forcing = basis.friction = basis.held_position = basis.held_velocity = Vector::Zero(S);
    const int d = basis.size;
    for (int i = 0; i < d; ++i) basis.component(i) = b.components[static_cast<std::size_t>(i)];
    basis.inverse.topLeftCorner(d, d) = b.system_inverse;
    basis.shapes.topLeftCorner(d, d) = b.shapes;
    basis.projector.topLeftCorner(d, d) = b.projector;
    basis.eigenvalues.head(d) = b.eigenvalues;
    basis.forcing.head(d) = b.forcing;
    basis.friction.head(d) = b.friction;
    basis.held_position.head(d) = b.held_position;
    basis.held_velocity.head(d) = b.held_velocity;
    const Eigen::VectorXcd modal_forcing = b.projector * b.forcing.cast<std::complex<double>>();
    for (int k = 0; k < d; ++k) {
      basis.forced_shapes.col(k).head(d) = b.shapes.col(k) * modal_forcing(k);
      const double nu = b.eigenvalues(k).imag();
      basis.weight(k) = nu > 0.0 ? 2 : nu == 0.0 ? 1 : 0;  // exact conjugates from the real Schur form
    }
    return basis;
  }
  // Forward-mode AD with derivative vectors of run-time size (the orbit layer's gradients) needs
  // every value to carry derivatives of one size: constants are made from a parameter, never T(c),
  // and products with the model's matrices are written out.
  template <typename T>
  static T ZeroLike(const ParametersT<T>& p) { return T(p.omega * 0.0); }

  // `loaded`: with the forcing and the friction force (the flow), or without (its linear part).
  template <typename T>
  MotionT<T> MotionFrom(Mode mode, const StateT<T>& start, const T& phase, const ParametersT<T>& p, bool loaded) const {
    const bool stick = mode == Mode::kStick;
    const T zero = ZeroLike(p);
    MotionT<T> m;
    m.basis = stick ? &stick_ : &slip_;
    m.holds = stick;
    m.omega = p.omega;
    m.phase = phase;
    m.held_position = stick ? start(Contact()) : zero;
    m.held_velocity = stick ? start(ContactVelocityIndex()) : zero;
    m.rest_velocity = p.v_b;
    m.alpha = m.beta = m.forced_re = m.forced_im = m.d_re = m.d_im = StateT<T>::Constant(StateSize(), zero);
    // The slip's constant force: -F_k sign(s) + alpha v_b (its -alpha q_N' is in the slip's basis).
    const T friction = stick || !loaded ? zero : T(-double(SlipDirection(mode)) * p.F_k + friction_slope_ * p.v_b);
    AddStaticResponse(friction, m);
    // None without forcing (where omega, playing no part, may sit on a natural frequency).
    if (loaded && !Autonomous()) AddForcedResponse(p.omega, m);
    AddFreeMotion(start, m);
    return m;
  }
  // alpha + beta s answering the constant and linear inputs e + f s: beta = -A^-1 f, alpha = A^-1 (beta - e).
  template <typename T>
  void AddStaticResponse(const T& friction, MotionT<T>& m) const {
    const Basis& b = *m.basis;
    StateT<T> e = m.alpha, f = m.alpha;
    for (int i = 0; i < b.size; ++i) {
      e(i) = b.friction(i) * friction + b.held_position(i) * m.held_position + b.held_velocity(i) * m.held_velocity;
      f(i) = b.held_position(i) * m.held_velocity;
    }
    for (int i = 0; i < b.size; ++i) {
      for (int j = 0; j < b.size; ++j) m.beta(i) -= b.inverse(i, j) * f(j);
    }
    for (int i = 0; i < b.size; ++i) {
      for (int j = 0; j < b.size; ++j) m.alpha(i) += b.inverse(i, j) * (m.beta(j) - e(j));
    }
  }
  // Z = sum_k V_k (W b)_k / (i omega - lambda_k), 1/(i omega - lambda) = (-sigma - i(omega - nu)) / |.|^2.
  template <typename T>
  void AddForcedResponse(const T& omega, MotionT<T>& m) const {
    const Basis& b = *m.basis;
    for (int k = 0; k < b.size; ++k) {
      const std::complex<double> lambda = b.eigenvalues(k);
      const T detune = omega - lambda.imag();
      const T norm = lambda.real() * lambda.real() + detune * detune;
      const T r_re = -lambda.real() / norm, r_im = -detune / norm;
      for (int i = 0; i < b.size; ++i) {
        const std::complex<double> u = b.forced_shapes(i, k);
        m.forced_re(i) += u.real() * r_re - u.imag() * r_im;
        m.forced_im(i) += u.real() * r_im + u.imag() * r_re;
      }
    }
  }
  // d = W (y(0) - alpha - Re(Z e^{i phase})): the free motion that meets the start.
  template <typename T>
  void AddFreeMotion(const StateT<T>& start, MotionT<T>& m) const {
    using std::cos;
    using std::sin;
    const Basis& b = *m.basis;
    const T c = cos(m.phase), sn = sin(m.phase);
    for (int j = 0; j < b.size; ++j) {
      const T free = start(b.component(j)) - m.alpha(j) - (m.forced_re(j) * c - m.forced_im(j) * sn);
      for (int k = 0; k < b.size; ++k) {
        m.d_re(k) += b.projector(k, j).real() * free;
        m.d_im(k) += b.projector(k, j).imag() * free;
      }
    }
  }
  CoordinatesT<double> Load(const State& x, double phase) const {
    const int n = Coordinates();
    return forcing_ * std::cos(phase) - stiffness_ * x.head(n) - damping_ * x.tail(n);
  }
  // q'' in a stick from the equations: q_N'' = 0 and M_rr q_r'' = (g cos psi - K q - C q')_r.
  CoordinatesT<double> HeldAcceleration(const State& x, double phase) const {
    const int n = Coordinates();
    CoordinatesT<double> q2 = CoordinatesT<double>::Zero(n);
    if (n > 1) q2.head(n - 1) = held_mass_factor_.solve(Load(x, phase).head(n - 1));
    return q2;
  }
  // w . x(s) + forcing_weight cos(omega s + phase) along a motion, x the state.
  ExponentialSum Along(const Motion& m, const Vector& w, double forcing_weight) const {
    const Basis& b = *m.basis;
    double constant = 0.0, slope = 0.0, forced_re = forcing_weight, forced_im = 0.0;
    std::vector<ExponentialTerm> terms;
    for (int i = 0; i < b.size; ++i) {
      const double wi = w(b.component(i));
      constant += wi * m.alpha(i);
      slope += wi * m.beta(i);
      forced_re += wi * m.forced_re(i);
      forced_im += wi * m.forced_im(i);
    }
    if (m.holds) {
      constant += w(b.contact) * m.held_position + w(b.contact_velocity) * m.held_velocity;
      slope += w(b.contact) * m.held_velocity;
    }
    // Re(Z e^{i(omega s + phase)}) = (Zr cos phase - Zi sin phase) cos omega s - (Zr sin phase + Zi cos phase) sin omega s.
    const double c = std::cos(m.phase), sn = std::sin(m.phase);
    terms.push_back({0, 0.0, {0.0, constant, 0.0}});
    terms.push_back({1, 0.0, {0.0, slope, 0.0}});
    terms.push_back({0, 0.0, {m.omega, forced_re * c - forced_im * sn, -(forced_re * sn + forced_im * c)}});
    for (int k = 0; k < b.size; ++k) {
      if (b.weight(k) == 0) continue;
      std::complex<double> shape = 0.0;
      for (int i = 0; i < b.size; ++i) shape += w(b.component(i)) * b.shapes(i, k);
      const std::complex<double> g = shape * std::complex<double>(m.d_re(k), m.d_im(k)) * double(b.weight(k));
      const std::complex<double> lambda = b.eigenvalues(k);
      terms.push_back({0, lambda.real(), {lambda.imag(), g.real(), -g.imag()}});
    }
    return ExponentialSum(std::move(terms));
  }

  using Square = Eigen::Matrix<double, N, N>;
  // M's block of the coordinates a stick leaves free (unused for n = 1).
  static constexpr int kFree = N == Eigen::Dynamic ? Eigen::Dynamic : N > 1 ? N - 1 : 1;
  using FreeSquare = Eigen::Matrix<double, kFree, kFree>;

  int n_ = 0;  // the number of coordinates (N at a fixed size)
  ModelDescription description_;
  Square mass_, damping_, stiffness_;
  Square compliance_;  // M^-1
  CoordinatesT<double> forcing_;
  double friction_slope_ = 0.0;  // alpha
  Eigen::LLT<Square> mass_factor_;
  // Factored once: the integrator asks for the stick's accelerations at every step.
  Eigen::LLT<FreeSquare> held_mass_factor_;
  Basis slip_, stick_;
  Eigen::Matrix<double, 1, kStateSize> holding_;
  double holding_forcing_ = 0.0;
};

// Its size read with its data (a file's model): states are Eigen::VectorXd.
using DynamicLinearOscillator = LinearOscillator<Eigen::Dynamic>;

}  // namespace stickslip
