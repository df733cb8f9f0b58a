// The periodic orbit a motion settles on, for any model (model/oscillator_model.hpp), as a guess
// for the periodicity equations: the motion simulated exactly from a start state for a given time,
// then its last whole period read from a stop (an orbit's origin is a stop). A forced model's
// period is the least k 2 pi/omega, k = 1 to max_multiple, that is one (a motion that has not
// settled, or a subharmonic of a higher order, is then no orbit); an autonomous one's (a mass on a belt, no forcing)
// is the time between its last two stick entries, its self-excited stick-slip cycle. An orbit
// whose second half mirrors its first (antisymmetric, to 1e-6 of the period, on a fixed surface) is
// written over its half, whose symmetric segments then vanish together as one. The period must be one: a segment
// begins one period after the stop it is read from, in the state that stop had (to 1e-6 of its size), within the
// last two periods of the simulation, with at most 100 segments; else the guess is none, and the
// message says why (a permanent stick, a steady slip, a motion not settled).
//
//   const SettledOrbitGuess<Model> g = SettledOrbitGuessOf(model, p, x0, 300 * T, 10 * T);  // T = 2 pi/omega
//   if (g.orbit) solve(*g.orbit); else report(g.message);
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/model/exact_simulator.hpp"
#include "stickslip/model/oscillator_model.hpp"
#include "stickslip/orbits/orbit.hpp"
#include "stickslip/progress.hpp"

