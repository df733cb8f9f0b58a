// Brute-force bifurcation diagram: a parameter stepped over a range, transients simulated out
// with the exact simulator, and the stroboscopic section (the state at the forcing phase
// phi_section, once per forcing period) recorded, from one or several starting states (chains).
// For the paper's model and for a forced model of the user's (DynamicLinearOscillator): the points
// hold their states as vectors of the model's size, so that one CSV writer and every front end
// take any model's sweep.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "stickslip/model/model_description.hpp"
#include "stickslip/model/oscillator_model.hpp"
#include "stickslip/model/pascal_2014.hpp"
#include "stickslip/model/pascal_2014/flows.hpp"
#include "stickslip/model/pascal_2014/parameters.hpp"
#include "stickslip/progress.hpp"

namespace stickslip {

// How each point of a chain starts.
enum class SweepStart {
  // Up from `from` to `to` and then back down, each point from the last state of the one
  // before (the down pass from where the up pass ended): the attractor followed as the
  // parameter moves, so hysteresis and coexisting motions show. `to` is simulated twice, last
  // of the up pass and first of the down pass (from the up pass's end): the two agree once the
  // motion has settled. Chains run in parallel.
  kChained,
  // Every point from its chain's starting state, in one pass: no memory between points, so
  // every (chain, point) runs in parallel.
  kFixed,
};

struct SweepOptions {
  // The swept parameter: its index in the model's description (ModelDescription::parameters; the
  // paper's model's in ParameterId's order), or kForcingFrequency.
  static constexpr int kForcingFrequency = -1;
  int parameter = kForcingFrequency;
  double from = 0.0;           // first value of the up (or only) pass
  double to = 0.0;             // last value of the up (or only) pass
  int steps = 40;              // intervals between from and to (>= 1)
  // Forcing periods simulated and discarded at each point (0 to kMaxTransientPeriods), in chunks
  // (SimulateTransient, model/transient.hpp), each a simulation of its own from the last one's end.
  int transient_periods = 500;
  int recorded_periods = 20;    // forcing periods recorded at each point (>= 1)
  double periodicity_tolerance = 1e-6;  // section points this close repeat
  // ... times the largest |component| of a point's section states (a model in physical units), else
  // absolutely (the paper's scaled model).
  bool relative_tolerance = false;
  int chunk_periods = 1000;  // forcing periods per transient chunk (SettleOptions)
  // A model without forcing: the time counted as a period (SettleOptions::time_unit, > 0); its
  // points are read on their stick-entry section.
  double time_unit = 0.0;
  SweepStart start = SweepStart::kChained;
  // The simulator's guard against chattering, per simulation (per transient chunk); reaching it fails the sweep with
  // an error naming the point, rather than recording a motion cut short.
  int max_events_per_simulation = 1000000;
  // A simulation that stops early (that guard, or the event search's bound on a motion that grows
  // without bound): false, the sweep throws naming the point; true, the point is recorded with its
  // message (SweepPoint::incomplete), its section the state it started from, and a chained pass
  // goes on from that state.
  bool record_incomplete = false;
  int threads = 0;  // 0: every hardware thread. The result does not depend on it.
  // Called after every point with done = the points simulated so far and total = all of them
  // (unit "points"), from the worker threads but one call at a time, done increasing. Empty: no
  // reports.
  ProgressCallback progress = {};
};

enum class SweepPass { kUp, kDown, kFixed };
std::string ToString(SweepPass pass);  // "up", "down", "fixed"

struct SweepPoint {
  int chain = 0;  // index of the starting state
  SweepPass pass = SweepPass::kUp;
  int step = 0;        // index along the pass
  double value = 0.0;  // the parameter
  std::vector<Eigen::VectorXd> section;  // recorded_periods states at phase phi_section
  double stops_per_period = 0.0;
  double sticks_per_period = 0.0;
  int period = 0;  // smallest p with section[k + p] == section[k] (to tolerance); 0 if none
  // max |q_c(t)| of the contact's coordinate (the paper's x2) over the recorded periods, exact
  // (SettledMotion::contact_amplitude): the quantity a branch's `amplitude:<q_c>` measures over its
  // period, so the two are drawn on one axis. NaN where the search was cut short or the point is
  // incomplete.
  double contact_amplitude = 0.0;
  // With SweepOptions::record_incomplete: why the simulation stopped early; "" when it ran its course.
  std::string incomplete;
};

// One chain per state of `starts`, each taken as the state at forcing phase `phi_section`
// (time 0) of its first point. Points are ordered by chain, then pass (up before down), then
// step, whatever the number of threads. A model without forcing is read on its stick-entry section
// (SimulateSettled). Throws InvalidInput for no starts, a start not of the model's size, omega or a
// time_unit <= 0 for a model without forcing, options out of range
// or a swept value where the model's Validate fails (field "from" or "to" at an end, "steps"
// inside), and std::runtime_error naming the point when a simulation stops early
// (max_events_per_simulation, or the event search's bound). Compiled for Pascal2014 and
// DynamicLinearOscillator.
template <OscillatorModel Model>
std::vector<SweepPoint> Sweep(const Model& model, const typename Model::Parameters& base,
                              const std::vector<typename Model::State>& starts, double phi_section,
                              const SweepOptions& options);

// The paper's model's.
std::vector<SweepPoint> Sweep(const Parameters& base, const std::vector<State>& starts, double phi_section,
                              const SweepOptions& options);

// `count` starting states: `centre` first, then states drawn uniformly from the box
// |x - centre|_inf <= half_width by a splitmix64 generator seeded with `seed` (the same numbers
// on every platform, so a sweep is reproduced by its command line).
template <typename StateVector>
std::vector<StateVector> ScatteredStarts(const StateVector& centre, double half_width, int count, std::uint64_t seed);

// One CSV row per recorded section point: chain, direction, step, <parameter>, section_phase, k,
// the state by the model's column names (ModelDescription::state_columns: x1, x2, v1, v2 for the
// paper's model), stops_per_period, sticks_per_period, period, amplitude:<q_c> (the point's,
// repeated on each of its rows). Deterministic: shortest round-trip numbers. `parameter` as
// SweepOptions::parameter.
template <OscillatorModel Model>
std::string SweepCsv(const Model& model, const std::vector<SweepPoint>& points, int parameter, double phi_section);
// Whether `line` is the header SweepCsv writes (for any model and parameter), or wrote before its
// second column was renamed "direction" from "pass": the mark of a file that sweep may replace.
bool IsSweepCsvHeader(std::string_view line);

}  // namespace stickslip
