// The exact event-driven simulator, for any model (oscillator_model.hpp): it advances the model's
// closed-form motion in each mode from event to event, and locates every stop and stick exit by
// bracketing root finding on the closed form (numerics/sinusoid_sum.hpp), so no event between two
// samples can be missed. Coulomb's law decides each mode at rest (the model's ModeFromRest).
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include <fmt/format.h>

#include "stickslip/model/oscillator_model.hpp"
#include "stickslip/model/simulation.hpp"

namespace stickslip {

namespace exact_simulation {

// The end of the current segment: when, how, and the mode after it.
struct SegmentEndpoint {
  double elapsed = 0.0;
  SegmentEnd reason = SegmentEnd::kHorizon;
  Mode next = Mode::kStick;
};

// What the search for a segment's end found: its end, none before the horizon (complete), or
// no answer (a root search cut short).
struct SegmentSearch {
  std::optional<SegmentEndpoint> end;
  ZeroSearchStatus status = ZeroSearchStatus::kComplete;
};

// In a slip: the first zero of the contact velocity. A crossing is a stop, decided by Coulomb's
// law (eq. 4); a touch (s = s' = 0) is an abnormal stop where the model admits them (u_r = u_s,
// eq. 25) and otherwise the onset of a stick, since there the friction needed is the kinetic
// level, below the static one.
template <OscillatorModel M>
SegmentSearch SlipEnd(const M& model, Mode mode, const typename M::Motion& motion, double phase, double horizon,
                      const typename M::Parameters& p, const ZeroSearchOptions& zeros) {
  const ZeroSearch found = Zeros(model.ContactVelocityAlong(motion), 0.0, horizon, 1, zeros);
  if (!found.Complete()) return {std::nullopt, found.status};
  if (found.zeros.empty()) return {};
  const Zero& z = found.zeros.front();
  const typename M::State at = model.AtRest(motion.StateAt(z.t), p);
  Mode next;
  if (z.kind == ZeroKind::kTouch) {
    next = model.AbnormalStopsPossible(p) ? mode : Mode::kStick;
  } else {
    next = model.ModeFromRest(at, phase + model.ForcingFrequency(p) * z.t, p);
    if (next == mode) next = Mode::kStick;  // rounding at the threshold: cannot go on
  }
  return {SegmentEndpoint{z.t, SegmentEnd::kStop, next}};
}

// `found` with the first crossing of a stick constraint in [from, to], into `next`, if it comes
// before the end found already. A touch leaves the constraint satisfied and the stick goes on;
// touches are rare, so the search looks past each one, all of them within one search's bound.
template <EventFunction F>
SegmentSearch FirstCrossing(const F& constraint, Mode next, double from, double to,
                                   const ZeroSearchOptions& zeros, SegmentSearch found) {
  ZeroSearchOptions left = zeros;
  while (from < to) {
    const ZeroSearch search = Zeros(constraint, from, to, 1, left);
    left.max_intervals -= search.intervals;
    if (!search.Complete()) {
      found.status = search.status;
      return found;
    }
    if (search.zeros.empty()) return found;
    const Zero& z = search.zeros.front();
    if (z.kind == ZeroKind::kCrossing) {
      if (!found.end || z.t < found.end->elapsed) found.end = SegmentEndpoint{z.t, SegmentEnd::kStickExit, next};
      return found;
    }
    from = z.t;
  }
  return found;
}

// In a stick: the first time G = s + threshold (exit into slip+) or G1 = -s + threshold (exit into
// slip-) crosses zero (eq. 11, 35). The search reaches one forcing period ahead, then two, four,
// ... up to kMaxReachPeriods, and from there on in windows of that many periods, until an exit or
// the horizon: searched to the horizon at once, a constraint that never crosses would make every
// stick cost the whole remaining time (a long simulation quadratic in its duration), while the
// doubling costs at most twice the reach it needs, and the windows keep each search within the
// root finder's bound on sub-intervals. Every search starts at the stick's start, where a
// constraint at zero level is understood (Zeros), or at the end of the last window, and ends
// where both constraints are clear of the touch level: there the sign alone tells whether a zero
// lies before the end, so a grazing or a crossing next to the end is classified as by a search
// that went on past it.
template <OscillatorModel M>
SegmentSearch StickEnd(const M& model, const typename M::Motion& motion, double phase, double horizon,
                       const typename M::Parameters& p, const ZeroSearchOptions& zeros) {
  constexpr double kMaxReachPeriods = 64.0;
  using F = typename M::EventFunction;
  const F force = model.StickForceAlong(motion, phase, p);
  const double threshold = model.StaticThreshold(p);
  const F g = force.Affine(1.0, threshold);
  const F g1 = force.Affine(-1.0, threshold);
  SegmentSearch result;
  const double period = 2.0 * std::numbers::pi / model.ForcingFrequency(p);
  double from = 0.0;
  for (double reach = period;; reach = std::min(2.0 * reach, kMaxReachPeriods * period)) {
    double to = std::min(horizon, from + reach);
    // Twice the touch level: room for rounding.
    const auto clear = [&](const F& f) { return std::abs(f(to)) > 2.0 * zeros.touch_tolerance * SizeAt(f, to); };
    while (to < horizon && !(clear(g) && clear(g1))) {
      to = std::min(horizon, to + 1e-3 * reach);
    }
    result = FirstCrossing(g, Mode::kSlipPositive, from, to, zeros, std::move(result));
    result = FirstCrossing(g1, Mode::kSlipNegative, from, to, zeros, std::move(result));
    if (result.end || result.status != ZeroSearchStatus::kComplete || to == horizon) return result;
    if (reach == kMaxReachPeriods * period) from = to;
  }
}

// Samples at k sample_step, each from the first segment that reaches it, as soon as that segment
// is known. A duration meant as a whole number of sample steps may come out a rounding error
// short of it (N T / T < N): its last sample still belongs in.
template <OscillatorModel M>
class Sampler {
 public:
  using State = typename M::State;
  Sampler(const M& model, const typename M::Parameters& p, double phi,
          const BasicSimulationOptions<State>& options)
      : model_(model), p_(p), phi_(phi), options_(options), count_(options.SampleCount()) {}

