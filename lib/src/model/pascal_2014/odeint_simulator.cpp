#include "stickslip/model/pascal_2014/odeint_simulator.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include <boost/numeric/odeint.hpp>

#include "stickslip/model/odeint_simulation.hpp"

namespace stickslip {

SimulationResult SimulateOdeint(const Parameters& p, const State& x0, double phi,
                                const SimulationOptions& options, const OdeintOptions& odeint) {
  return SimulateOdeint(Pascal2014{}, p, x0, phi, options, odeint);
}

State IntegrateMode(Mode mode, const State& start, double phase, double s, const Parameters& p,
                    const OdeintOptions& odeint) {
  return IntegrateMode(Pascal2014{}, mode, start, phase, s, p, odeint);
}

namespace {

namespace ode = boost::numeric::odeint;

// The variational equations of one mode, Y = (X, Phi, X_psi, X_p) with 4 + 16 + 4 + 20 = 44
// components:
//   X'     = f(X, tau)                              X(0)     = start
//   Phi'   = A Phi,           A = df/dX             Phi(0)   = I     (Phi = dX/dX(0))
//   X_psi' = A X_psi + df/dpsi                      X_psi(0) = 0     (X_psi = dX/dpsi)
//   X_p'   = A X_p + df/dp                          X_p(0)   = 0     (X_p = dX/dp, 5 columns)
// Every 4x4 or 4x5 block is stored column by column.
constexpr int kTransitionOffset = 4;
constexpr int kPhaseOffset = kTransitionOffset + 16;
constexpr int kParameterOffset = kPhaseOffset + 4;
constexpr int kVariationalSize = kParameterOffset + 4 * kParameterCount;  // 44
constexpr int kSensitivityColumns = 4 + 1 + kParameterCount;  // Phi, X_psi, X_p: A acts on each
using VariationalState = std::array<double, kVariationalSize>;
using VariationalDopri5 = ode::runge_kutta_dopri5<VariationalState>;
using OdeState = odeint_simulation::OdeState<Pascal2014>;

// The derivatives of the right-hand side of eq. (2) / eq. (9), written out by hand (nothing is
// taken from the closed form), and the variational system built from them.
class VariationalField {
 public:
  VariationalField(Mode mode, double phase, const Parameters& p)
      : field_{Pascal2014{}, mode, phase, p},
        stick_(mode == Mode::kStick),
        phase_(phase),
        p_(p),
        // u = -u_s sign(x2') in a slip (eq. 4), so du/du_s = -sign(x2').
        du_dus_(-SlipDirection(mode)),
        friction_(-SlipDirection(mode) * p.u_s) {}

  // The vector field f(X, tau) alone (d_elapsed at the end point).
  OdeState Field(const OdeState& x, double tau) const {
    OdeState f;
    field_(x, f, tau);
    return f;
  }

  void operator()(const VariationalState& y, VariationalState& dydt, double tau) const {
    const OdeState x = {y[0], y[1], y[2], y[3]};
    const OdeState f = Field(x, tau);
    std::copy(f.begin(), f.end(), dydt.begin());
    for (int k = 0; k < kSensitivityColumns; ++k) {
      ApplyJacobian(&y[kTransitionOffset + 4 * k], &dydt[kTransitionOffset + 4 * k]);
    }
    // df/dchi: eq. (2)/(9) first line, x1'' = -x1 + chi x2 -> x2 (both modes).
    dydt[kParameterOffset + 4 * Column(ParameterId::kChi) + 2] += x[1];
    if (stick_) return;  // eq. (9): x2'' = 0 depends on no phase and no other parameter.
    // Second line of eq. (2): x2'' = -chi eta (x2 - x1) + eta u + cos(omega tau + psi).
    const double angle = p_.omega * tau + phase_;
    const double sin_angle = std::sin(angle);
    // df/dpsi = (0, 0, 0, -sin(omega tau + psi)).
    dydt[kPhaseOffset + 3] += -sin_angle;
    // df/dchi, x2'' row: -eta (x2 - x1).
    dydt[kParameterOffset + 4 * Column(ParameterId::kChi) + 3] += -p_.eta * (x[1] - x[0]);
    // df/deta: -chi (x2 - x1) + u.
    dydt[kParameterOffset + 4 * Column(ParameterId::kEta) + 3] +=
        -p_.chi * (x[1] - x[0]) + friction_;
    // df/domega: d cos(omega tau + psi)/domega = -tau sin(omega tau + psi).
    dydt[kParameterOffset + 4 * Column(ParameterId::kOmega) + 3] += -tau * sin_angle;
    // df/du_s: eta du/du_s = -eta sign(x2') (eq. 4).
    dydt[kParameterOffset + 4 * Column(ParameterId::kSlidingFriction) + 3] += p_.eta * du_dus_;
    // df/du_r = 0: the static friction level only decides when a stick ends (eq. 4, 11).
  }

 private:
  static int Column(ParameterId id) { return static_cast<int>(id); }

  // out = A v with A = df/dX, constant in each mode:
  //   rows 1-2: (x1, x2)' = (x1', x2');
  //   row 3, eq. (2)/(9): x1'' = -x1 + chi x2;
  //   row 4, eq. (2): x2'' = chi eta x1 - chi eta x2 + ... in a slip; 0 in a stick (eq. 9).
  void ApplyJacobian(const double* v, double* out) const {
    out[0] = v[2];
    out[1] = v[3];
    out[2] = -v[0] + p_.chi * v[1];
    out[3] = stick_ ? 0.0 : p_.chi * p_.eta * (v[0] - v[1]);
  }

  odeint_simulation::ModeField<Pascal2014> field_;
  bool stick_;
  double phase_;
  Parameters p_;
  double du_dus_;
  double friction_;
};

}  // namespace

FlowDerivatives IntegrateModeWithDerivatives(Mode mode, const State& start, double phase, double s,
                                             const Parameters& p, const OdeintOptions& odeint) {
  if (!(std::isfinite(s) && s >= 0.0)) {
    throw InvalidInput("s", s, "finite and >= 0");
  }
  odeint.CheckValid();
  const VariationalField field(mode, phase, p);
  VariationalState y{};
  for (int i = 0; i < 4; ++i) {
    y[i] = start(i);
    y[kTransitionOffset + 4 * i + i] = 1.0;  // Phi(0) = I
  }
  if (s > 0.0) {
    ode::integrate_adaptive(
        ode::make_controlled(odeint.absolute_tolerance, odeint.relative_tolerance,
                             VariationalDopri5()),
        field, y, 0.0, s, std::min(odeint_simulation::kInitialStep, s));
  }
  FlowDerivatives out;
  const OdeState x_end = {y[0], y[1], y[2], y[3]};
  const OdeState f_end = field.Field(x_end, s);
  for (int i = 0; i < 4; ++i) {
    out.state(i) = x_end[i];
    out.d_elapsed(i) = f_end[i];
    out.d_phase(i) = y[kPhaseOffset + i];
    for (int j = 0; j < 4; ++j) out.d_start(i, j) = y[kTransitionOffset + 4 * j + i];
    for (int k = 0; k < kParameterCount; ++k) {
      out.d_parameters(i, k) = y[kParameterOffset + 4 * k + i];
    }
  }
  return out;
}

}  // namespace stickslip