namespace stickslip {

template <OscillatorModel Model>
struct SettledOrbitGuess {
  std::optional<BasicOrbit<Model>> orbit;
  std::string message;  // why there is none: the simulation stopped early, too few stops or sticks
};

namespace settled_orbit_detail {

// A period read off a motion has at most this many segments (more: the motion has not settled, or
// chatters).
inline constexpr std::size_t kMaxSegments = 100;

// The first segment of the last whole period, for a period `period` > 0, or of the last cycle
// between two stick entries (period 0); segments.size() where there is none.
template <typename Segments>
std::size_t LastPeriodStart(const Segments& segments, double duration, double period) {
  std::vector<std::size_t> entries;  // segments that begin at a stop
  for (std::size_t k = 1; k < segments.size(); ++k) {
    const bool at_stop = segments[k - 1].end_reason == SegmentEnd::kStop;
    if (at_stop && (period > 0.0 ? segments[k].t_start <= duration - period : segments[k].mode == Mode::kStick)) {
      entries.push_back(k);
    }
  }
  if (period > 0.0) return entries.empty() ? segments.size() : entries.back();
  return entries.size() < 2 ? segments.size() : entries[entries.size() - 2];
}

// Why the segments from `first` over `period` are no period of a settled motion, or "".
template <typename Segments>
std::string NotSettled(const Segments& segments, std::size_t first, double period, double duration) {
  const double t0 = segments[first].t_start, tolerance = 1e-6 * period;
  if (t0 < duration - 2.0 * period) {
    return fmt::format("no stop in the last period (the last at t = {:.6g} of {:.6g}): the motion never stops (a steady "
                       "slip) or has not settled",
                       t0, duration);
  }
  std::size_t end = first;
  while (end < segments.size() && segments[end].t_start < t0 + period - tolerance) ++end;
  if (end - first > kMaxSegments) {
    return fmt::format("{} segments in a period (at most {} are read): the motion has not settled, chatters, or is of "
                       "a type too long to solve",
                       end - first, kMaxSegments);
  }
  // Back where it started: a segment begins one period on, in the state it began.
  if (end == segments.size() || std::abs(segments[end].t_start - (t0 + period)) > tolerance) {
    return "no segment begins one period after the stop the period is read from: the motion has not settled";
  }
  const auto& x0 = segments[first].start;
  const double mismatch = (segments[end].start - x0).template lpNorm<Eigen::Infinity>();
  // Relative to the state's size: a model in other units (forces of micronewtons) is judged alike.
  if (!(mismatch <= 1e-6 * std::max(x0.template lpNorm<Eigen::Infinity>(), std::numeric_limits<double>::min()))) {
    return fmt::format("the state one period on differs by {:.3g} from the start: the motion has not settled (simulate "
                       "longer) or is not of this period",
                       mismatch);
  }
  return "";
}

// The surface's speed (a belt's), 0 for a model whose surface is fixed.
template <OscillatorModel Model>
double RestVelocity(const Model&, const typename Model::Parameters& p) {
  if constexpr (Model::kRestVelocityParameter >= 0) return Model::ParameterAt(p, Model::kRestVelocityParameter);
  return 0.0;
}

}  // namespace settled_orbit_detail

namespace settled_orbit_detail {

// The last `record` of a simulation of `duration` from x0 (times from its start, `phi0` the phase
// there), the time before it in chunks of `record` that keep only their end state, so that memory
// and any one simulation's events stay bounded by the record's; and whether the contact never left
// the stick it began in (each chunk one stick).
template <OscillatorModel Model>
struct Record {
  BasicSimulationResult<Model> result;
  double phi0 = 0.0;
  bool stuck_throughout = false;
};
template <OscillatorModel Model>
Record<Model> SimulateRecord(const Model& model, const typename Model::Parameters& p, const typename Model::State& x0,
                             double duration, double record, double phi0, const ProgressCallback& progress) {
  const double omega = model.ForcingFrequency(p);
  const double unit = 2.0 * std::numbers::pi / omega;  // progress counts forcing periods
  BasicSimulationOptions<typename Model::State> options;
  typename Model::State x = x0;
  double t = 0.0;
  const auto simulate = [&](double length) {
    options.duration = length;
    if (progress) {
      options.progress = [&, offset = t / unit](const Progress& within) {
        progress({offset + within.done, duration / unit, "periods"});
      };
    }
    return SimulateExact(model, p, x, phi0 + omega * t, options);
  };
  const auto one_stick = [](const BasicSimulationResult<Model>& r) {
    return r.segments.size() == 1 && r.segments.front().mode == Mode::kStick;
  };
  bool stuck = true;
  // Bounded: at most duration / record chunks.
  for (double transient = duration - record; t < transient;) {
    const double length = std::min(record, transient - t);
    BasicSimulationResult<Model> chunk = simulate(length);
    if (!chunk.Completed() || chunk.segments.empty()) return {std::move(chunk), 0.0, false};
    stuck = stuck && one_stick(chunk);
    x = chunk.segments.back().end;
    t = length >= transient - t ? transient : t + length;
  }
  BasicSimulationResult<Model> last = simulate(record);
  stuck = stuck && one_stick(last);
  return {std::move(last), phi0 + omega * t, stuck};
}

// The orbit over `period` from segment `first` (a settled period, NotSettled), written over its half
// where its second half mirrors its first (on a fixed surface only: the mirror of a stick on a moving
// one moves the other way).
template <OscillatorModel Model>
SettledOrbitGuess<Model> OrbitOverPeriod(const Model& model, const typename Model::Parameters& p,
                                         const BasicSimulationResult<Model>& r, std::size_t first, double period,
                                         double phi0, int multiple) {
  const auto& segments = r.segments;
  const bool forced = !model.Autonomous();
  const double t0 = segments[first].t_start;
  std::vector<Mode> modes;
  std::vector<double> durations;
  for (std::size_t k = first; k < segments.size() && segments[k].t_start < t0 + (1.0 - 1e-6) * period; ++k) {
    modes.push_back(segments[k].mode);
    durations.push_back(std::min(segments[k].t_end, t0 + period) - segments[k].t_start);
  }
  const std::size_t half = modes.size() / 2;
  // Half an odd number of forcing periods flips the forcing's sign, as the mirror needs.
  bool antisymmetric = forced && multiple % 2 == 1 && modes.size() % 2 == 0 && RestVelocity(model, p) == 0.0;
  for (std::size_t k = 0; antisymmetric && k < half; ++k) {
    antisymmetric = modes[k + half] == Mirror(modes[k]) && std::abs(durations[k + half] - durations[k]) <= 1e-6 * period;
  }
  if (antisymmetric) {
    modes.resize(half);
    durations.resize(half);
  }
  try {
    const double phi = forced ? std::remainder(model.ForcingFrequency(p) * t0 + phi0, 2.0 * std::numbers::pi) : 0.0;
    return {BasicOrbit<Model>{Signature(modes, antisymmetric, multiple), p, segments[first].start, phi, durations}, ""};
  } catch (const InvalidInput& e) {  // a sequence no orbit type has (two sticks in a row)
    return {std::nullopt, std::string("the motion's period is no orbit type: ") + e.what()};
  }
}

// The orbit of a forced model over the least k <= max_multiple forcing periods that is a period of the
// motion's end (a subharmonic of order k: NotSettled finds none shorter), or why there is none (the
// reason for k = 1, the forcing's own period).
template <OscillatorModel Model>
SettledOrbitGuess<Model> ForcedOrbitGuess(const Model& model, const typename Model::Parameters& p,
                                          const BasicSimulationResult<Model>& r, double record, double phi0,
                                          int max_multiple) {
  const double forcing_period = 2.0 * std::numbers::pi / model.ForcingFrequency(p);
  std::string why;
  for (int k = 1; k <= max_multiple; ++k) {
    const double period = k * forcing_period;
    const std::size_t first = LastPeriodStart(r.segments, record, period);
    std::string reason = first == r.segments.size()
                             ? "no stop in the last forcing period: the motion never stops (a steady slip) or has not settled"
                             : NotSettled(r.segments, first, period, record);
    if (reason.empty()) return OrbitOverPeriod(model, p, r, first, period, phi0, k);
    if (k == 1) why = std::move(reason);
    if (first == r.segments.size()) break;  // no stop a longer period before the end either
  }
  if (max_multiple > 1) why += fmt::format(" (nor is any k <= {} forcing periods a period of it)", max_multiple);
  return {std::nullopt, std::move(why)};
}

}  // namespace settled_orbit_detail

// Simulates `duration` (in the model's time, > 0) from x0 at phase phi0, and reads the period off
// the last `record` of it (0 < record <= duration; it must hold two periods; SimulateRecord): for a
// forced model the least of 1 to max_multiple forcing periods that is one (a subharmonic beyond the
// first). `progress` reports the whole simulation (simulation.hpp).
template <OscillatorModel Model>
SettledOrbitGuess<Model> SettledOrbitGuessOf(const Model& model, const typename Model::Parameters& p,
                                             const typename Model::State& x0, double duration, double record,
                                             double phi0 = 0.0, const ProgressCallback& progress = {},
                                             int max_multiple = 1) {
  using namespace settled_orbit_detail;
  record = std::min(record, duration);
  const Record<Model> recorded = SimulateRecord(model, p, x0, duration, record, phi0, progress);
  const BasicSimulationResult<Model>& r = recorded.result;
  if (!r.Completed() || r.segments.empty()) return {std::nullopt, "the simulation stopped early: " + r.message};
  const auto& segments = r.segments;
  if (recorded.stuck_throughout) {
    return {std::nullopt, fmt::format("the contact never left the stick it began in, over the whole simulation ({:.6g} "
                                      "{}): the friction force it needs stayed below the static level (a permanent "
                                      "stick: no orbit type); a larger forcing, a smaller static level or another "
                                      "start sets it moving",
                                      model.Autonomous() ? duration : duration * model.ForcingFrequency(p) / (2.0 * std::numbers::pi),
                                      model.Autonomous() ? model.Description().units.time : "forcing periods")};
  }
  if (segments.back().mode == Mode::kStick && segments.back().t_start <= record / 2) {
    return {std::nullopt, fmt::format("the contact stays stuck over the last {:.6g} of the {:.6g} read: a permanent "
                                      "stick (no orbit type), or a stick longer than that (simulate longer)",
                                      record - segments.back().t_start, record)};
  }
  if (!model.Autonomous()) return ForcedOrbitGuess(model, p, r, record, recorded.phi0, max_multiple);
  const std::size_t first = LastPeriodStart(segments, record, 0.0);
  if (first == segments.size()) {
    return {std::nullopt, "fewer than two sticks in the time read: the motion does not stick periodically (a steady "
                          "slip, or nothing moves), or its stick-slip cycle is longer (simulate longer)"};
  }
  double period = 0.0;
  for (std::size_t k = first + 1; k < segments.size() && period == 0.0; ++k) {
    if (segments[k].mode == Mode::kStick && segments[k - 1].end_reason == SegmentEnd::kStop) {
      period = segments[k].t_start - segments[first].t_start;
    }
  }
  if (std::string why = NotSettled(segments, first, period, record); !why.empty()) return {std::nullopt, std::move(why)};
  return OrbitOverPeriod(model, p, r, first, period, recorded.phi0, 1);
}

}  // namespace stickslip
