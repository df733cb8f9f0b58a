#include "stickslip/model/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include <fmt/format.h>

#include "stickslip/model/events.hpp"

namespace stickslip {

const char* ToString(SimulationEnd end) {
  switch (end) {
    case SimulationEnd::kDuration: return "duration";
    case SimulationEnd::kMaxEvents: return "max-events";
    case SimulationEnd::kStuckAtRest: return "stuck-at-rest";
    case SimulationEnd::kSearchLimit: break;
  }
  return "search-limit";
}

const char* ToString(EventKind kind) {
  return kind == EventKind::kStop ? "stop" : "stick-exit";
}

const char* ToString(SegmentEnd end) {
  switch (end) {
    case SegmentEnd::kStop: return "stop";
    case SegmentEnd::kStickExit: return "stick-exit";
    case SegmentEnd::kHorizon: break;
  }
  return "horizon";
}

namespace {

// An x2' within rounding of zero is a state at rest: a sampled state at a stop carries ~1e-15,
// and a slip started from it would miss the stop that is due at once.
bool AtRest(const State& x) { return std::abs(x(3)) <= 1e-12 * (1.0 + x.head<3>().lpNorm<Eigen::Infinity>()); }

}  // namespace

Mode InitialMode(const State& x0, double phi, const Parameters& p) {
  if (AtRest(x0)) {
    State rest = x0;
    rest(3) = 0.0;
    return ModeFromRest(rest, phi, p);
  }
  return x0(3) < 0.0 ? Mode::kSlipNegative : Mode::kSlipPositive;
}

namespace {

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

bool FrictionLevelsEqual(const Parameters& p) {
  return std::abs(p.u_r - p.u_s) <= 1e-12 * p.u_r;
}

// In a slip: the first zero of x2'. A crossing is a stop, decided by Coulomb's law (eq. 4); a
// touch (x2' = x2'' = 0) is an abnormal stop when u_r = u_s (eq. 25) and otherwise the onset
// of a stick, since there |s| = eta u_s < eta u_r.
SegmentSearch SlipEnd(Mode mode, const ModeMotion<double>& motion, double phase, double horizon,
                      const Parameters& p, const ZeroSearchOptions& zeros) {
  const SinusoidSum velocity = CoordinateAlong(motion, 3);
  const ZeroSearch found = Zeros(velocity, 0.0, horizon, 1, zeros);
  if (!found.Complete()) return {std::nullopt, found.status};
  if (found.zeros.empty()) return {};
  const Zero& z = found.zeros.front();
  State at = motion.StateAt(z.t);
  at(3) = 0.0;
  Mode next;
  if (z.kind == ZeroKind::kTouch) {
    next = FrictionLevelsEqual(p) ? mode : Mode::kStick;
  } else {
    next = ModeFromRest(at, phase + p.omega * z.t, p);
    if (next == mode) next = Mode::kStick;  // rounding at the threshold: cannot go on
  }
  return {SegmentEndpoint{z.t, SegmentEnd::kStop, next}};
}

// In a stick: the first time G (exit into slip+) or G1 (exit into slip-) crosses zero
// (eq. 11, 35). A touch leaves the constraint satisfied and the stick goes on. The search reaches
// one forcing period ahead, then two, four, ... up to kMaxReachPeriods, and from there on in
// windows of that many periods, until an exit or the horizon: searched to the horizon at once, a
// constraint that never crosses would make every stick cost the whole remaining time (a long
// simulation quadratic in its duration), while the doubling costs at most twice the reach it
// needs, and the windows keep each search within the root finder's bound on sub-intervals.
// Every search starts at the stick's start, where a constraint at zero level is understood
// (Zeros), or at the end of the last window, and ends where both constraints are clear of the
// touch level: there the sign alone tells whether a zero lies before the end, so a grazing or a
// crossing next to the end is classified as by a search that went on past it.
SegmentSearch StickEnd(const ModeMotion<double>& motion, double phase, double horizon, const Parameters& p,
                       const ZeroSearchOptions& zeros) {
  constexpr double kMaxReachPeriods = 64.0;
  const SinusoidSum force = StickForceAlong(motion, phase, p);
  const double threshold = p.eta * p.u_r;
  const SinusoidSum g = force.Affine(1.0, threshold);    // G = s + eta u_r
  const SinusoidSum g1 = force.Affine(-1.0, threshold);  // G1 = -s + eta u_r
  SegmentSearch result;
  auto first_crossing = [&](const SinusoidSum& constraint, Mode next, double from, double to) {
    // Touches are rare; look past each one, all of them within one search's bound.
    ZeroSearchOptions left = zeros;
    while (from < to) {
      const ZeroSearch found = Zeros(constraint, from, to, 1, left);
      left.max_intervals -= found.intervals;
      if (!found.Complete()) {
        result.status = found.status;
        return;
      }
      if (found.zeros.empty()) return;
      const Zero& z = found.zeros.front();
      if (z.kind == ZeroKind::kCrossing) {
        if (!result.end || z.t < result.end->elapsed) result.end = SegmentEndpoint{z.t, SegmentEnd::kStickExit, next};
        return;
      }
      from = z.t;
    }
  };
  const double g_level = 2.0 * zeros.touch_tolerance * g.Scale();  // twice: room for rounding
  const double g1_level = 2.0 * zeros.touch_tolerance * g1.Scale();
  const double period = 2.0 * std::numbers::pi / p.omega;
  double from = 0.0;
  for (double reach = period;; reach = std::min(2.0 * reach, kMaxReachPeriods * period)) {
    double to = std::min(horizon, from + reach);
    while (to < horizon && !(std::abs(g(to)) > g_level && std::abs(g1(to)) > g1_level)) {
      to = std::min(horizon, to + 1e-3 * reach);
    }
    first_crossing(g, Mode::kSlipPositive, from, to);
    first_crossing(g1, Mode::kSlipNegative, from, to);
    if (result.end || result.status != ZeroSearchStatus::kComplete || to == horizon) return result;
    if (reach == kMaxReachPeriods * period) from = to;
  }
}

}  // namespace

SimulationResult SimulateExact(const Parameters& p, const State& x0, double phi,
                               const SimulationOptions& options) {
  SimulationResult result;
  result.parameters = p;
  result.phi = phi;
  double t = 0.0;
  State x = x0;
  Mode mode = InitialMode(x0, phi, p);
  if (AtRest(x0)) x(3) = 0.0;
  // Samples at k sample_step, each from the first segment that reaches it, as soon as that segment
  // is known. A duration meant as a whole number of sample steps may come out a rounding error
  // short of it (N T / T < N): its last sample still belongs in.
  const long sample_count = options.sample_step > 0.0
                                ? static_cast<long>(std::floor(options.duration / options.sample_step * (1.0 + 1e-12))) + 1
                                : 0;
  long next_sample = 0;
  auto sample_segment = [&](const Segment& s) {
    for (; next_sample < sample_count; ++next_sample) {
      const double ts = std::min(static_cast<double>(next_sample) * options.sample_step, options.duration);
      if (ts > s.t_end) break;
      const TimeSample sample{ts, Flow(s.mode, s.start, p.omega * s.t_start + phi, ts - s.t_start, p)};
      if (options.on_sample) {
        options.on_sample(sample, s.mode);
      } else {
        result.samples.push_back(sample);
      }
    }
  };
  while (true) {
    const double phase = p.omega * t + phi;
    const double horizon = options.duration - t;
    const ModeMotion<double> motion = MotionInMode(mode, x, phase, p);
    const SegmentSearch search = mode == Mode::kStick ? StickEnd(motion, phase, horizon, p, options.zeros)
                                                       : SlipEnd(mode, motion, phase, horizon, p, options.zeros);
    if (search.status != ZeroSearchStatus::kComplete) {
      result.end = SimulationEnd::kSearchLimit;
      result.message = fmt::format("the search for the end of the {} at t = {} ended: {} (max_intervals {})",
                                   ToString(mode), t, ToString(search.status), options.zeros.max_intervals);
      break;
    }
    const std::optional<SegmentEndpoint>& end = search.end;
    Segment segment{mode, t, options.duration, x, State::Zero(), SegmentEnd::kHorizon};
    if (!end) {
      segment.end = motion.StateAt(horizon);
      result.segments.push_back(segment);
      sample_segment(segment);
      break;
    }
    segment.t_end = t + end->elapsed;
    segment.end = motion.StateAt(end->elapsed);
    segment.end(3) = 0.0;  // both events happen at rest: x2' = 0 exactly
    segment.end_reason = end->reason;
    result.segments.push_back(segment);
    sample_segment(segment);
    result.events.push_back({segment.t_end,
                             end->reason == SegmentEnd::kStop ? EventKind::kStop
                                                              : EventKind::kStickExit,
                             mode, end->next, segment.end});
    t = segment.t_end;
    x = segment.end;
    mode = end->next;
    ReportSimulated(options, p, t);
    if (static_cast<int>(result.events.size()) >= options.max_events) {
      result.end = SimulationEnd::kMaxEvents;
      result.message = fmt::format("stopped after {} events at t = {} (max_events)",
                                   result.events.size(), t);
      break;
    }
  }
  return result;
}

void ReportSimulated(const SimulationOptions& options, const Parameters& p, double t) {
  if (!options.progress) return;
  const double period = 2.0 * std::numbers::pi / p.omega;
  options.progress({t / period, options.duration / period, "periods"});
}

State StateAt(const SimulationResult& result, double t) {
  const auto it = std::lower_bound(
      result.segments.begin(), result.segments.end(), t,
      [](const Segment& s, double time) { return s.t_end < time; });
  const Segment& s = it == result.segments.end() ? result.segments.back() : *it;
  const Parameters& p = result.parameters;
  return Flow(s.mode, s.start, p.omega * s.t_start + result.phi, t - s.t_start, p);
}

}  // namespace stickslip
