#include "stickslip/analysis/settled_motion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <numbers>
#include <optional>
#include <vector>

#include "stickslip/invalid_input.hpp"
#include "stickslip/model/exact_simulator.hpp"
#include "stickslip/model/linear_oscillator.hpp"
#include "stickslip/model/transient.hpp"
#include "stickslip/orbits/orbit_measures.hpp"

namespace stickslip {

namespace {

// max |q_c| of the contact's coordinate c over the simulated segments of `r`: at each segment's
// ends, and inside a slip also at the extrema of its closed form (MinimumAndMaximum: the zeros of
// q_c'); NaN if a search was cut short.
template <OscillatorModel Model>
double ContactAmplitude(const Model& model, const BasicSimulationResult<Model>& r) {
  const typename Model::Parameters& p = r.parameters;
  const int c = ContactCoordinate(model);
  const double omega = model.ForcingFrequency(p);
  double amplitude = 0.0;
  for (const auto& s : r.segments) {
    double low = std::min(s.start(c), s.end(c)), high = std::max(s.start(c), s.end(c));
    if (s.mode != Mode::kStick) {
      const typename Model::Motion motion = model.MotionInMode(s.mode, s.start, omega * s.t_start + r.phi, p);
      const Extrema e = MinimumAndMaximum(model.CoordinateAlong(motion, c), 0.0, s.t_end - s.t_start);
      if (std::isnan(e.minimum.value) || std::isnan(e.maximum.value)) return std::numeric_limits<double>::quiet_NaN();
      low = std::min(low, e.minimum.value);
      high = std::max(high, e.maximum.value);
    }
    amplitude = std::max({amplitude, high, -low});
  }
  return amplitude;
}

// The smallest p <= n/2 with section[k + p] == section[k] (to tolerance, absolute) for every k; 0 if none.
template <typename StateVector>
int RepeatingPeriod(const std::vector<StateVector>& section, double tolerance) {
  const int n = static_cast<int>(section.size());
  for (int candidate = 1; candidate <= n / 2; ++candidate) {
    bool repeats = true;
    for (int k = 0; k + candidate < n && repeats; ++k) {
      repeats = (section[k + candidate] - section[k]).template lpNorm<Eigen::Infinity>() <= tolerance;
    }
    if (repeats) return candidate;
  }
  return 0;
}

// max |section[k + step] - section[k]|_inf over k = from .. from + count - 1.
template <typename StateVector>
double StepMismatch(const std::vector<StateVector>& section, int step, int from, int count) {
  double mismatch = 0.0;
  for (int k = from; k < from + count; ++k) {
    mismatch = std::max(mismatch, (section[k + step] - section[k]).template lpNorm<Eigen::Infinity>());
  }
  return mismatch;
}

// The distance still to go after steps that shrink geometrically from `early` to `late` (each the
// sum of `window` steps; q = (late/early)^exponent the rate per step): the tail
// (late/window)(1 + q + q^2 ...); infinite where they do not shrink.
double GeometricTail(double early, double late, double exponent, int window) {
  if (!(late < early)) return std::numeric_limits<double>::infinity();
  const double rate = std::pow(late / early, exponent);
  return late / window / (1.0 - rate);
}

// How far a section that repeats after p periods to tolerance may still be from a motion of period
// d (d divides p) that it contracts onto; nullopt when it shows no such contraction. A motion that
// contracts slowly onto a period-d orbit whose multiplier is near a (p/d)-th root of unity returns
// nearer after p periods than after d: the p-step test passes first. Then the p-step differences
// shrink by a rate q per p periods (measured over the record: the first p of them against the
// last p), the distance still to go is at most late/(1 - q) (a geometric tail), and the d-step
// differences, shrinking too, are at most twice that distance. A motion of least period p has
// d-step differences that neither shrink nor fit that bound.
inline constexpr double kContractionShown = 0.99;
template <typename StateVector>
std::optional<double> ContractionOntoPeriod(const std::vector<StateVector>& section, int p, int d) {
  const int n = static_cast<int>(section.size());
  const int span = n - 2 * p;  // periods between the first and the last window of p-step differences
  if (span < p) return std::nullopt;
  const double early = StepMismatch(section, p, 0, p);
  const double late = StepMismatch(section, p, span, p);
  // A contraction shows: its p-step differences shrink by 1 % at least across the record. Steps
  // that hold their size (a motion worn down by a constant amount per cycle) are a drift.
  if (!(late <= kContractionShown * early)) return std::nullopt;
  const double remaining = GeometricTail(early, late, static_cast<double>(p) / span, 1);  // rate per p periods
  const double d_early = StepMismatch(section, d, 0, p);
  const double d_late = StepMismatch(section, d, n - p - d, p);
  if (!(d_late < d_early && d_late <= 2.0 * remaining)) return std::nullopt;
  return remaining;
}

struct LeastSectionPeriod {
  int period = 0;
  double settling = 0.0;
};


// How far a section that repeats after p periods step by step (every p-step difference within the
// tolerance) may still be from its period-p motion: 0 where no phase moves on across the record;
// where one does (two steps or more, its last point farther than the tolerance from its first and
// farther than half its path: one way, not circling an orbit), the geometric tail of its steps
// (its late half against its early half) where that is no more than the way it moved over the
// record; nullopt where it is more: a drift, not a settled motion. Steps below the tolerance add up:
// a large motion that friction wears down by a constant amount per cycle repeats step by step.
template <typename StateVector>
std::optional<double> SettlingOntoPeriod(const std::vector<StateVector>& section, int p, double tolerance) {
  const int n = static_cast<int>(section.size());
  const auto apart = [&section](int j, int k) { return (section[j] - section[k]).template lpNorm<Eigen::Infinity>(); };
  double settling = 0.0;
  for (int k = 0; k < p; ++k) {
    const int steps = (n - 1 - k) / p;
    if (steps < 2) continue;
    std::vector<double> step(steps);
    for (int i = 0; i < steps; ++i) step[i] = apart(k + (i + 1) * p, k + i * p);
    const double drift = apart(k + steps * p, k);
    const double path = std::accumulate(step.begin(), step.end(), 0.0);
    if (!(drift > tolerance && drift > 0.5 * path)) continue;
    const int half = steps / 2;
    const double early = std::accumulate(step.begin(), step.begin() + half, 0.0);
    const double late = std::accumulate(step.end() - half, step.end(), 0.0);
    const double tail = GeometricTail(early, late, 1.0 / (steps - half), half);
    if (!(tail <= drift)) return std::nullopt;
    settling = std::max(settling, tail);
  }
  return settling;
}

// The period on the section (RepeatingPeriod), reduced to the least divisor d that the section is
// contracting onto (ContractionOntoPeriod), with the distance still to go; where there is none, the
// distance still to go to the period itself (SettlingOntoPeriod), and 0 where the section drifts.
template <typename StateVector>
LeastSectionPeriod LeastPeriodOnSection(const std::vector<StateVector>& section, double tolerance) {
  const int p = RepeatingPeriod(section, tolerance);
  for (int d = 1; d < p; ++d) {
    if (p % d != 0) continue;
    if (const std::optional<double> remaining = ContractionOntoPeriod(section, p, d)) return {d, *remaining};
  }
  if (p == 0) return {0, 0.0};
  const std::optional<double> settling = SettlingOntoPeriod(section, p, tolerance);
  return settling ? LeastSectionPeriod{p, *settling} : LeastSectionPeriod{0, 0.0};
}

struct PerPeriod {
  double stops = 0.0;
  double sticks = 0.0;
};

// Stops and sticks per period over the `periods` periods from t0 to t1 of the record (the events
// are in time order).
template <typename Model>
PerPeriod CountPerPeriod(const BasicSimulationResult<Model>& r, int periods, double t0, double t1) {
  PerPeriod count;
  for (const auto& e : r.events) {
    if (e.t >= t1) break;
    if (e.t < t0) continue;
    count.stops += e.kind == EventKind::kStop;
    count.sticks += e.mode_after == Mode::kStick;
  }
  count.stops /= periods;
  count.sticks /= periods;
  return count;
}

// The segments of the record that are a stick begun at a stop (the stick-entry section of a model
// without forcing: their start states are at rest exactly), at most `count`.
template <typename Model>
std::vector<std::size_t> StickEntries(const BasicSimulationResult<Model>& r, std::size_t count) {
  std::vector<std::size_t> entries;
  for (std::size_t k = 1; k < r.segments.size() && entries.size() < count; ++k) {
    if (r.segments[k].mode == Mode::kStick && r.segments[k - 1].end_reason == SegmentEnd::kStop) entries.push_back(k);
  }
  return entries;
}

// The state at time t (t_start <= t <= t_end of a segment of `r`) from the closed form.
template <OscillatorModel Model>
typename Model::State StateAtTime(const Model& model, const BasicSimulationResult<Model>& r, double t) {
  const auto it = std::lower_bound(r.segments.begin(), r.segments.end(), t,
                                   [](const auto& s, double time) { return s.t_end < time; });
  const auto& s = it == r.segments.end() ? r.segments.back() : *it;
  return model.Flow(s.mode, s.start, model.ForcingFrequency(r.parameters) * s.t_start + r.phi, t - s.t_start, r.parameters);
}

// The transient from `start` (its periods 2 pi/frequency), then the record of `duration` from its end:
// the motion with its record, or with where and why a simulation stopped early.
template <OscillatorModel Model>
BasicSettledMotion<Model> SimulateOut(const Model& model, const typename Model::Parameters& p,
                                      const typename Model::State& start, double phi_section, double frequency,
                                      double duration, const SettleOptions& o) {
  using ModelState = typename Model::State;
  BasicSettledMotion<Model> motion;
  // The transients in chunks (SimulateTransientAt), each a simulation under max_events_per_simulation,
  // so that the largest transients (1e6 periods, millions of events) run.
  BasicTransientOptions<ModelState> transient;
  transient.periods = o.transient_periods;
  transient.chunk_periods = o.chunk_periods;
  transient.simulation.max_events = o.max_events_per_simulation;
  const auto simulate = [&model](const typename Model::Parameters& q, const ModelState& x, double phi,
                                 const BasicSimulationOptions<ModelState>& so) { return SimulateExact(model, q, x, phi, so); };
  const BasicTransient<ModelState> settled =
      SimulateTransientAt(frequency, simulate, p, start, phi_section, transient);
  motion.last = settled.state;
  if (!settled.Completed()) {
    motion.end = settled.end;
    motion.message = settled.message;
    return motion;
  }
  BasicSimulationOptions<ModelState> record;
  record.duration = duration;
  record.max_events = o.max_events_per_simulation;
  motion.record = SimulateExact(model, p, settled.state, phi_section, record);
  const BasicSimulationResult<Model>& r = motion.record;
  if (!r.Completed()) {
    motion.end = r.end;
    motion.message = r.message;
    if (!r.segments.empty()) motion.last = r.segments.back().end;
  }
  return motion;
}

// The section's least period (to the tolerance, relative where asked to the motion's size: its
// section states' and the contact's excursion over the record, which a section at rest does not
// show) and the distance still to go.
template <typename StateVector>
LeastSectionPeriod PeriodOnSection(const std::vector<StateVector>& section, const SettleOptions& o, double excursion) {
  double scale = 1.0;
  if (o.relative_tolerance) {
    scale = std::isfinite(excursion) ? excursion : 0.0;
    for (const StateVector& x : section) scale = std::max(scale, x.template lpNorm<Eigen::Infinity>());
  }
  return LeastPeriodOnSection(section, o.periodicity_tolerance * scale);
}

// A model without forcing: the state at each stick entry (recorded_periods of them, in a record of
// recorded_periods kRecordUnitsPerEntry time units), its least period in stick-slip cycles; where
// the contact never sticks, the state every time unit (a steady slide repeats at once).
inline constexpr int kRecordUnitsPerEntry = 10;
template <OscillatorModel Model>
BasicSettledMotion<Model> WithStickEntrySection(const Model& model, double unit, const SettleOptions& o,
                                                BasicSettledMotion<Model> motion) {
  const BasicSimulationResult<Model>& r = motion.record;
  const std::vector<std::size_t> entries = StickEntries(r, static_cast<std::size_t>(o.recorded_periods) + 1);
  if (entries.size() < 2) {
    // No stick-slip cycle in the record: the state every time unit, and the stops and sticks per time
    // unit; a period only where nothing happens (a steady slide, or a contact stuck throughout).
    for (int k = 1; k <= o.recorded_periods; ++k) motion.section.push_back(StateAtTime(model, r, k * unit));
    const int units = o.recorded_periods * kRecordUnitsPerEntry;  // the whole record
    const PerPeriod per_unit = CountPerPeriod(r, units, 0.0, units * unit);
    motion.stops_per_period = per_unit.stops;
    motion.sticks_per_period = per_unit.sticks;
    motion.period = r.events.empty() ? PeriodOnSection(motion.section, o, motion.contact_amplitude).period : 0;
    motion.last = motion.section.back();
    return motion;
  }
  for (std::size_t k = 0; k + 1 < entries.size(); ++k) motion.section.push_back(r.segments[entries[k]].start);
  const LeastSectionPeriod least = PeriodOnSection(motion.section, o, motion.contact_amplitude);
  motion.period = least.period;
  motion.settling = least.settling;
  const int cycles = static_cast<int>(entries.size()) - 1;
  const int counted = least.period > 0 ? cycles / least.period * least.period : cycles;
  const PerPeriod per_cycle =
      CountPerPeriod(r, counted, r.segments[entries.front()].t_start, r.segments[entries[counted]].t_start);
  motion.stops_per_period = per_cycle.stops;
  motion.sticks_per_period = per_cycle.sticks;
  motion.last = motion.section.back();
  return motion;
}

}  // namespace

template <OscillatorModel Model>
BasicSettledMotion<Model> SimulateSettled(const Model& model, const typename Model::Parameters& p,
                                          const typename Model::State& start, double phi_section,
                                          const SettleOptions& o) {
  const bool forced = !model.Autonomous();
  if (!forced && !(o.time_unit > 0.0)) throw InvalidInput("time_unit", o.time_unit, "time_unit > 0 without forcing");
  const double frequency = forced ? model.ForcingFrequency(p) : 2.0 * std::numbers::pi / o.time_unit;
  const double period = forced ? 2.0 * std::numbers::pi / frequency : o.time_unit;
  BasicSettledMotion<Model> motion = SimulateOut(model, p, start, phi_section, frequency,
                                                 o.recorded_periods * period * (forced ? 1 : kRecordUnitsPerEntry), o);
  if (!motion.Completed()) return motion;
  const BasicSimulationResult<Model>& r = motion.record;
  motion.contact_amplitude = ContactAmplitude(model, r);
  if (!forced) {
    return WithStickEntrySection(model, period, o, std::move(motion));
  }
  for (int k = 1; k <= o.recorded_periods; ++k) motion.section.push_back(StateAtTime(model, r, k * period));
  motion.last = motion.section.back();
  const LeastSectionPeriod least = PeriodOnSection(motion.section, o, motion.contact_amplitude);
  motion.period = least.period;
  motion.settling = least.settling;
  // Over whole least periods (a period-p motion gives multiples of 1/p), the record's whole when
  // there is none: a window of part of a period would count that part's events once too few or many.
  const int counted = least.period > 0 ? o.recorded_periods / least.period * least.period : o.recorded_periods;
  const PerPeriod per_period = CountPerPeriod(r, counted, 0.0, counted * period);
  motion.stops_per_period = per_period.stops;
  motion.sticks_per_period = per_period.sticks;
  return motion;
}

template BasicSettledMotion<Pascal2014> SimulateSettled(const Pascal2014&, const Parameters&, const State&, double,
                                                         const SettleOptions&);
template BasicSettledMotion<DynamicLinearOscillator> SimulateSettled(const DynamicLinearOscillator&,
                                                                     const DynamicLinearOscillator::Parameters&,
                                                                     const DynamicLinearOscillator::State&, double,
                                                                     const SettleOptions&);

SettledMotion SimulateSettled(const Parameters& p, const State& start, double phi_section, const SettleOptions& o) {
  return SimulateSettled(Pascal2014{}, p, start, phi_section, o);
}

}  // namespace stickslip
