#include "stickslip/orbits/margins.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "stickslip/model/events.hpp"
#include "stickslip/numerics/sinusoid_sum.hpp"

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
// of either end (there f is at an end value fixed by an end condition); +inf if none.
Extremum InteriorMinimum(const SinusoidSum& f, double d) {
  const double guard = 1e-9 * std::max(1.0, d);
  Extremum best{0.0, kInfinity};
  const SinusoidSum df = f.Derivative();
  const SinusoidSum d2f = df.Derivative();
  if (!(d > 2 * guard)) return best;
  for (const Zero& z : Zeros(df, guard, d - guard, std::numeric_limits<int>::max())) {
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
  const Signature& signature = orbit.signature;
  const double threshold = p.eta * p.u_r;
  std::vector<Margin> margins;
  margins.reserve(5 * signature.size() + 1);
  auto add = [&](const char* name, MarginKind kind, int i, double value, double t) {
    margins.push_back({name, kind, i, value, t});
  };

  State start = orbit.InitialState();
  std::vector<double> times = {0.0};
  for (int i = 0; i < signature.size(); ++i) {
    const Mode mode = signature.segments()[i];
    const double d = orbit.durations[i];
    times.push_back(times[i] + d);
    const double phase = orbit.phi + p.omega * times[i];
    const double end_phase = phase + p.omega * d;
    const ModeMotion<double> motion = MotionInMode(mode, start, phase, p);
    const State end = motion.StateAt(d);
    start = end;
    add("duration", MarginKind::kDuration, i, d, times[i]);

    if (mode != Mode::kStick) {
      const double sigma = SlipDirection(mode);
      const SinusoidSum velocity = CoordinateAlong(motion, 3).Affine(sigma, 0.0);
      const Extremum low = InteriorMinimum(velocity, d);
      add("velocity", MarginKind::kSlipVelocity, i, low.value, times[i] + low.t);
      const double force = StickForce(end, end_phase, p);
      const double x2_acceleration = Acceleration(mode, end, end_phase, p)(1);
      switch (signature.EndKind(i)) {
        case SegmentEndKind::kReversal:
          add("stop-slope", MarginKind::kStopSlope, i, -sigma * x2_acceleration, times[i + 1]);
          add("reversal", MarginKind::kStopForce, i,
              signature.NextMode(i) == Mode::kSlipNegative ? force - threshold : -force - threshold,
              times[i + 1]);
          break;
        case SegmentEndKind::kStickEntry:
          add("stop-slope", MarginKind::kStopSlope, i, -sigma * x2_acceleration, times[i + 1]);
          add("stick-entry", MarginKind::kStopForce, i, threshold - std::abs(force), times[i + 1]);
          break;
        default: {  // abnormal stop: x2'' = 0 there; x2''' = -chi eta (x2' - x1') - omega sin
          const double jerk = -p.chi * p.eta * (end(3) - end(2)) - p.omega * std::sin(end_phase);
          add("abnormal-stop", MarginKind::kStopForce, i, sigma * jerk, times[i + 1]);
          break;
        }
      }
      continue;
    }

    const SinusoidSum force = StickForceAlong(motion, phase, p);
    const SinusoidSum g = force.Affine(1.0, threshold);    // G, eq. (35)
    const SinusoidSum g1 = force.Affine(-1.0, threshold);  // G1
    const bool exit_negative = signature.EndKind(i) == SegmentEndKind::kExitToNegative;
    // The constraint that ends the stick is zero at the exit by its end condition.
    auto constraint_margin = [&](const char* name, const SinusoidSum& c, bool ends_stick) {
      Extremum low = ends_stick ? InteriorMinimum(c, d) : Minimum(c, 0.0, d);
      if (ends_stick && c(0.0) < low.value) low = {0.0, c(0.0)};
      add(name, MarginKind::kStickConstraint, i, low.value, times[i] + low.t);
    };
    constraint_margin("G", g, !exit_negative);
    constraint_margin("G1", g1, exit_negative);
    const double slope = force.Derivative()(d);
    add("exit-slope", MarginKind::kExitSlope, i, exit_negative ? slope : -slope, times[i + 1]);
  }
  margins.push_back({"sliding-friction", MarginKind::kFrictionLevel, -1, p.u_s, 0.0});
  return margins;
}

Margin SmallestMargin(const std::vector<Margin>& margins) {
  return *std::min_element(margins.begin(), margins.end(),
                           [](const Margin& a, const Margin& b) { return a.value < b.value; });
}

}  // namespace stickslip
