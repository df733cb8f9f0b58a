#include "stickslip/model/odeint_simulator.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include <boost/numeric/odeint.hpp>
#include <fmt/format.h>

namespace stickslip {

void OdeintOptions::CheckValid() const {
  for (const auto& [name, value] : {std::pair{"relative_tolerance", relative_tolerance},
                                    std::pair{"absolute_tolerance", absolute_tolerance},
                                    std::pair{"event_time_tolerance", event_time_tolerance}}) {
    if (!(std::isfinite(value) && value > 0.0)) throw InvalidInput(name, value, "finite and > 0");
  }
}

namespace {

namespace ode = boost::numeric::odeint;
using OdeState = std::array<double, 4>;  // (x1, x2, x1', x2')
using Dopri5 = ode::runge_kutta_dopri5<OdeState>;
using DenseStepper = ode::result_of::make_dense_output<Dopri5>::type;

// First trial step; the controller adapts it at once.
constexpr double kInitialStep = 1e-2;
// Dense-output points scanned in the first step of a slip started from rest (see Advance).
constexpr int kFirstStepScan = 32;

OdeState ToOde(const State& x) { return {x(0), x(1), x(2), x(3)}; }
State FromOde(const OdeState& x) { return State(x[0], x[1], x[2], x[3]); }

// Kept separate from SlipDirection (flows.hpp) on purpose: nothing shared with the closed form.
// Sign of x2' in a slip: -1 (slip-), +1 (slip+), 0 for a stick.
double VelocitySign(Mode mode) {
  switch (mode) {
    case Mode::kSlipNegative: return -1.0;
    case Mode::kSlipPositive: return 1.0;
    case Mode::kStick: break;
  }
  return 0.0;
}

// The right-hand side of eq. (2) in one mode. Time is the elapsed time tau in the mode, the
// forcing cos(omega tau + phase).
class ModeField {
 public:
  ModeField(Mode mode, double phase, const Parameters& p)
      : stick_(mode == Mode::kStick), phase_(phase), p_(p),
        // Coulomb (eq. 4): u = -u_s sign(x2') in a slip.
        friction_(-VelocitySign(mode) * p.u_s) {}

  void operator()(const OdeState& x, OdeState& dxdt, double tau) const {
    dxdt[0] = x[2];
    dxdt[1] = x[3];
    dxdt[2] = -x[0] + p_.chi * x[1];  // eq. (2), first line; the same in a stick (eq. 9)
    if (stick_) {
      dxdt[3] = 0.0;  // eq. (9): x2'' = 0
      return;
    }
    // eq. (2), second line: x2'' = -chi eta (x2 - x1) + eta u + cos(omega t + phi)
    dxdt[3] = -p_.chi * p_.eta * (x[1] - x[0]) + p_.eta * friction_ +
              std::cos(p_.omega * tau + phase_);
  }

 private:
  bool stick_;
  double phase_;
  Parameters p_;
  double friction_;
};

// s of eq. (11): what the friction must hold (times eta) for m2 to stay at rest.
double HoldingForce(const OdeState& x, double phase, const Parameters& p) {
  return p.chi * p.eta * (x[1] - x[0]) - std::cos(phase);
}

// Coulomb's law at rest (eq. 4, 11; ERRATA for the signs): stick while |s| < eta u_r, else
// slip away from the side s pushes to. On the threshold to rounding the sign of ds/dt
// (x2' = 0) decides: the stick is left only if s is moving outwards.
Mode ModeAtRest(const OdeState& x, double phase, const Parameters& p) {
  const double s = HoldingForce(x, phase, p);
  const double threshold = p.eta * p.u_r;
  const double rounding =
      1e-12 * std::max({threshold, std::abs(p.chi * p.eta * (x[1] - x[0])), 1.0});
  if (s > threshold + rounding) return Mode::kSlipNegative;
  if (s < -threshold - rounding) return Mode::kSlipPositive;
  const double ds_dt = -p.chi * p.eta * x[2] + p.omega * std::sin(phase);
  if (std::abs(s - threshold) <= rounding && ds_dt > 0.0) return Mode::kSlipNegative;
  if (std::abs(s + threshold) <= rounding && ds_dt < 0.0) return Mode::kSlipPositive;
  return Mode::kStick;
}

// What ends a mode: the event functions, positive while the mode goes on.
//   slip: sign * x2' (a stop when it reaches 0);
//   stick: eta u_r - s (G1 of eq. 35, exit to slip-) and eta u_r + s (G, exit to slip+).
struct Constraints {
  std::array<double, 2> value{};
  int count = 0;
};

Constraints ConstraintsOf(Mode mode, const OdeState& x, double phase, const Parameters& p) {
  Constraints c;
  if (mode != Mode::kStick) {
    c.value[0] = VelocitySign(mode) * x[3];
    c.count = 1;
    return c;
  }
  const double s = HoldingForce(x, phase, p);
  c.value[0] = p.eta * p.u_r - s;
  c.value[1] = p.eta * p.u_r + s;
  c.count = 2;
  return c;
}

// The controlled dense-output dopri5 on one mode, from elapsed time 0.
class ModeIntegrator {
 public:
  ModeIntegrator(Mode mode, const State& start, double phase, const Parameters& p,
                 const OdeintOptions& options)
      : field_(mode, phase, p),
        options_(options),
        stepper_(ode::make_dense_output(options.absolute_tolerance, options.relative_tolerance,
                                        Dopri5())) {
    stepper_.initialize(ToOde(start), 0.0, kInitialStep);
  }

