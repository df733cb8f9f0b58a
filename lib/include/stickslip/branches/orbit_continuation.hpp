// Branches of periodic orbits: the orbit problem (orbits/periodicity.hpp) continued in one of its
// variables by the generic engine, watched by the OrbitMonitor (orbit_monitor.hpp): the
// admissibility margins as terminal test functions, whose sign changes are changes of orbit type.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "stickslip/branches/orbit_condition.hpp"
#include "stickslip/branches/orbit_monitor.hpp"
#include "stickslip/continuation/augmented_system.hpp"
#include "stickslip/continuation/continuation.hpp"
#include "stickslip/orbits/orbit_problem.hpp"
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

template <OscillatorModel Model>
struct BasicOrbitContinuationSetup {
  OrbitOfModel<Model> start;   // the start orbit, or a guess of it (corrected at its parameter)
  UnknownChoice unknowns;      // square at a fixed continuation parameter
  std::string parameter = "omega";  // the continued variable
  ShootingChoice shooting = ShootingChoice::kAuto;
  LinearSolverType sparse_solver = LinearSolverType::kKlu;
  ContinuationOptions options;  // parameter_index is set here
  BasicFlowEvaluator<Model> flow;  // the closed form; the benchmark compares Odeint
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
  Model model{};  // last, so that the paper's model's setups need not name it
};
using OrbitContinuationSetup = BasicOrbitContinuationSetup<Pascal2014>;

template <OscillatorModel Model>
struct BasicOrbitBranch {
  Branch branch;
  std::vector<OrbitOfModel<Model>> orbits;  // one per branch point
  Shooting shooting = Shooting::kSingle;
  std::vector<PointColumn> columns;  // the monitor's, in the order of the result files
};
using OrbitBranch = BasicOrbitBranch<Pascal2014>;

// Throws InvalidInput naming "free", "fix", "unknowns", "parameter", "max_amplitude",
// "resonance_approach" if the choice of unknowns is not square, the parameter is not a held
// variable, max_amplitude is not > 0 or resonance_approach not in [0, 1). A branch ends as the engine ends it, or at a
// resonance (max_amplitude, resonance_approach). `observer`, if given, sees the branch after every
// step (a progress display, say). Compiled for the paper's model (orbit_continuation.cpp) and a
// [model]'s (DynamicLinearOscillator, model_trace.cpp); for another model include
// branches/model_orbit_continuation.hpp.
template <OscillatorModel Model>
BasicOrbitBranch<Model> ContinueOrbit(const BasicOrbitContinuationSetup<Model>& setup,
                                      const std::function<void(const Branch&)>& observer = {});
OrbitBranch ContinueOrbit(const OrbitContinuationSetup& setup, const std::function<void(const Branch&)>& observer = {});

// The pieces of ContinueOrbit, for stepping by hand: those of any model's problem.
struct OrbitContinuationProblem {
  std::unique_ptr<OrbitProblem> system;  // the periodicity equations
  std::unique_ptr<ExtraEquations> extra;       // with a condition: its equations, and
  std::unique_ptr<AugmentedSystem> augmented;  // the two together
  std::unique_ptr<OrbitMonitor> monitor;
  ContinuationOptions options;
  Eigen::VectorXd start;  // the unknowns of Continued()
  // What the engine continues: the periodicity equations, with the condition's where there is one.
  const NonlinearSystem& Continued() const;
};
template <OscillatorModel Model>
OrbitContinuationProblem MakeOrbitContinuation(const BasicOrbitContinuationSetup<Model>& setup);
// The branch of a continuation stepped by hand on `problem` (made for Model), as ContinueOrbit
// returns it: the orbit of every point, the shooting and the monitor's columns.
template <OscillatorModel Model>
BasicOrbitBranch<Model> ToOrbitBranch(const OrbitContinuationProblem& problem, Branch branch);

// What MakeOrbitContinuation assembles any model's problem from, once the model is erased.
struct OrbitContinuationParts {
  explicit OrbitContinuationParts(OrbitVariableSet v) : variables(std::move(v)) {}
  std::unique_ptr<OrbitProblem> system;
  Eigen::VectorXd start;  // the start's variables (orbits/orbit_problem.hpp)
  OrbitVariableSet variables;
  std::vector<int> free;  // the unknowns at a fixed parameter
  int parameter = 0;      // the continued variable
  bool tie_static_friction = false;
  std::string parameter_name;
  ContinuationOptions options;
  LinearSolverType sparse_solver = LinearSolverType::kKlu;
  std::vector<std::string> unwatched;
  std::shared_ptr<const OrbitCondition> condition;
  Eigen::VectorXd condition_start;                  // the condition's own unknowns at the start
};
OrbitContinuationProblem AssembleOrbitContinuation(OrbitContinuationParts parts);
// Throws InvalidInput naming "max_amplitude" or "resonance_approach" outside their ranges.
void CheckResonanceLimits(double max_amplitude, double resonance_approach);

// Where a branch stepped by hand ends before the engine would end it: at its point `point`.
struct BranchStop {
  int point = 0;
  BranchEnd why = BranchEnd::kStopped;
  std::string message;
};
// `branch` ended at `stop` as the engine ends a branch: the points after it and their special
// points dropped, an EP there (its test function ToString(why)).
Branch EndedAt(Branch branch, const BranchStop& stop);

// A branch of periodic orbits of any model stepped by hand, ending as ContinueOrbit's does: as
// the engine ends it, or at a resonance (BranchEnd::kStopped at the first point whose amplitude
// passed setup.max_amplitude, or is nan: the extrema's search was cut short, no bound; or that,
// never sticking, came nearer an undamped slip's natural frequency than the point before it, with
// a larger amplitude, and to within setup.resonance_approach).
//   OrbitContinuation c(setup);
//   while (c.Step()) show(c.branch());
//   OrbitBranch b = c.Result();
class OrbitContinuation {
 public:
  template <OscillatorModel Model>
  explicit OrbitContinuation(const BasicOrbitContinuationSetup<Model>& setup)
      : OrbitContinuation(MakeOrbitContinuation(setup), setup.max_amplitude, setup.resonance_approach) {}
  OrbitContinuation(OrbitContinuationProblem problem, double max_amplitude, double resonance_approach);
  bool Step();  // false once the branch has ended
  const Branch& branch() const { return ended_ ? *ended_ : continuation_->branch(); }
  const OrbitContinuationProblem& problem() const { return problem_; }
  template <OscillatorModel Model = Pascal2014>
  BasicOrbitBranch<Model> Result() const {
    return ToOrbitBranch<Model>(problem_, branch());
  }

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
  std::vector<int> amplitudes_;  // the amplitude measures' indices in BranchPoint::recorded
  std::string amplitude_name_;   // "max(|x1|, |x2|)"
  std::size_t checked_ = 0;      // points seen by Resonance
  std::optional<Branch> ended_;  // the branch ended at a resonance
};

template <OscillatorModel Model>
BasicOrbitBranch<Model> ContinueOrbit(const BasicOrbitContinuationSetup<Model>& setup,
                                      const std::function<void(const Branch&)>& observer) {
  OrbitContinuation continuation(setup);
  while (continuation.Step()) {
    if (observer) observer(continuation.branch());
  }
  return continuation.Result<Model>();
}

// Compiled once, in orbit_continuation.cpp, for the paper's model.
extern template OrbitContinuationProblem MakeOrbitContinuation(const OrbitContinuationSetup& setup);
extern template OrbitBranch ToOrbitBranch<Pascal2014>(const OrbitContinuationProblem& problem, Branch branch);

}  // namespace stickslip
