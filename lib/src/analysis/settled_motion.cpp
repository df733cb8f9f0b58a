#include "stickslip/analysis/settled_motion.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

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

// The smallest p <= n/2 with section[k + p] == section[k] (to tolerance, absolute) for every k; 0 if none.
int RepeatingPeriod(const std::vector<State>& section, double tolerance) {
  const int n = static_cast<int>(section.size());
  for (int candidate = 1; candidate <= n / 2; ++candidate) {
    bool repeats = true;
    for (int k = 0; k + candidate < n && repeats; ++k) {
      repeats = (section[k + candidate] - section[k]).lpNorm<Eigen::Infinity>() <= tolerance;
    }
    if (repeats) return candidate;
  }
  return 0;
}

// max |section[k + step] - section[k]|_inf over k = from .. from + count - 1.
double StepMismatch(const std::vector<State>& section, int step, int from, int count) {
  double mismatch = 0.0;
  for (int k = from; k < from + count; ++k) {
    mismatch = std::max(mismatch, (section[k + step] - section[k]).lpNorm<Eigen::Infinity>());
  }
  return mismatch;
}

// How far a section that repeats after p periods to tolerance may still be from a motion of period
// d (d divides p) that it contracts onto; nullopt when it shows no such contraction. A motion that
// contracts slowly onto a period-d orbit whose multiplier is near a (p/d)-th root of unity returns
// nearer after p periods than after d: the p-step test passes first. Then the p-step differences
// shrink by a rate q per p periods (measured over the record: the first p of them against the
// last p), the distance still to go is at most late/(1 - q) (a geometric tail), and the d-step
// differences, shrinking too, are at most twice that distance. A motion of least period p has
// d-step differences that neither shrink nor fit that bound.
std::optional<double> ContractionOntoPeriod(const std::vector<State>& section, int p, int d) {
  const int n = static_cast<int>(section.size());
  const int span = n - 2 * p;  // periods between the first and the last window of p-step differences
  if (span < p) return std::nullopt;
  const double early = StepMismatch(section, p, 0, p);
  const double late = StepMismatch(section, p, span, p);
  if (!(late < early)) return std::nullopt;
  const double rate = std::pow(late / early, static_cast<double>(p) / span);
  const double remaining = late / (1.0 - rate);
  const double d_early = StepMismatch(section, d, 0, p);
  const double d_late = StepMismatch(section, d, n - p - d, p);
  if (!(d_late < d_early && d_late <= 2.0 * remaining)) return std::nullopt;
  return remaining;
}

struct LeastSectionPeriod {
  int period = 0;
  double settling = 0.0;
};

// The period on the section (RepeatingPeriod), reduced to the least divisor d that the section is
// contracting onto (ContractionOntoPeriod), with the distance still to go.
LeastSectionPeriod LeastPeriodOnSection(const std::vector<State>& section, double tolerance) {
  const int p = RepeatingPeriod(section, tolerance);
  for (int d = 1; d < p; ++d) {
    if (p % d != 0) continue;
    if (const std::optional<double> remaining = ContractionOntoPeriod(section, p, d)) return {d, *remaining};
  }
  return {p, 0.0};
}

struct PerPeriod {
  double stops = 0.0;
  double sticks = 0.0;
};

// Stops and sticks per forcing period over the first `periods` forcing periods of the record (the
// events are in time order).
PerPeriod CountPerPeriod(const SimulationResult& r, int periods, double forcing_period) {
  PerPeriod count;
  const double end = periods * forcing_period;
  for (const Event& e : r.events) {
    if (e.t >= end) break;
    count.stops += e.kind == EventKind::kStop;
    count.sticks += e.mode_after == Mode::kStick;
  }
  count.stops /= periods;
  count.sticks /= periods;
  return count;
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
  motion.amplitude_x2 = AmplitudeX2(r);
  const LeastSectionPeriod least = LeastPeriodOnSection(motion.section, o.periodicity_tolerance);
  motion.period = least.period;
  motion.settling = least.settling;
  // Over whole least periods (a period-p motion gives multiples of 1/p), the record's whole when
  // there is none: a window of part of a period would count that part's events once too few or many.
  const int counted = least.period > 0 ? o.recorded_periods / least.period * least.period : o.recorded_periods;
  const PerPeriod per_period = CountPerPeriod(r, counted, period);
  motion.stops_per_period = per_period.stops;
  motion.sticks_per_period = per_period.sticks;
  return motion;
}

}  // namespace stickslip
