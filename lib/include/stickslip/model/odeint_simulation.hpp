// The Odeint simulator, for any model whose equations of motion are given
// (integrable_oscillator_model.hpp): the independent cross-check of the closed forms. The
// equations are integrated mode by mode with Boost.Odeint's controlled dense-output dopri5; each
// event is located by bisection on the dense output, and the integration restarts in the next
// mode (never across a switch). Coulomb's law at rest is decided here from the model's holding
// force, not by its ModeFromRest (the closed forms' decision).
//
// Events are found from sign changes of the event functions between accepted steps, and from a
// minimum clearly below zero inside a step (a short excursion whose two crossings one step
// straddles: ZeroWithinStep); a zero touched tangentially (a grazing, or an abnormal stop) is seen
// only if rounding makes it a crossing at a step's end.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <boost/numeric/odeint.hpp>
#include <fmt/format.h>

#include "stickslip/model/integrable_oscillator_model.hpp"
#include "stickslip/model/odeint_options.hpp"
#include "stickslip/model/simulation.hpp"

namespace stickslip {

namespace odeint_simulation {

namespace ode = boost::numeric::odeint;

// Odeint's range algebra on a std::array (a std::vector for a model whose size comes from a file):
// the model's state is copied in and out at the field, so the stepper's arithmetic does not depend
// on the model's state type.
template <IntegrableOscillatorModel M>
using OdeState = std::conditional_t<M::kStateSize == Eigen::Dynamic, std::vector<double>,
                                    std::array<double, std::max(M::kStateSize, 0)>>;
template <IntegrableOscillatorModel M>
using Dopri5 = ode::runge_kutta_dopri5<OdeState<M>>;

// First trial step; the controller adapts it at once.
constexpr double kInitialStep = 1e-2;
// Dense-output points scanned in the first step of a slip started from rest (FirstMovingPoint).
constexpr int kFirstStepScan = 32;

template <IntegrableOscillatorModel M>
OdeState<M> ToOde(const typename M::State& x) {
  OdeState<M> y{};
  if constexpr (M::kStateSize == Eigen::Dynamic) y.resize(static_cast<std::size_t>(x.size()));
  for (std::size_t i = 0; i < y.size(); ++i) y[i] = x(static_cast<Eigen::Index>(i));
  return y;
}
template <IntegrableOscillatorModel M>
typename M::State FromOde(const OdeState<M>& y) {
  typename M::State x(static_cast<Eigen::Index>(y.size()));
  for (std::size_t i = 0; i < y.size(); ++i) x(static_cast<Eigen::Index>(i)) = y[i];
  return x;
}

// The model's equations of motion in one mode as Odeint's system: time is the elapsed time tau in
// the mode, the forcing phase phase + omega tau.
template <IntegrableOscillatorModel M>
struct ModeField {
  M model;
  Mode mode;
  double phase;
  typename M::Parameters p;

