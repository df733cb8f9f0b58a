// Event-driven simulation of an oscillator with a Coulomb contact (Pascal 2014, eqs. 2-4, 11, for
// the paper's model): the result types shared by every simulator and every model
// (oscillator_model.hpp), and the paper's model's entry to the exact simulator
// (exact_simulator.hpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "stickslip/model/oscillator_model.hpp"
#include "stickslip/model/pascal_2014/flows.hpp"
#include "stickslip/model/pascal_2014/parameters.hpp"
#include "stickslip/model/pascal_2014.hpp"
#include "stickslip/numerics/sinusoid_sum.hpp"
#include "stickslip/progress.hpp"

namespace stickslip {

// A stop is x2' reaching zero in a slip; a stick exit is |s| reaching eta u_r in a stick.
enum class EventKind { kStop, kStickExit };
const char* ToString(EventKind kind);  // "stop", "stick-exit"

// Why a segment ended: at an event, or at the end of the simulated interval.
enum class SegmentEnd { kStop, kStickExit, kHorizon };
const char* ToString(SegmentEnd end);  // "stop", "stick-exit", "horizon"

// One interval of motion in a single mode. Times are absolute (forcing cos(omega t + phi)).
template <typename StateType>
struct BasicSegment {
  Mode mode = Mode::kStick;
  double t_start = 0.0;
  double t_end = 0.0;
  StateType start = FixedSizeDefault<StateType>();
  StateType end = FixedSizeDefault<StateType>();
  SegmentEnd end_reason = SegmentEnd::kHorizon;
};

// A switching event between two segments. At a stop, mode_after tells the outcome: the reverse
// slip (a normal stop), a stick, or the same slip (an abnormal stop, x2' = x2'' = 0, which needs
// u_r = u_s: ERRATA).
template <typename StateType>
struct BasicEvent {
  double t = 0.0;
  EventKind kind = EventKind::kStop;
  Mode mode_before = Mode::kStick;
  Mode mode_after = Mode::kStick;
  StateType state = FixedSizeDefault<StateType>();
  bool IsAbnormalStop() const { return kind == EventKind::kStop && mode_before == mode_after; }
};

template <typename StateType>
struct BasicTimeSample {
  double t = 0.0;
  StateType state = FixedSizeDefault<StateType>();
};

template <typename StateType>
struct BasicSimulationOptions {
  double duration = 0.0;      // simulated time from t = 0, > 0
  double sample_step = 0.0;   // > 0: also record the state every sample_step (for CSV output)
  // A guard against chattering (infinitely many events in finite time) and a bound on the memory
  // of the stored events and segments (about 150 bytes each); reaching it ends the simulation
  // with SimulationEnd::kMaxEvents and a message naming it.
  int max_events = 1000000;
  ZeroSearchOptions zeros;    // event location accuracy (time tolerance 1e-13)
  // Called after every event with done = the time simulated and total = duration, both in
  // forcing periods 2 pi/omega (unit "periods"). Empty: no reports.
  ProgressCallback progress = {};
  // When set, every sample goes to it in time order, with the mode of the segment that holds it
  // (at an event, the segment that ends there), instead of into SimulationResult::samples: a long,
  // finely sampled simulation is then streamed rather than held in memory.
  std::function<void(const BasicTimeSample<StateType>&, Mode)> on_sample;

  // The samples, one rule for every simulator: sample k (0 <= k < SampleCount()) lies at
  // k sample_step, computed from k and never by adding steps, the last clipped to the duration.
  // The count allows for rounding in duration / sample_step: 3 periods at 1000 samples a period
  // give 3001 samples even where the quotient comes out as 2999.9999999999995.
  long SampleCount() const {
    if (!(sample_step > 0.0)) return 0;
    return static_cast<long>(std::floor(duration / sample_step * (1.0 + 1e-12))) + 1;
  }
  double SampleTime(long k) const { return std::min(static_cast<double>(k) * sample_step, duration); }
};

// options.progress, if any, at time t of a simulation whose forcing has the given period (both
// simulators report this way).
template <typename StateType>
void ReportSimulated(const BasicSimulationOptions<StateType>& options, double forcing_period, double t) {
  if (!options.progress) return;
  options.progress({t / forcing_period, options.duration / forcing_period, "periods"});
}

// How a simulation ended: a numerical outcome, not an error (bad input throws InvalidInput).
enum class SimulationEnd {
  kDuration,     // the whole duration was simulated
  kMaxEvents,    // options.max_events stopped it (chattering, or a duration too long)
  kStuckAtRest,  // Odeint only: a slip chosen from rest does not move in its direction
  kSearchLimit,  // exact only: the search for an event reached options.zeros.max_intervals
};
const char* ToString(SimulationEnd end);  // "duration", "max-events", "stuck-at-rest", "search-limit"

// A simulation of a model (oscillator_model.hpp).
template <typename Model>
struct BasicSimulationResult {
  using State = typename Model::State;
  typename Model::Parameters parameters;
  double phi = 0.0;  // forcing phase at t = 0
  std::vector<BasicSegment<State>> segments;
  std::vector<BasicEvent<State>> events;
  std::vector<BasicTimeSample<State>> samples;  // filled when sample_step > 0
  SimulationEnd end = SimulationEnd::kDuration;
  std::string message;  // why it stopped early, if it did
  bool Completed() const { return end == SimulationEnd::kDuration; }
};

// The paper's model, as every layer above uses it today.
using Segment = BasicSegment<State>;
using Event = BasicEvent<State>;
using TimeSample = BasicTimeSample<State>;
using SimulationOptions = BasicSimulationOptions<State>;
using SimulationResult = BasicSimulationResult<Pascal2014>;

// Initial mode from a state: the sign of x2', or Coulomb's law at rest when x2' = 0 (to
// rounding: |x2'| <= 1e-12 (1 + |(x1, x2, x1')|)).
Mode InitialMode(const State& x0, double phi, const Parameters& p);

// The exact event-driven simulator (exact_simulator.hpp) for the paper's model. Every stop and
// stick exit is located to options.zeros.time_tolerance by bracketing root finding on the closed
// form; no event between two samples can be missed (zeros are excluded only by a bound on |f''|,
// see sinusoid_sum.hpp). Preconditions: Validate(p) passed, x0 finite, duration > 0.
SimulationResult SimulateExact(const Parameters& p, const State& x0, double phi,
                               const SimulationOptions& options);

// The state at time t (t_start <= t <= t_end of a segment of `result`) from the closed form.
State StateAt(const SimulationResult& result, double t);

}  // namespace stickslip
