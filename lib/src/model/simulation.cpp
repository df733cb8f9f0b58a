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
    case SimulationEnd::kStuckAtRest: break;
  }
  return "stuck-at-rest";
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

bool FrictionLevelsEqual(const Parameters& p) {
  return std::abs(p.u_r - p.u_s) <= 1e-12 * p.u_r;
}

// In a slip: the first zero of x2'. A crossing is a stop, decided by Coulomb's law (eq. 4); a
// touch (x2' = x2'' = 0) is an abnormal stop when u_r = u_s (eq. 25) and otherwise the onset
// of a stick, since there |s| = eta u_s < eta u_r.
std::optional<SegmentEndpoint> SlipEnd(Mode mode, const ModeMotion<double>& motion, double phase,
                                       double horizon, const Parameters& p,
                                       const ZeroSearchOptions& zeros) {
  const SinusoidSum velocity = CoordinateAlong(motion, 3);
  const std::vector<Zero> found = Zeros(velocity, 0.0, horizon, 1, zeros);
  if (found.empty()) return std::nullopt;
  const Zero& z = found.front();
  State at = motion.StateAt(z.t);
  at(3) = 0.0;
  Mode next;
  if (z.kind == ZeroKind::kTouch) {
    next = FrictionLevelsEqual(p) ? mode : Mode::kStick;
  } else {
    next = ModeFromRest(at, phase + p.omega * z.t, p);
    if (next == mode) next = Mode::kStick;  // rounding at the threshold: cannot go on
  }
  return SegmentEndpoint{z.t, SegmentEnd::kStop, next};
}

// In a stick: the first time G (exit into slip+) or G1 (exit into slip-) crosses zero
// (eq. 11, 35). A touch leaves the constraint satisfied and the stick goes on. The search reaches
// one forcing period ahead, then two, four, ... until an exit or the horizon: searched to the
// horizon at once, a constraint that never crosses would make every stick cost the whole
// remaining time (a long simulation quadratic in its duration), while the doubling costs at
// most twice the reach it needs. Every search starts at the stick's start, where a constraint
// at zero level is understood (Zeros), and ends where both constraints are clear of the touch
// level: there the sign alone tells whether a zero lies before the end, so a grazing or a
// crossing next to the end is classified as by a search that went on past it.
std::optional<SegmentEndpoint> StickEnd(const ModeMotion<double>& motion, double phase,
                                        double horizon, const Parameters& p,
                                        const ZeroSearchOptions& zeros) {
  const SinusoidSum force = StickForceAlong(motion, phase, p);
  const double threshold = p.eta * p.u_r;
  const SinusoidSum g = force.Affine(1.0, threshold);    // G = s + eta u_r
  const SinusoidSum g1 = force.Affine(-1.0, threshold);  // G1 = -s + eta u_r
  std::optional<SegmentEndpoint> end;
  auto first_crossing = [&](const SinusoidSum& constraint, Mode next, double to) {
    double from = 0.0;
    // Touches are rare; look past each one.
    while (from < to) {
      const std::vector<Zero> found = Zeros(constraint, from, to, 1, zeros);
      if (found.empty()) return;
      if (found.front().kind == ZeroKind::kCrossing) {
        if (!end || found.front().t < end->elapsed) {
          end = SegmentEndpoint{found.front().t, SegmentEnd::kStickExit, next};
        }
        return;
      }
      from = found.front().t;
    }
  };
  const double g_level = 2.0 * zeros.touch_tolerance * g.Scale();  // twice: room for rounding
  const double g1_level = 2.0 * zeros.touch_tolerance * g1.Scale();
  for (double reach = 2.0 * std::numbers::pi / p.omega;; reach *= 2.0) {
    double to = std::min(horizon, reach);
    while (to < horizon && !(std::abs(g(to)) > g_level && std::abs(g1(to)) > g1_level)) {
      to = std::min(horizon, to + 1e-3 * reach);
    }
    first_crossing(g, Mode::kSlipPositive, to);
    first_crossing(g1, Mode::kSlipNegative, to);
    if (end || to == horizon) return end;
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
  while (true) {
    const double phase = p.omega * t + phi;
    const double horizon = options.duration - t;
    const ModeMotion<double> motion = MotionInMode(mode, x, phase, p);
    const std::optional<SegmentEndpoint> end =
        mode == Mode::kStick ? StickEnd(motion, phase, horizon, p, options.zeros)
                             : SlipEnd(mode, motion, phase, horizon, p, options.zeros);
    Segment segment{mode, t, options.duration, x, State::Zero(), SegmentEnd::kHorizon};
    if (!end) {
      segment.end = motion.StateAt(horizon);
      result.segments.push_back(segment);
      break;
    }
    segment.t_end = t + end->elapsed;
    segment.end = motion.StateAt(end->elapsed);
    segment.end(3) = 0.0;  // both events happen at rest: x2' = 0 exactly
    segment.end_reason = end->reason;
    result.segments.push_back(segment);
    result.events.push_back({segment.t_end,
                             end->reason == SegmentEnd::kStop ? EventKind::kStop
                                                              : EventKind::kStickExit,
                             mode, end->next, segment.end});
    t = segment.t_end;
    x = segment.end;
    mode = end->next;
    if (static_cast<int>(result.events.size()) >= options.max_events) {
      result.end = SimulationEnd::kMaxEvents;
      result.message = fmt::format("stopped after {} events at t = {} (max_events)",
                                   result.events.size(), t);
      break;
    }
  }
  if (options.sample_step > 0.0) {
    // A duration meant as a whole number of sample steps may come out a rounding error short of
    // it (N T / T < N): its last sample still belongs in.
    const auto count = static_cast<long>(std::floor(options.duration / options.sample_step * (1.0 + 1e-12)));
    for (long k = 0; k <= count; ++k) {
      const double ts = std::min(static_cast<double>(k) * options.sample_step, options.duration);
      if (ts > result.segments.back().t_end) break;
      result.samples.push_back({ts, StateAt(result, ts)});
    }
  }
  return result;
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