  double PhaseAt(double tau) const { return phase + model.ForcingFrequency(p) * tau; }
  void operator()(const OdeState<M>& x, OdeState<M>& dxdt, double tau) const {
    dxdt = ToOde<M>(model.VectorField(mode, FromOde<M>(x), PhaseAt(tau), p));
  }
};

// Coulomb's law at rest from the model's holding force s: stick while |s| < threshold, else slip
// away from the side s pushes to. On the threshold to rounding the sign of ds/dt decides: the
// stick is left only if s is moving outwards.
template <IntegrableOscillatorModel M>
Mode ModeAtRest(const M& model, const typename M::State& x, double phase, const typename M::Parameters& p) {
  const double s = model.HoldingForce(x, phase, p);
  const double threshold = model.StaticThreshold(p);
  const double rounding = 1e-12 * std::max(threshold, model.HoldingForceScale(x, p));
  if (s > threshold + rounding) return Mode::kSlipNegative;
  if (s < -threshold - rounding) return Mode::kSlipPositive;
  const double ds_dt = model.HoldingForceRate(x, phase, p);
  if (std::abs(s - threshold) <= rounding && ds_dt > 0.0) return Mode::kSlipNegative;
  if (std::abs(s + threshold) <= rounding && ds_dt < 0.0) return Mode::kSlipPositive;
  return Mode::kStick;
}

// The first mode: the sign of the contact velocity, or Coulomb's law where it is exactly zero.
template <IntegrableOscillatorModel M>
Mode StartingMode(const M& model, const typename M::State& x0, double phi, const typename M::Parameters& p) {
  const double velocity = model.ContactVelocity(x0, p);
  if (velocity < 0.0) return Mode::kSlipNegative;
  if (velocity > 0.0) return Mode::kSlipPositive;
  return ModeAtRest(model, x0, phi, p);
}

// What ends a mode: the event functions, positive while the mode goes on.
//   slip: the contact velocity times the slip's direction (a stop when it reaches 0);
//   stick: threshold - s (exit to slip-) and threshold + s (exit to slip+).
struct Constraints {
  std::array<double, 2> value{};
  int count = 0;
};

template <IntegrableOscillatorModel M>
Constraints ConstraintsOf(const ModeField<M>& field, const typename M::State& x, double tau) {
  if (field.mode != Mode::kStick) return {{SlipDirection(field.mode) * field.model.ContactVelocity(x, field.p), 0.0}, 1};
  const double s = field.model.HoldingForce(x, field.PhaseAt(tau), field.p);
  const double threshold = field.model.StaticThreshold(field.p);
  return {{threshold - s, threshold + s}, 2};
}

// The contact's velocity component of a state (s is that less the rest velocity, a constant): of
// the state's derivative, the contact's acceleration.
template <IntegrableOscillatorModel M>
double ContactVelocityComponent(const ModeField<M>& field, const typename M::State& x) {
  const typename M::State zero = M::State::Zero(x.size());
  return field.model.ContactVelocity(x, field.p) - field.model.ContactVelocity(zero, field.p);
}

// The constraints' time derivatives along the mode's motion, from the equations of motion: in a
// slip the direction times the contact's acceleration, in a stick -+ the holding force's rate.
template <IntegrableOscillatorModel M>
Constraints RatesOf(const ModeField<M>& field, const typename M::State& x, double tau) {
  if (field.mode != Mode::kStick) {
    const typename M::State dx = field.model.VectorField(field.mode, x, field.PhaseAt(tau), field.p);
    return {{SlipDirection(field.mode) * ContactVelocityComponent(field, dx), 0.0}, 1};
  }
  const double rate = field.model.HoldingForceRate(x, field.PhaseAt(tau), field.p);
  return {{-rate, rate}, 2};
}

// The controlled dense-output dopri5 on one mode, from elapsed time 0.
template <IntegrableOscillatorModel M>
class ModeIntegrator {
 public:
  using State = typename M::State;
  ModeIntegrator(const ModeField<M>& field, const State& start, const OdeintOptions& options)
      : field_(field), options_(options),
        stepper_(ode::make_dense_output(options.absolute_tolerance, options.relative_tolerance, Dopri5<M>())) {
    stepper_.initialize(ToOde<M>(start), 0.0, kInitialStep);
  }

  const ModeField<M>& field() const { return field_; }
  const OdeintOptions& options() const { return options_; }
  void Step() { stepper_.do_step(field_); }
  double previous_time() const { return stepper_.previous_time(); }
  double current_time() const { return stepper_.current_time(); }

  // The interpolated state, for tau in the last step [previous_time, current_time].
  State Interpolated(double tau) const {
    OdeState<M> x = stepper_.current_state();  // (sized: a std::vector is not resized)
    stepper_.calc_state(tau, x);
    return FromOde<M>(x);
  }
  Constraints ConstraintsAt(double tau) const { return ConstraintsOf(field_, Interpolated(tau), tau); }
  Constraints RatesAt(double tau) const { return RatesOf(field_, Interpolated(tau), tau); }

  // The state at tau in the last step, integrated from the last step's start instead of
  // interpolated: dopri5's dense output is one order lower than its steps.
  State Integrated(double tau) const {
    if (tau >= current_time()) return FromOde<M>(stepper_.current_state());
    OdeState<M> x = stepper_.previous_state();
    if (tau <= previous_time()) return FromOde<M>(x);
    ode::integrate_adaptive(ode::make_controlled(options_.absolute_tolerance, options_.relative_tolerance, Dopri5<M>()),
                            field_, x, previous_time(), tau, tau - previous_time());
    return FromOde<M>(x);
  }

