// From a simulated motion to its exact periodic orbit: simulate out a transient with the exact
// simulator, detect the period on the stroboscopic section (the state at t = n 2 pi/omega, where
// the forcing phase is the start's phi): the smallest k whose section repeats and whose events
// repeat with it (the origin's event comes back after k T, to 1e-3 T); read the orbit type, the
// durations, the phase and the state off the simulated events of one period, solve the periodicity equations from there
// (orbits/start_problem.hpp, orbits/orbit_solver.hpp) and verify the solution by both
// simulators (orbits/verification.hpp).
//
// The orbit's origin is a segment end (x2' = 0, periodicity.hpp). Of the events in the first
// period after the transient, it is the first of, in this order of preference: a reversal from
// slip+ into slip-, a stick exit into slip-, an abnormal stop in slip-, any event. This is the
// paper's choice for all five of its orbits, so that a found paper orbit has the paper's phase
// and durations. An orbit whose period holds no event at all (a permanent stick) has no orbit
// type (a stick cannot follow itself) and is reported as such.
//
//   const FindOrbitResult found = FindOrbit(parameters, x0, phi);
//   if (found.status == FindOrbitStatus::kFound) use(found.solution->orbit);
//   // found.start: the builder's input (signature, set, guess) that `stickslip solve` takes.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "stickslip/model/pascal_2014/flows.hpp"
#include "stickslip/model/pascal_2014/parameters.hpp"
#include "stickslip/model/transient.hpp"
#include "stickslip/progress.hpp"
#include "stickslip/orbits/margins.hpp"
#include "stickslip/orbits/orbit_solver.hpp"
#include "stickslip/orbits/start_problem.hpp"
#include "stickslip/orbits/verification.hpp"

namespace stickslip {

struct FindOrbitOptions {
  // Forcing periods simulated and discarded before the period is detected (0 to kMaxTransient).
  int transient_periods = 1000;
  // While the section does not repeat, the transient goes on for twice as long as the last one,
  // up to this many more times (0 to 10), and never beyond kMaxTransient periods in all: from the
  // default 1000, up to 31000 periods (an unstable orbit is left slowly).
  int settle_rounds = 4;
  // The largest period multiple k tried: the motion repeats after k forcing periods (1 to
  // kMaxMultiple).
  int max_multiple = 8;
  // Section points repeat when |X(t + k T) - X(t)|_inf <= tolerance (1 + |X(t)|_inf), T = 2 pi/omega
  // (kMinTolerance to kMaxTolerance). The same test decides antisymmetry, X(t + k T/2) = -X(t) for odd k.
  double periodicity_tolerance = 1e-6;
  // How many whole periods of k T every section comparison is repeated over (1 to kMaxConfirmations).
  int confirmations = 3;
  // The largest number of listed segments of a found orbit type (1 to 1000): a bound on the
  // equations solved.
  int max_segments = 200;
  // The exact simulator's guard against chattering, per simulation.
  int max_events = 1000000;
  // Newton on the periodicity equations.
  OrbitSolverOptions solver;

  // Reports the transient periods simulated over every round (total: those of the rounds so far).
  ProgressCallback progress = {};

  static constexpr int kMaxTransient = kMaxTransientPeriods;
  static constexpr int kMaxMultiple = 999;  // the signature's "period K" range
  static constexpr int kMaxConfirmations = 100;
  static constexpr double kMinTolerance = 1e-12;
  static constexpr double kMaxTolerance = 1e-2;
  // Throws InvalidInput naming the member ("transient_periods", ...) when one is out of range.
  void Validate() const;
};

enum class FindOrbitStatus {
  kFound,                 // solved, every margin > 0, and verified by both simulators
  kNotPeriodic,           // no k <= max_multiple repeats on the section (or none whose events
                          // repeat with it: the motion has not settled)
  kSimulationIncomplete,  // the simulator stopped early (max_events, or the event search's bound)
  kNoOrbitType,           // periodic, but its events give no orbit type (none in a period, or
                          // too many segments, or events that do not repeat with the section)
  kSolveFailed,           // Newton did not converge from the simulated start
  kNotAMotion,            // solved, but a margin <= 0 or the verification by simulation failed
};
const char* ToString(FindOrbitStatus status);  // "found", "not-periodic", ...

struct FindOrbitResult {
  FindOrbitStatus status = FindOrbitStatus::kSimulationIncomplete;
  std::string message;  // one line: what was found, or why not

  int transient_periods = 0;  // forcing periods simulated as transient in all
  // The section: the k detected (0 when none), the mismatch of that k, or, when none repeats,
  // the smallest mismatch seen and its k. Mismatches are relative, as the tolerance.
  int period_multiple = 0;
  double mismatch = 0.0;
  int closest_multiple = 0;
  bool antisymmetric = false;
  double antisymmetry_mismatch = 0.0;  // for odd k; NaN for even k

  // What was read off one simulated period, as the one start builder takes it: the signature,
  // the parameters (set), the origin's state x10 x20 v10, its phase phi in [0, 2 pi) and the
  // durations d1..dn (guess); with abnormal stops u_s is released and u_r tied to it. Filled
  // for kSolveFailed, kNotAMotion and kFound (and kNoOrbitType when the builder refuses it).
  std::optional<StartInput> start;
  std::optional<StartProblem> problem;  // built from `start`: the orbit guess and its unknowns
  double origin_time = 0.0;  // time of the origin after the transient, 0 < t < 2 k T

  std::optional<OrbitSolution> solution;    // when Newton ran
  std::vector<Margin> margins;              // of the converged solution
  std::optional<Verification> verification;  // of the converged solution

  bool Found() const { return status == FindOrbitStatus::kFound; }
};

// The start builder's input (orbits/start_problem.hpp) that gives back `orbit`: its signature, its
// parameters as set, its state, phase and durations as guess, and, when it has an abnormal stop,
// u_s released with u_r tied to it (its equations are square only so, eq. 25).
StartInput StartInputOf(const Orbit& orbit);

// Simulates from (x0, phi) at `parameters` and finds the periodic orbit the motion settles on.
// Throws InvalidInput for invalid parameters (Validate), a start outside kStateRange, or options
// out of range; every numerical outcome is a status. Bounded: simulations of
// the transient and of max((confirmations + 1), 3) max_multiple + 1 forcing periods, each within
// max_events, per round (at most settle_rounds + 1, and kMaxTransient periods of transient in
// all), and one Newton solve of at most max_segments + 4 unknowns.
FindOrbitResult FindOrbit(const Parameters& parameters, const State& x0, double phi,
                          const FindOrbitOptions& options = {});

}  // namespace stickslip