  void Step() { stepper_.do_step(field_); }
  double previous_time() const { return stepper_.previous_time(); }
  double current_time() const { return stepper_.current_time(); }

  // The interpolated state, for tau in the last step [previous_time, current_time].
  OdeState Interpolated(double tau) const {
    OdeState x;
    stepper_.calc_state(tau, x);
    return x;
  }

  // The state at tau in the last step, integrated from the last step's start instead of
  // interpolated: dopri5's dense output is one order lower than its steps.
  OdeState Integrated(double tau) const {
    if (tau >= current_time()) return stepper_.current_state();
    OdeState x = stepper_.previous_state();
    if (tau <= previous_time()) return x;
    ode::integrate_adaptive(
        ode::make_controlled(options_.absolute_tolerance, options_.relative_tolerance, Dopri5()),
        field_, x, previous_time(), tau, tau - previous_time());
    return x;
  }

 private:
  ModeField field_;
  OdeintOptions options_;
  DenseStepper stepper_;
};

// How a mode ended: the elapsed time, which constraint reached zero (-1: the horizon).
struct ModeEnd {
  double tau = 0.0;
  int constraint = -1;
};

// Bisection on the dense output for the first zero of constraint k in (lo, hi], where it is
// positive at lo (or, at the very start of a mode, on its boundary) and <= 0 at hi.
double LocateZero(const ModeIntegrator& integrator, Mode mode, double phase, const Parameters& p,
                  int k, double lo, double hi, double tolerance) {
  while (hi - lo > tolerance) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;  // no double between them
    const OdeState x = integrator.Interpolated(mid);
    if (ConstraintsOf(mode, x, phase + p.omega * mid, p).value[k] > 0.0) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  return hi;
}

}  // namespace

State IntegrateMode(Mode mode, const State& start, double phase, double s, const Parameters& p,
                    const OdeintOptions& odeint) {
  if (!(std::isfinite(s) && s >= 0.0)) {
    throw InvalidInput("s", s, "finite and >= 0");
  }
  if (s == 0.0) return start;
  ModeIntegrator integrator(mode, start, phase, p, odeint);
  while (integrator.current_time() < s) integrator.Step();
  return FromOde(integrator.Integrated(s));
}

namespace {

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

// The derivatives of the right-hand side of eq. (2) / eq. (9), written out by hand (nothing is
// taken from the closed form), and the variational system built from them.
class VariationalField {
 public:
  VariationalField(Mode mode, double phase, const Parameters& p)
      : field_(mode, phase, p),
        stick_(mode == Mode::kStick),
        phase_(phase),
        p_(p),
        // u = -u_s sign(x2') in a slip (eq. 4), so du/du_s = -sign(x2').
        du_dus_(-VelocitySign(mode)),
        friction_(-VelocitySign(mode) * p.u_s) {}

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