 private:
  ModeField<M> field_;
  OdeintOptions options_;
  typename ode::result_of::make_dense_output<Dopri5<M>>::type stepper_;
};

// Bisection on the dense output for the first zero of constraint k in (lo, hi], where it is
// positive at lo (or, at the very start of a mode, on its boundary) and <= 0 at hi.
template <IntegrableOscillatorModel M>
double LocateZero(const ModeIntegrator<M>& integrator, int k, double lo, double hi, double tolerance) {
  while (hi - lo > tolerance) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;  // no double between them
    if (integrator.ConstraintsAt(mid).value[k] > 0.0) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  return hi;
}

// How a mode ended: an event at elapsed time tau, where `constraint` of Constraints reached zero;
// the horizon at tau; or stuck: a slip chosen from rest that has not moved in its direction by
// tau (Coulomb's law chose it, so only at a degenerate threshold).
struct ModeEnd {
  enum class Kind { kEvent, kHorizon, kStuck };
  Kind kind = Kind::kHorizon;
  double tau = 0.0;
  int constraint = 0;
};

// The first zero of the constraints that are <= 0 at the end hi of the last step, searched from
// `from`.
template <IntegrableOscillatorModel M>
std::optional<ModeEnd> FirstZero(const ModeIntegrator<M>& integrator, const Constraints& at_hi, double from, double hi,
                                 double tolerance) {
  std::optional<ModeEnd> end;
  for (int k = 0; k < at_hi.count; ++k) {
    if (at_hi.value[k] > 0.0) continue;
    const double tau = LocateZero(integrator, k, from, hi, tolerance);
    if (!end || tau < end->tau) end = ModeEnd{ModeEnd::Kind::kEvent, tau, k};
  }
  return end;
}

// The constraints and their rates at one time, and the size of what a constraint is computed
// from there (its rounding and the integrator's error scale with it): in a slip the contact's
// velocity component (not s = that - the rest velocity, which is small near a stop), in a stick
// the holding force's terms (HoldingForceScale, at least the static threshold).
struct ConstraintsAndRates {
  Constraints value;
  Constraints rate;
  double scale = 0.0;
};

template <IntegrableOscillatorModel M>
ConstraintsAndRates ConstraintsAndRatesAt(const ModeIntegrator<M>& integrator, double tau) {
  const ModeField<M>& field = integrator.field();
  const typename M::State x = integrator.Interpolated(tau);
  const double scale = field.mode == Mode::kStick ? field.model.HoldingForceScale(x, field.p)
                                                  : std::abs(ContactVelocityComponent(field, x));
  return {ConstraintsOf(field, x, tau), RatesOf(field, x, tau), scale};
}

// A constraint positive at both ends of the last step that dipped below zero in between: a short
// excursion (as a brief re-stick, when the levels are close) whose two crossings one step
// straddles. Where a constraint's rate goes from negative at `from` to positive at hi, its minimum
// between is located by bisection on the rate, and if it lies below -depth, the first zero before
// it. depth is 1e4 times the integrator's error tolerance at the constraint's scale: a shallower
// dip may be the integrator's error at a tangency (an abnormal stop, a stick force touching its
// threshold), which stays unseen as every tangency is. The search is made for the default
// tolerances (1e-12: a dip of 1e-8 of the scale is seen); at looser ones only deeper dips are.
// (Two minima in one step are not looked for.)
template <IntegrableOscillatorModel M>
std::optional<ModeEnd> ZeroWithinStep(const ModeIntegrator<M>& integrator, double from, const ConstraintsAndRates& at_from,
                                      double hi, const ConstraintsAndRates& at_hi, double tolerance) {
  const Constraints& rate_from = at_from.rate;
  const Constraints& rate_hi = at_hi.rate;
  std::optional<ModeEnd> end;
  for (int k = 0; k < rate_from.count; ++k) {
    if (!(rate_from.value[k] < 0.0 && rate_hi.value[k] > 0.0)) continue;
    double lo = from, minimum = hi;
    while (minimum - lo > tolerance) {
      const double mid = 0.5 * (lo + minimum);
      if (mid <= lo || mid >= minimum) break;  // no double between them
      (integrator.RatesAt(mid).value[k] < 0.0 ? lo : minimum) = mid;
    }
    const double scale = std::max({at_from.scale, at_hi.scale, std::abs(at_from.value.value[k]), std::abs(at_hi.value.value[k])});
    const double depth = 1e4 * (integrator.options().absolute_tolerance + integrator.options().relative_tolerance * scale);
    if (integrator.ConstraintsAt(minimum).value[k] >= -depth) continue;
    const double tau = LocateZero(integrator, k, from, minimum, tolerance);
    if (!end || tau < end->tau) end = ModeEnd{ModeEnd::Kind::kEvent, tau, k};
  }
  return end;
}

// A slip from rest back at or behind its starting zero by the end hi of its first step: a very
// short slip, searched from the first of a few points of the step where it was moving, or none.
template <IntegrableOscillatorModel M>
std::optional<double> FirstMovingPoint(const ModeIntegrator<M>& integrator, double lo, double hi) {
  for (int i = 1; i < kFirstStepScan; ++i) {
    const double tau = lo + (hi - lo) * i / kFirstStepScan;
    if (integrator.ConstraintsAt(tau).value[0] > 0.0) return tau;
  }
  return std::nullopt;
}

// Samples at the options' SampleTime(k) (simulation.hpp), each from the dense output of the step
// that covers it: kept here, or streamed to options.on_sample.
template <IntegrableOscillatorModel M>
class Sampler {
 public:
  using State = typename M::State;
  explicit Sampler(const BasicSimulationOptions<State>& options) : options_(options), count_(options.SampleCount()) {}

