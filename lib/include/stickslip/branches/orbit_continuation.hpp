// Branches of periodic orbits: the orbit problem (orbits/periodicity.hpp) continued in one of its
// variables by the generic engine, watched by the OrbitMonitor (orbit_monitor.hpp): the
// admissibility margins as terminal test functions, whose sign changes are changes of orbit type.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "stickslip/branches/orbit_condition.hpp"
#include "stickslip/branches/orbit_monitor.hpp"
#include "stickslip/continuation/augmented_system.hpp"
#include "stickslip/continuation/continuation.hpp"
#include "stickslip/orbits/orbit_solver.hpp"
#include "stickslip/orbits/periodicity.hpp"

namespace stickslip {

// The amplitude, max |x1|, |x2| over an orbit (scaled displacements: orbits/orbit_measures.hpp),
// past which a branch ends at a resonance of the forcing: as omega nears a natural frequency (eq.
// 56) the forced response grows without bound, and no parameter range ends the branch first.
inline constexpr double kDefaultMaxAmplitude = 1e3;
// How near (relative) a branch of orbits that never stick may come to a natural frequency of an
// undamped slip (orbits/slip_resonance.hpp) while approaching it: there its amplitude already
// grows as 1/|omega - omega_k|, and the continuation, its step bounded, would creep on towards it.
inline constexpr double kDefaultResonanceApproach = 1e-2;

struct OrbitContinuationSetup {
  Orbit start;                 // the start orbit, or a guess of it (corrected at its parameter)
  UnknownChoice unknowns;      // square at a fixed continuation parameter
  std::string parameter = "omega";  // the continued variable
  ShootingChoice shooting = ShootingChoice::kAuto;
  LinearSolverType sparse_solver = LinearSolverType::kKlu;
  ContinuationOptions options;  // parameter_index is set here
  FlowEvaluator flow;  // the closed form; the benchmark compares Odeint
  // Test functions (by column name: "margin:G:2", "floquet:torus") recorded but not watched,
  // besides the condition's Defining() (those that sit on zero or mean nothing along its curve).
  std::vector<std::string> unwatched;
  // With a condition, the branch is a curve in two parameters (branches/boundary_curve.hpp): the
  // periodicity equations and the condition's, in the unknowns and the condition's own; the
  // condition's defining test functions are not watched.
  std::shared_ptr<const OrbitCondition> condition;
  // A resonance ends the branch at its first point whose amplitude passes this (> 0; infinity:
  // never): BranchEnd::kStopped, the message beginning "resonance:".
  double max_amplitude = kDefaultMaxAmplitude;
  // A resonance ends the branch too at its first point that, never sticking, approached an undamped
  // slip's natural frequency to within this (relative, 0 to 1; 0: never), its amplitude growing:
  // the message beginning "resonance: at omega_k".
  double resonance_approach = kDefaultResonanceApproach;
};

struct OrbitBranch {
  Branch branch;
  std::vector<Orbit> orbits;  // one per branch point
  Shooting shooting = Shooting::kSingle;
  std::vector<PointColumn> columns;  // the monitor's, in the order of the result files
};

// Throws InvalidInput naming "free", "fix", "unknowns", "parameter", "max_amplitude" or
// "resonance_approach" if the choice of unknowns is not square, the parameter is not a held
// variable, max_amplitude is not > 0 or resonance_approach not in [0, 1). A branch ends as the
// engine ends it, or at a resonance (max_amplitude, resonance_approach). `observer`, if
// given, sees the branch after every step (a progress display, say).
OrbitBranch ContinueOrbit(const OrbitContinuationSetup& setup,
                          const std::function<void(const Branch&)>& observer = {});

// The pieces of ContinueOrbit, for stepping by hand.
struct OrbitContinuationProblem {
  std::unique_ptr<OrbitSystem> system;  // the periodicity equations
  std::unique_ptr<ExtraEquations> extra;       // with a condition: its equations, and
  std::unique_ptr<AugmentedSystem> augmented;  // the two together
  std::unique_ptr<OrbitMonitor> monitor;
  ContinuationOptions options;
  Eigen::VectorXd start;  // the unknowns of Continued()
  // What the engine continues: the periodicity equations, with the condition's where there is one.
  const NonlinearSystem& Continued() const;
};
OrbitContinuationProblem MakeOrbitContinuation(const OrbitContinuationSetup& setup);
// The branch of a continuation stepped by hand on `problem`, as ContinueOrbit returns it: the
// orbit of every point, the shooting and the monitor's columns.
OrbitBranch ToOrbitBranch(const OrbitContinuationProblem& problem, Branch branch);

// Where a branch stepped by hand ends before the engine would end it: at its point `point`.
struct BranchStop {
  int point = 0;
  BranchEnd why = BranchEnd::kStopped;
  std::string message;
};
// `branch` ended at `stop` as the engine ends a branch: the points after it and their special
// points dropped, an EP there (its test function ToString(why)).
Branch EndedAt(Branch branch, const BranchStop& stop);

// A branch of periodic orbits stepped by hand, ending as ContinueOrbit's does: as the engine ends
// it, or at a resonance (BranchEnd::kStopped at the first point whose amplitude passed
// setup.max_amplitude, or is nan: the extrema's search was cut short, no bound; or that, never
// sticking, came nearer an undamped slip's natural frequency than the point before it, with a
// larger amplitude, and to within setup.resonance_approach).
//   OrbitContinuation c(setup);
//   while (c.Step()) show(c.branch());
//   OrbitBranch b = c.Result();
class OrbitContinuation {
 public:
  explicit OrbitContinuation(const OrbitContinuationSetup& setup);
  bool Step();  // false once the branch has ended
  const Branch& branch() const { return ended_ ? *ended_ : continuation_->branch(); }
  const OrbitContinuationProblem& problem() const { return problem_; }
  OrbitBranch Result() const { return ToOrbitBranch(problem_, branch()); }

 private:
  // The first point added since the last call at a resonance, as a stop.
  std::optional<BranchStop> Resonance();
  double Amplitude(const BranchPoint& point) const;
  std::optional<BranchStop> AmplitudeBound(const BranchPoint& point, bool start) const;
  std::optional<BranchStop> SlipResonanceApproached(const BranchPoint& point, bool start);

  OrbitContinuationProblem problem_;
  std::unique_ptr<Continuation> continuation_;
  double max_amplitude_ = 0.0;
  double resonance_approach_ = 0.0;
  struct ResonanceDistance {
    double distance = 0.0;   // to the nearest undamped slip frequency (relative)
    double amplitude = 0.0;  // Amplitude()
  };
  std::optional<ResonanceDistance> last_;  // at the last point seen, if it never sticks
  std::string parameter_;
  int amplitude_x1_ = 0;  // the measures' indices in BranchPoint::recorded
  int amplitude_x2_ = 0;
  std::size_t checked_ = 0;     // points seen by Resonance
  std::optional<Branch> ended_;  // the branch ended at a resonance
};

}  // namespace stickslip
