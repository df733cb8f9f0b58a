#include "stickslip/analysis/settled_motion.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "stickslip/model/pascal_2014/events.hpp"
#include "stickslip/model/transient.hpp"

namespace stickslip {

namespace {

// max |x2| over the simulated segments of `r`: at each segment's ends, and inside a slip also at
// the extrema of its closed form (MinimumAndMaximum: the zeros of x2'); NaN if a search was cut short.
double AmplitudeX2(const SimulationResult& r) {
  const Parameters& p = r.parameters;
  double amplitude = 0.0;
  for (const Segment& s : r.segments) {
    double low = std::min(s.start(1), s.end(1)), high = std::max(s.start(1), s.end(1));
    if (s.mode != Mode::kStick) {
      const ModeMotion<double> motion = MotionInMode(s.mode, s.start, p.omega * s.t_start + r.phi, p);
      const Extrema e = MinimumAndMaximum(CoordinateAlong(motion, 1), 0.0, s.t_end - s.t_start);
      if (std::isnan(e.minimum.value) || std::isnan(e.maximum.value)) return std::numeric_limits<double>::quiet_NaN();
      low = std::min(low, e.minimum.value);
      high = std::max(high, e.maximum.value);
    }
    amplitude = std::max({amplitude, high, -low});
  }
  return amplitude;
}

}  // namespace

SettledMotion SimulateSettled(const Parameters& p, const State& start, double phi_section, const SettleOptions& o) {
  const double period = 2.0 * std::numbers::pi / p.omega;
  SettledMotion motion;
  // The transients in chunks (SimulateTransient), each a simulation under max_events_per_simulation,
  // so that the largest transients (1e6 periods, millions of events) run.
  TransientOptions transient;
  transient.periods = o.transient_periods;
  transient.simulation.max_events = o.max_events_per_simulation;
  const Transient settled = SimulateTransient(SimulateExact, p, start, phi_section, transient);
  motion.last = settled.state;
  if (!settled.Completed()) {
    motion.end = settled.end;
    motion.message = settled.message;
    return motion;
  }
  SimulationOptions record;
  record.duration = o.recorded_periods * period;
  record.max_events = o.max_events_per_simulation;
  motion.record = SimulateExact(p, settled.state, phi_section, record);
  const SimulationResult& r = motion.record;
  if (!r.Completed()) {
    motion.end = r.end;
    motion.message = r.message;
    if (!r.segments.empty()) motion.last = r.segments.back().end;
    return motion;
  }
  for (int k = 1; k <= o.recorded_periods; ++k) motion.section.push_back(StateAt(r, k * period));
  motion.last = motion.section.back();
  for (const Event& e : r.events) {
    motion.stops_per_period += e.kind == EventKind::kStop;
    motion.sticks_per_period += e.mode_after == Mode::kStick;
  }
  motion.amplitude_x2 = AmplitudeX2(r);
  motion.stops_per_period /= o.recorded_periods;
  motion.sticks_per_period /= o.recorded_periods;
  const std::vector<State>& section = motion.section;
  const int n = static_cast<int>(section.size());
  for (int candidate = 1; candidate <= n / 2 && motion.period == 0; ++candidate) {
    bool repeats = true;
    for (int k = 0; k + candidate < n && repeats; ++k) {
      repeats = (section[k + candidate] - section[k]).lpNorm<Eigen::Infinity>() <= o.periodicity_tolerance;
    }
    if (repeats) motion.period = candidate;
  }
  return motion;
}

}  // namespace stickslip