  void Take(const BasicSegment<State>& s, BasicSimulationResult<M>& result) {
    const double omega = model_.ForcingFrequency(p_);
    for (; next_ < count_; ++next_) {
      const double ts = options_.SampleTime(next_);
      if (ts > s.t_end) break;
      const BasicTimeSample<State> sample{
          ts, model_.MotionInMode(s.mode, s.start, omega * s.t_start + phi_, p_).StateAt(ts - s.t_start)};
      if (options_.on_sample) {
        options_.on_sample(sample, s.mode);
      } else {
        result.samples.push_back(sample);
      }
    }
  }

 private:
  const M& model_;
  const typename M::Parameters& p_;
  double phi_;
  const BasicSimulationOptions<State>& options_;
  long count_;
  long next_ = 0;
};

}  // namespace exact_simulation

// Initial mode from a state: the sign of the contact velocity, or Coulomb's law at rest when it is
// zero to rounding (the model's NearRest).
template <OscillatorModel M>
Mode InitialMode(const M& model, const typename M::State& x0, double phi, const typename M::Parameters& p) {
  if (model.NearRest(x0, p)) return model.ModeFromRest(model.AtRest(x0, p), phi, p);
  return model.ContactVelocity(x0, p) < 0.0 ? Mode::kSlipNegative : Mode::kSlipPositive;
}

// Preconditions: model.Validate(p) passed, x0 finite, duration > 0.
template <OscillatorModel M>
BasicSimulationResult<M> SimulateExact(const M& model, const typename M::Parameters& p,
                                       const typename M::State& x0, double phi,
                                       const BasicSimulationOptions<typename M::State>& options) {
  using namespace exact_simulation;
  BasicSimulationResult<M> result;
  result.parameters = p;
  result.phi = phi;
  const double omega = model.ForcingFrequency(p);
  double t = 0.0;
  typename M::State x = model.NearRest(x0, p) ? model.AtRest(x0, p) : x0;
  Mode mode = InitialMode(model, x0, phi, p);
  Sampler<M> sampler(model, p, phi, options);
  while (true) {
    const double phase = omega * t + phi;
    const double horizon = options.duration - t;
    const typename M::Motion motion = model.MotionInMode(mode, x, phase, p);
    const SegmentSearch search = mode == Mode::kStick ? StickEnd(model, motion, phase, horizon, p, options.zeros)
                                                       : SlipEnd(model, mode, motion, phase, horizon, p, options.zeros);
    if (search.status != ZeroSearchStatus::kComplete) {
      result.end = SimulationEnd::kSearchLimit;
      result.message = fmt::format("the search for the end of the {} at t = {} ended: {} (max_intervals {})",
                                   ToString(mode), t, ToString(search.status), options.zeros.max_intervals);
      break;
    }
    BasicSegment<typename M::State> segment{mode, t, options.duration, x, FilledState(model, 0.0), SegmentEnd::kHorizon};
    if (!search.end) {
      segment.end = motion.StateAt(horizon);
      result.segments.push_back(segment);
      sampler.Take(segment, result);
      break;
    }
    const SegmentEndpoint& end = *search.end;
    segment.t_end = t + end.elapsed;
    segment.end = model.AtRest(motion.StateAt(end.elapsed), p);  // both events happen at rest exactly
    segment.end_reason = end.reason;
    result.segments.push_back(segment);
    sampler.Take(segment, result);
    result.events.push_back({segment.t_end, end.reason == SegmentEnd::kStop ? EventKind::kStop : EventKind::kStickExit,
                             mode, end.next, segment.end});
    t = segment.t_end;
    x = segment.end;
    mode = end.next;
    ReportSimulated(options, 2.0 * std::numbers::pi / omega, t);
    if (static_cast<int>(result.events.size()) >= options.max_events) {
      result.end = SimulationEnd::kMaxEvents;
      result.message = fmt::format("stopped after {} events at t = {} (max_events)", result.events.size(), t);
      break;
    }
  }
  return result;
}

}  // namespace stickslip