  // Those up to elapsed time `covered` in the mode started at time t, whose last step began at lo.
  void Take(const ModeIntegrator<M>& integrator, double t, double lo, double covered) {
    for (; next_ < count_ && Time(next_) - t <= covered; ++next_) {
      const double tau = std::clamp(Time(next_) - t, lo, covered);
      const BasicTimeSample<State> sample{Time(next_), integrator.Interpolated(tau)};
      if (options_.on_sample) {
        options_.on_sample(sample, integrator.field().mode);
      } else {
        samples_.push_back(sample);
      }
    }
  }
  std::vector<BasicTimeSample<State>> Samples() && { return std::move(samples_); }

 private:
  double Time(long k) const { return options_.SampleTime(k); }

  const BasicSimulationOptions<State>& options_;
  long count_;
  long next_ = 0;
  std::vector<BasicTimeSample<State>> samples_;
};

// Steps one mode, started at time t from `start`, to its first event or the horizon, sampling
// on the way. A slip from rest starts at its constraint's zero, which is not a stop: the
// constraint is armed only once the contact has moved in the slip's direction. The constraints and
// rates at a step's end are those at the next one's start.
template <IntegrableOscillatorModel M>
ModeEnd RunMode(ModeIntegrator<M>& integrator, const typename M::State& start, double t, double horizon,
                double tolerance, Sampler<M>& sampler) {
  bool armed = integrator.field().mode == Mode::kStick || ConstraintsOf(integrator.field(), start, 0.0).value[0] > 0.0;
  std::optional<ConstraintsAndRates> at_lo;
  while (true) {
    integrator.Step();
    const double lo = integrator.previous_time();
    const double hi = std::min(integrator.current_time(), horizon);
    const ConstraintsAndRates at_end = ConstraintsAndRatesAt(integrator, hi);
    const Constraints& at_hi = at_end.value;
    std::optional<double> search_from = lo;
    if (!armed) {
      armed = true;
      if (at_hi.value[0] > 0.0) {
        search_from = std::nullopt;  // left the starting zero: nothing to locate in this step
      } else {
        search_from = FirstMovingPoint(integrator, lo, hi);
        if (!search_from) return {ModeEnd::Kind::kStuck, hi};
      }
    }
    std::optional<ModeEnd> end;
    if (search_from) end = FirstZero(integrator, at_hi, *search_from, hi, tolerance);
    if (search_from && !end) {
      const ConstraintsAndRates at_from =
          at_lo && *search_from == lo ? *at_lo : ConstraintsAndRatesAt(integrator, *search_from);
      end = ZeroWithinStep(integrator, *search_from, at_from, hi, at_end, tolerance);
    }
    at_lo = at_end;
    if (!end && hi >= horizon) end = ModeEnd{ModeEnd::Kind::kHorizon, horizon};
    sampler.Take(integrator, t, lo, end ? end->tau : hi);
    if (end) return *end;
  }
}

// What a mode started at time t from x has done by `end` (not stuck): its segment, and the event
// that ends it unless the horizon does, with the state there at rest. A stick left at
// s = +threshold starts slip-, at s = -threshold slip+ (eq. 4 of the paper, ERRATA); after a stop
// Coulomb's law decides.
template <IntegrableOscillatorModel M>
struct ModeOutcome {
  BasicSegment<typename M::State> segment;
  std::optional<BasicEvent<typename M::State>> event;
};

template <IntegrableOscillatorModel M>
ModeOutcome<M> Outcome(const ModeIntegrator<M>& integrator, double t, const typename M::State& x, const ModeEnd& end,
                       double duration) {
  const ModeField<M>& field = integrator.field();
  if (end.kind == ModeEnd::Kind::kHorizon) {
    return {{field.mode, t, duration, x, integrator.Integrated(end.tau), SegmentEnd::kHorizon}, std::nullopt};
  }
  BasicEvent<typename M::State> event{t + end.tau, EventKind::kStop, field.mode, field.mode,
                                      field.model.AtRest(integrator.Integrated(end.tau), field.p)};
  if (field.mode == Mode::kStick) {
    event.kind = EventKind::kStickExit;
    event.mode_after = end.constraint == 0 ? Mode::kSlipNegative : Mode::kSlipPositive;
  } else {
    event.mode_after = ModeAtRest(field.model, event.state, field.PhaseAt(end.tau), field.p);
  }
  const SegmentEnd reason = event.kind == EventKind::kStop ? SegmentEnd::kStop : SegmentEnd::kStickExit;
  return {{field.mode, t, event.t, x, event.state, reason}, event};
}

// Why a simulation ends with SimulationEnd::kStuckAtRest, for a mode started at time t.
template <IntegrableOscillatorModel M>
std::string StuckMessage(const ModeIntegrator<M>& integrator, double t, const ModeEnd& end) {
  const ModeField<M>& field = integrator.field();
  return fmt::format("at t = {} a {} from rest does not move in its direction (contact velocity {} after {})", t,
                     ToString(field.mode), field.model.ContactVelocity(integrator.Interpolated(end.tau), field.p), end.tau);
}

// Throws InvalidInput naming the first input that is not valid.
template <IntegrableOscillatorModel M>
void CheckInput(const M& model, const typename M::Parameters& p, const typename M::State& x0, double phi,
                const BasicSimulationOptions<typename M::State>& options, const OdeintOptions& odeint) {
  if (auto invalid = model.Validate(p)) throw *invalid;
  for (int i = 0; i < x0.size(); ++i) {
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
}

}  // namespace odeint_simulation

// One mode only, no events: the state after elapsed time s from `start` at forcing phase `phase`
// (pascal_2014/odeint_simulator.hpp's IntegrateMode for any model). Throws InvalidInput if s < 0 or s is not
// finite.
template <IntegrableOscillatorModel M>
typename M::State IntegrateMode(const M& model, Mode mode, const typename M::State& start, double phase, double s,
                                const typename M::Parameters& p, const OdeintOptions& odeint = {}) {
  if (!(std::isfinite(s) && s >= 0.0)) throw InvalidInput("s", s, "finite and >= 0");
  if (s == 0.0) return start;
  odeint_simulation::ModeIntegrator<M> integrator({model, mode, phase, p}, start, odeint);
  while (integrator.current_time() < s) integrator.Step();
  return integrator.Integrated(s);
}

// The simulation (pascal_2014/odeint_simulator.hpp's SimulateOdeint for any model). Throws InvalidInput for
// bad input (model.Validate(p) fails, x0, phi or the options not finite, duration <= 0,
// sample_step < 0, invalid `odeint`). A slip started from rest that does not move in its
// direction ends the simulation with SimulationEnd::kStuckAtRest.
template <IntegrableOscillatorModel M>
BasicSimulationResult<M> SimulateOdeint(const M& model, const typename M::Parameters& p, const typename M::State& x0,
                                        double phi, const BasicSimulationOptions<typename M::State>& options,
                                        const OdeintOptions& odeint = {}) {
  using namespace odeint_simulation;
  CheckInput(model, p, x0, phi, options, odeint);
  BasicSimulationResult<M> result;
  result.parameters = p;
  result.phi = phi;
  Sampler<M> sampler(options);
  const double omega = model.ForcingFrequency(p);
  double t = 0.0;
  typename M::State x = x0;
  Mode mode = StartingMode(model, x0, phi, p);
  while (true) {
    const double horizon = options.duration - t;
    if (horizon <= 0.0) {  // the last event fell on the horizon: a final segment of length 0
      result.segments.push_back({mode, t, t, x, x, SegmentEnd::kHorizon});
      break;
    }
    ModeIntegrator<M> integrator({model, mode, omega * t + phi, p}, x, odeint);
    const ModeEnd end = RunMode(integrator, x, t, horizon, odeint.event_time_tolerance, sampler);
    if (end.kind == ModeEnd::Kind::kStuck) {
      result.end = SimulationEnd::kStuckAtRest;
      result.message = StuckMessage(integrator, t, end);
      break;
    }
    const auto [segment, event] = Outcome(integrator, t, x, end, options.duration);
    result.segments.push_back(segment);
    if (!event) break;
    result.events.push_back(*event);
    t = event->t;
    x = event->state;
    mode = event->mode_after;
    ReportSimulated(options, 2.0 * std::numbers::pi / omega, t);
    if (static_cast<int>(result.events.size()) >= options.max_events) {
      result.end = SimulationEnd::kMaxEvents;
      result.message = fmt::format("stopped after {} events at t = {} (max_events)", result.events.size(), t);
      break;
    }
  }
  result.samples = std::move(sampler).Samples();
  return result;
}

}  // namespace stickslip
