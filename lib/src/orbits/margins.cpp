#include "stickslip/orbits/margins.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "stickslip/model/events.hpp"
#include "stickslip/numerics/sinusoid_sum.hpp"
#include "stickslip/orbits/segment_walk.hpp"

namespace stickslip {

const char* ToString(MarginKind kind) {
  switch (kind) {
    case MarginKind::kDuration: return "duration";
    case MarginKind::kSlipVelocity: return "slip-velocity";
    case MarginKind::kStopSlope: return "stop-slope";
    case MarginKind::kStopForce: return "stop-force";
    case MarginKind::kStickConstraint: return "stick-constraint";
    case MarginKind::kExitSlope: return "exit-slope";
    case MarginKind::kFrictionLevel: break;
  }
  return "friction-level";
}

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The smallest interior local minimum of f on (0, d), ignoring critical points within `guard`
// of either end (there f is at an end value fixed by an end condition); +inf if none; NaN if
// the search for them could not be completed (a NaN in the orbit, or a segment too long for the
// search's bound): a margin that is not defined there, never a wrong one.
Extremum InteriorMinimum(const SinusoidSum& f, double d) {
  const double guard = 1e-9 * std::max(1.0, d);
  Extremum best{0.0, kInfinity};
  const SinusoidSum df = f.Derivative();
  const SinusoidSum d2f = df.Derivative();
  if (std::isnan(d)) return {0.0, std::numeric_limits<double>::quiet_NaN()};
  if (!(d > 2 * guard)) return best;
  const ZeroSearch critical = Zeros(df, guard, d - guard, std::numeric_limits<int>::max());
  if (!critical.Complete()) return {0.0, std::numeric_limits<double>::quiet_NaN()};
  for (const Zero& z : critical.zeros) {
    if (d2f(z.t) < 0.0) continue;  // a maximum
    const double value = f(z.t);
    if (value < best.value) best = {z.t, value};
  }
  return best;
}

}  // namespace

std::string Margin::Name() const {
  return segment < 0 ? std::string(base) : fmt::format("{}:{}", base, segment + 1);
}

std::vector<Margin> AdmissibilityMargins(const Orbit& orbit) {
  const Parameters& p = orbit.parameters;
  const double threshold = p.eta * p.u_r;
  std::vector<Margin> margins;
  margins.reserve(5 * orbit.signature.size() + 1);
  auto add = [&](const char* name, MarginKind kind, int i, double value, double t) {
    margins.push_back({name, kind, i, value, t});
  };
  WalkSegments(orbit, Extent::kListed, PhaseRule::kFromOrigin, [&](const SegmentVisit<double>& s) {
    const int i = s.spec.listed;
    const Mode mode = s.spec.mode;
    const double d = s.duration;
    const double t_end = s.t0 + d;
    add("duration", MarginKind::kDuration, i, d, s.t0);

    if (mode != Mode::kStick) {
      const SinusoidSum velocity = CoordinateAlong(s.motion, 3).Affine(SlipDirection(mode), 0.0);
      const Extremum low = InteriorMinimum(velocity, d);
      add("velocity", MarginKind::kSlipVelocity, i, low.value, s.t0 + low.t);
      switch (s.spec.end) {
        case SegmentEndKind::kReversal:
          add("stop-slope", MarginKind::kStopSlope, i, StopSlope(mode, s.end, s.end_phase, p), t_end);
          add("reversal", MarginKind::kStopForce, i, ReversalForce(s.spec.next, s.end, s.end_phase, p), t_end);
          break;
        case SegmentEndKind::kStickEntry:
          add("stop-slope", MarginKind::kStopSlope, i, StopSlope(mode, s.end, s.end_phase, p), t_end);
          add("stick-entry", MarginKind::kStopForce, i, StickEntryForce(s.end, s.end_phase, p), t_end);
          break;
        default:
          add("abnormal-stop", MarginKind::kStopForce, i, AbnormalStopJerk(mode, s.end, s.end_phase, p), t_end);
          break;
      }
      return;
    }

    const SinusoidSum force = StickForceAlong(s.motion, s.phase, p);
    const SinusoidSum g = force.Affine(1.0, threshold);    // G, eq. (35)
    const SinusoidSum g1 = force.Affine(-1.0, threshold);  // G1
    const bool exit_negative = s.spec.end == SegmentEndKind::kExitToNegative;
    // The constraint that ends the stick is zero at the exit by its end condition.
    auto constraint_margin = [&](const char* name, const SinusoidSum& c, bool ends_stick) {
      Extremum low = ends_stick ? InteriorMinimum(c, d) : Minimum(c, 0.0, d);
      if (ends_stick && c(0.0) < low.value) low = {0.0, c(0.0)};
      add(name, MarginKind::kStickConstraint, i, low.value, s.t0 + low.t);
    };
    constraint_margin("G", g, !exit_negative);
    constraint_margin("G1", g1, exit_negative);
    const double slope = force.Derivative()(d);
    add("exit-slope", MarginKind::kExitSlope, i, exit_negative ? slope : -slope, t_end);
  });
  margins.push_back({"sliding-friction", MarginKind::kFrictionLevel, -1, p.u_s, 0.0});
  return margins;
}

Margin SmallestMargin(const std::vector<Margin>& margins) {
  const auto undefined = std::find_if(margins.begin(), margins.end(), [](const Margin& m) { return std::isnan(m.value); });
  if (undefined != margins.end()) return *undefined;
  return *std::min_element(margins.begin(), margins.end(),
                           [](const Margin& a, const Margin& b) { return a.value < b.value; });
}

}  // namespace stickslip
