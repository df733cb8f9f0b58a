// Event-driven simulation of the nonsmooth oscillator under Coulomb's law (Pascal 2014,
// eqs. 2-4, 11): the result types shared by every simulator, and the exact simulator that
// advances the closed-form flows (flows.hpp) from event to event.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "stickslip/model/flows.hpp"
#include "stickslip/model/parameters.hpp"
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
struct Segment {
  Mode mode = Mode::kStick;
  double t_start = 0.0;
  double t_end = 0.0;
  State start = State::Zero();
  State end = State::Zero();
  SegmentEnd end_reason = SegmentEnd::kHorizon;
};

// A switching event between two segments. At a stop, mode_after tells the outcome: the reverse
// slip (a normal stop), a stick, or the same slip (an abnormal stop, x2' = x2'' = 0, which needs
// u_r = u_s: ERRATA).
struct Event {
  double t = 0.0;
  EventKind kind = EventKind::kStop;
  Mode mode_before = Mode::kStick;
  Mode mode_after = Mode::kStick;
  State state = State::Zero();
  bool IsAbnormalStop() const { return kind == EventKind::kStop && mode_before == mode_after; }
};

struct TimeSample {
  double t = 0.0;
  State state = State::Zero();
};

struct SimulationOptions {
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
  std::function<void(const TimeSample&, Mode)> on_sample;
};

// options.progress, if any, at time t of a simulation of p (both simulators report this way).
void ReportSimulated(const SimulationOptions& options, const Parameters& p, double t);

// How a simulation ended: a numerical outcome, not an error (bad input throws InvalidInput).
enum class SimulationEnd {
  kDuration,     // the whole duration was simulated
  kMaxEvents,    // options.max_events stopped it (chattering, or a duration too long)
  kStuckAtRest,  // Odeint only: a slip chosen from rest does not move in its direction
  kSearchLimit,  // exact only: the search for an event reached options.zeros.max_intervals
};
const char* ToString(SimulationEnd end);  // "duration", "max-events", "stuck-at-rest", "search-limit"

struct SimulationResult {
  Parameters parameters;
  double phi = 0.0;  // forcing phase at t = 0
  std::vector<Segment> segments;
  std::vector<Event> events;
  std::vector<TimeSample> samples;  // filled when sample_step > 0
  SimulationEnd end = SimulationEnd::kDuration;
  std::string message;  // why it stopped early, if it did
  bool Completed() const { return end == SimulationEnd::kDuration; }
};

// Initial mode from a state: the sign of x2', or Coulomb's law at rest when x2' = 0 (to
// rounding: |x2'| <= 1e-12 (1 + |(x1, x2, x1')|)).
Mode InitialMode(const State& x0, double phi, const Parameters& p);

// The exact event-driven simulator. Every stop and stick exit is located to
// options.zeros.time_tolerance by bracketing root finding on the closed form; no event between
// two samples can be missed (zeros are excluded only by a bound on |f''|, see
// sinusoid_sum.hpp). Preconditions: Validate(p) passed, x0 finite, duration > 0.
SimulationResult SimulateExact(const Parameters& p, const State& x0, double phi,
                               const SimulationOptions& options);

// The state at time t (t_start <= t <= t_end of a segment of `result`) from the closed form.
State StateAt(const SimulationResult& result, double t);

}  // namespace stickslip