  ModeField field_;
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
        field, y, 0.0, s, std::min(kInitialStep, s));
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

SimulationResult SimulateOdeint(const Parameters& p, const State& x0, double phi,
                                const SimulationOptions& options, const OdeintOptions& odeint) {
  SimulationResult result;
  result.parameters = p;
  result.phi = phi;
  auto stop = [&](SimulationEnd end, std::string message) {
    result.end = end;
    result.message = std::move(message);
    return result;
  };
  if (auto invalid = Validate(p)) throw *invalid;
  for (int i = 0; i < 4; ++i) {
    if (!std::isfinite(x0(i))) throw InvalidInput(fmt::format("x0({})", i), x0(i), "a finite number");
  }
  if (!std::isfinite(phi)) throw InvalidInput("phi", phi, "a finite number");
  if (!(std::isfinite(options.duration) && options.duration > 0.0)) {
    throw InvalidInput("duration", options.duration, "finite and > 0");
  }
  if (!(std::isfinite(options.sample_step) && options.sample_step >= 0.0)) {
    throw InvalidInput("sample_step", options.sample_step, "finite and >= 0");
  }
  odeint.CheckValid();

  // Samples at k * sample_step (the last one clipped to the duration), taken from the dense
  // output of the segment that covers them.
  const long sample_count = options.SampleCount();
  long next_sample = 0;
  auto sample_time = [&](long k) { return options.SampleTime(k); };

  double t = 0.0;
  OdeState x = ToOde(x0);
  Mode mode = x[3] < 0.0 ? Mode::kSlipNegative
            : x[3] > 0.0 ? Mode::kSlipPositive
                         : ModeAtRest(x, phi, p);
  while (true) {
    const double phase = p.omega * t + phi;
    const double horizon = options.duration - t;
    if (horizon <= 0.0) {  // the last event fell on the horizon: a final segment of length 0
      result.segments.push_back({mode, t, t, FromOde(x), FromOde(x), SegmentEnd::kHorizon});
      break;
    }
    ModeIntegrator integrator(mode, FromOde(x), phase, p, odeint);
    // A slip from rest starts with x2' = 0: that zero is not a stop, so the slip's constraint
    // is armed only once x2' has moved in the slip's direction.
    bool armed = ConstraintsOf(mode, x, phase, p).value[0] > 0.0 || mode == Mode::kStick;
    std::optional<ModeEnd> end;
    while (!end) {
      integrator.Step();
      const double lo = integrator.previous_time();
      const double hi = std::min(integrator.current_time(), horizon);
      const Constraints at_hi =
          ConstraintsOf(mode, integrator.Interpolated(hi), phase + p.omega * hi, p);
      double search_from = lo;
      bool check = armed;
      if (!armed) {
        if (at_hi.value[0] > 0.0) {
          armed = true;  // left the starting zero: nothing to locate in this step
        } else {
          // Back at or behind zero by the end of the first step: either a very short slip
          // (find a point where it was moving, and search from there) or a slip that cannot
          // start (Coulomb's law chose it from rest, so only at a degenerate threshold).
          for (int i = 1; i < kFirstStepScan && !armed; ++i) {
            const double tau = lo + (hi - lo) * i / kFirstStepScan;
            if (ConstraintsOf(mode, integrator.Interpolated(tau), phase + p.omega * tau, p)
                    .value[0] > 0.0) {
              armed = check = true;
              search_from = tau;
            }
          }
          if (!armed) {
            return stop(SimulationEnd::kStuckAtRest, fmt::format(
                "at t = {} a {} from rest does not move in its direction (x2' = {} after {})",
                t, ToString(mode), integrator.Interpolated(hi)[3], hi));
          }
        }
      }
      for (int k = 0; check && k < at_hi.count; ++k) {
        if (at_hi.value[k] > 0.0) continue;
        const double tau =
            LocateZero(integrator, mode, phase, p, k, search_from, hi, odeint.event_time_tolerance);
        if (!end || tau < end->tau) end = ModeEnd{tau, k};
      }
      if (!end && hi >= horizon) end = ModeEnd{horizon, -1};
      // Samples up to the end of this step (or of the segment).
      const double covered = end ? end->tau : hi;
      for (; next_sample < sample_count && sample_time(next_sample) - t <= covered; ++next_sample) {
        const double tau = std::clamp(sample_time(next_sample) - t, lo, covered);
        const TimeSample sample{sample_time(next_sample), FromOde(integrator.Interpolated(tau))};
        if (options.on_sample) {
          options.on_sample(sample, mode);
        } else {
          result.samples.push_back(sample);
        }
      }
    }

    Segment segment{mode, t, options.duration, FromOde(x), State::Zero(), SegmentEnd::kHorizon};
    OdeState x_end = integrator.Integrated(end->tau);
    if (end->constraint < 0) {
      segment.end = FromOde(x_end);
      result.segments.push_back(segment);
      break;
    }
    x_end[3] = 0.0;  // both events happen at rest
    const double t_event = t + end->tau;
    Event event{t_event, EventKind::kStop, mode, mode, FromOde(x_end)};
    if (mode == Mode::kStick) {
      // Leaving at s = +eta u_r starts slip-, at s = -eta u_r slip+ (eq. 4, ERRATA).
      event.kind = EventKind::kStickExit;
      event.mode_after = end->constraint == 0 ? Mode::kSlipNegative : Mode::kSlipPositive;
      segment.end_reason = SegmentEnd::kStickExit;
    } else {
      event.mode_after = ModeAtRest(x_end, phase + p.omega * end->tau, p);
      segment.end_reason = SegmentEnd::kStop;
    }
    segment.t_end = t_event;
    segment.end = event.state;
    result.segments.push_back(segment);
    result.events.push_back(event);
    t = t_event;
    x = x_end;
    mode = event.mode_after;
    ReportSimulated(options, 2.0 * std::numbers::pi / p.omega, t);
    if (static_cast<int>(result.events.size()) >= options.max_events) {
      return stop(SimulationEnd::kMaxEvents, fmt::format("stopped after {} events at t = {} (max_events)",
                              result.events.size(), t));
    }
  }
  return result;
}

}  // namespace stickslip
