// Independent verification of a computed orbit: one period simulated from its initial state by
// the exact simulator and by the Boost.Odeint simulator. The event sequence must equal the
// signature, the state must come back, and the events must fall where the orbit says. For any
// model (model/oscillator_model.hpp); the simulators are the caller's, so that this header does
// not carry the integrator.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "stickslip/model/mode.hpp"
#include "stickslip/model/simulation.hpp"
#include "stickslip/orbits/any_orbit.hpp"
#include "stickslip/orbits/orbit.hpp"
#include "stickslip/orbits/segment_walk.hpp"

namespace stickslip {

// Odeint locates events by sign changes and cannot see an abnormal stop (a tangency of x2' to
// zero); its sequence is compared with consecutive equal modes merged.
struct SimulatorCheck {
  std::vector<Mode> modes;               // segment modes the simulation went through
  bool sequence_matches = false;         // == the signature over a whole period
  double periodicity_mismatch = 0.0;     // max |X(T) - X(0)|
  double max_event_time_difference = 0.0;  // against the orbit's segment ends (when matching)
};

struct Verification {
  std::vector<Mode> expected;  // the signature over a whole period
  // Why the orbit could not be simulated (parameters outside the physical range, say u_s <= 0
  // where Newton converged past the family's end, or a simulation that stopped early); empty
  // when both simulators ran over the whole period.
  std::string not_simulated;
  SimulatorCheck exact;
  SimulatorCheck odeint;
  // Thresholds: the exact flows carry rounding only; Odeint integrates at 1e-12 tolerances.
  static constexpr double kExactTolerance = 1e-9;
  static constexpr double kOdeintTolerance = 1e-6;
  // The orbit's size the mismatches are judged against, in the model's units (OrbitSize): the
  // thresholds are the tolerances times it. 1 for the paper's scaled model: absolute.
  double scale = 1.0;
  bool Passed() const;
  std::string Report() const;  // one line per simulator, or why there was no simulation
};

// Consecutive equal modes merged: the sequence as a simulator that sees only crossings of the
// contact's rest reports it (an abnormal stop is a tangency, invisible to sign changes).
std::vector<Mode> MergedModes(const std::vector<Mode>& modes);

// One simulated period `r` against the orbit's `expected` modes over the period, its `event_times`
// and its `start`.
template <typename Model>
SimulatorCheck CheckSimulation(const BasicSimulationResult<Model>& r, double period, const typename Model::State& start,
                               std::vector<Mode> expected, std::vector<double> event_times, bool sees_tangencies) {
  if (!sees_tangencies) {
    std::vector<double> crossing_times;
    for (std::size_t i = 0; i + 1 < expected.size(); ++i) {
      if (expected[i] != expected[i + 1]) crossing_times.push_back(event_times[i]);
    }
    event_times = crossing_times;
    expected = MergedModes(expected);
  }
  SimulatorCheck check;
  // A stop that falls a rounding error before the period's end opens a last sliver of segment;
  // it belongs to the next period.
  for (const auto& s : r.segments) {
    if (s.t_start < period - 1e-7) check.modes.push_back(s.mode);
  }
  if (!sees_tangencies) check.modes = MergedModes(check.modes);
  check.sequence_matches = check.modes == expected;
  const auto& last = r.segments.back();
  typename Model::State end = last.end;
  if (last.t_start >= period - 1e-7 && r.segments.size() > 1) end = r.segments[r.segments.size() - 2].end;
  check.periodicity_mismatch = (end - start).template lpNorm<Eigen::Infinity>();
  if (check.sequence_matches) {
    std::size_t k = 0;
    for (const auto& e : r.events) {
      if (k + 1 >= expected.size() || k >= event_times.size()) break;
      if (!sees_tangencies && e.IsAbnormalStop()) continue;
      check.max_event_time_difference = std::max(check.max_event_time_difference, std::abs(e.t - event_times[k++]));
    }
  }
  return check;
}

// The largest |component| of the state at the orbit's segment ends over its whole period: its size
// in the model's units (metres and metres per second of a user's [model], whose forces may be
// micronewtons or meganewtons), 1 where that is not a positive finite number.
template <OscillatorModel Model>
double OrbitSize(const Model& model, const BasicOrbit<Model>& orbit) {
  double size = 0.0;
  WalkSegments(model, orbit, Extent::kFullPeriod, PhaseRule::kAccumulated, [&](const SegmentVisit<double, Model>& s) {
    size = std::max(size, s.end.template lpNorm<Eigen::Infinity>());
  });
  return std::isfinite(size) && size > 0.0 ? size : 1.0;
}

// The verification of an orbit of any model by two simulators of one period from its start, each
// called as simulate(model, parameters, start, phi, options): `exact` follows the model's closed
// forms and sees tangencies; `integrated` integrates its equations of motion (model/odeint_simulation.hpp)
// and sees sign changes only.
template <typename Model, typename Exact, typename Integrated>
Verification VerifyOrbit(const Model& model, const BasicOrbit<Model>& orbit, Exact&& exact, Integrated&& integrated) {
  Verification v;
  // The full period: the listed segments, mirrored when antisymmetric.
  v.expected = orbit.signature.FullPeriod();
  std::vector<double> event_times;
  WalkSegments(model, orbit, Extent::kFullPeriod, PhaseRule::kAccumulated,
               [&](const SegmentVisit<double, Model>& s) { event_times.push_back(s.t0 + s.duration); });
  if (const auto invalid = model.Validate(orbit.parameters)) {
    v.not_simulated = fmt::format("the orbit is not a motion of the system: {}", invalid->what());
    return v;
  }
  const double period = PeriodOf(model, orbit);  // an autonomous orbit's: its durations
  BasicSimulationOptions<typename Model::State> options;
  options.duration = period;
  const BasicSimulationResult<Model> by_exact = exact(model, orbit.parameters, orbit.start, orbit.phi, options);
  const BasicSimulationResult<Model> by_odeint = integrated(model, orbit.parameters, orbit.start, orbit.phi, options);
  for (const auto& [name, r] : {std::pair{"exact", &by_exact}, std::pair{"odeint", &by_odeint}}) {
    if (!r->Completed() || r->segments.empty()) {
      v.not_simulated = fmt::format("the {} simulation stopped early: {}", name, r->message);
      return v;
    }
  }
  v.exact = CheckSimulation<Model>(by_exact, period, orbit.start, v.expected, event_times, /*sees_tangencies=*/true);
  v.odeint = CheckSimulation<Model>(by_odeint, period, orbit.start, v.expected, event_times, /*sees_tangencies=*/false);
  return v;
}

// The paper's model, by its exact and Odeint simulators.
Verification VerifyOrbit(const Orbit& orbit);

}  // namespace stickslip
