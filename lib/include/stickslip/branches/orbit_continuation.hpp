// Branches of periodic orbits: the orbit problem (orbits/periodicity.hpp) continued in one of its
// variables by the generic engine, watched by the OrbitMonitor (orbit_monitor.hpp): the
// admissibility margins as terminal test functions, whose sign changes are changes of orbit type.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "stickslip/branches/orbit_condition.hpp"
#include "stickslip/branches/orbit_monitor.hpp"
#include "stickslip/continuation/augmented_system.hpp"
#include "stickslip/continuation/continuation.hpp"
#include "stickslip/orbits/orbit_solver.hpp"
#include "stickslip/orbits/periodicity.hpp"

namespace stickslip {

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
};

struct OrbitBranch {
  Branch branch;
  std::vector<Orbit> orbits;  // one per branch point
  Shooting shooting = Shooting::kSingle;
  std::vector<PointColumn> columns;  // the monitor's, in the order of the result files
};

// Throws InvalidInput naming "free", "fix", "unknowns" or "parameter" if the choice of unknowns
// is not square or the parameter is not a held variable. `observer`, if given, sees the branch after
// every step (a progress display, say).
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

}  // namespace stickslip
