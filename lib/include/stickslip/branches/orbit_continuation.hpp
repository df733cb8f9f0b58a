// Branches of periodic orbits: the orbit problem (orbits/periodicity.hpp) continued in one of its
// variables by the generic engine, with the admissibility margins (orbits/margins.hpp) as test
// functions. A margin's sign change is a change of orbit type:
//   GR  a stick constraint G or G1 grazing zero inside a stick (G:i, G1:i), or born at the stick
//       exit (exit-slope:i)
//   T0  a stick phase shrinking to zero (duration:i of a stick)
//   S0  a slip phase shrinking to zero (duration:i of a slip)
//   NS  x2' touching zero inside a slip (velocity:i), or at its end (stop-slope:i): a new stop
//   SK  the force condition at a stop crossing its threshold (reversal:i, stick-entry:i,
//       abnormal-stop:i)
//   EP  the sliding friction level u_s reaching zero: the end of the physical family
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "stickslip/continuation/continuation.hpp"
#include "stickslip/orbits/margins.hpp"
#include "stickslip/orbits/orbit_solver.hpp"
#include "stickslip/orbits/periodicity.hpp"

namespace stickslip {

// The special-point code of a margin's sign change.
std::string OrbitTypeChangeCode(const Margin& margin, Mode segment_mode);

// The margins of the orbit at each branch point, as test functions (all terminal).
class OrbitMonitor final : public Monitor {
 public:
  // `start` is any orbit of the system's signature (the names depend on the signature only).
  OrbitMonitor(const OrbitSystem& system, const Orbit& start);
  std::vector<TestFunctionInfo> TestFunctions() const override { return info_; }
  Eigen::VectorXd Evaluate(const Eigen::VectorXd& u) const override;

 private:
  const OrbitSystem& system_;
  std::vector<TestFunctionInfo> info_;
};

struct OrbitContinuationSetup {
  Orbit start;                 // the start orbit, or a guess of it (corrected at its parameter)
  UnknownChoice unknowns;      // square at a fixed continuation parameter
  std::string parameter = "omega";  // the continued variable
  ShootingChoice shooting = ShootingChoice::kAuto;
  LinearSolverType sparse_solver = LinearSolverType::kKlu;
  ContinuationOptions options;  // parameter_index is set here
  FlowEvaluator flow;  // the closed form; the benchmark compares Odeint
};

struct OrbitBranch {
  Branch branch;
  std::vector<Orbit> orbits;  // one per branch point
  Shooting shooting = Shooting::kSingle;
};

// Throws std::invalid_argument with a message naming the problem if the choice of unknowns is
// not square or the parameter is not a variable. `observer`, if given, sees the branch after
// every step (a progress display, say).
OrbitBranch ContinueOrbit(const OrbitContinuationSetup& setup,
                          const std::function<void(const Branch&)>& observer = {});

// The pieces of ContinueOrbit, for stepping by hand.
struct OrbitContinuationProblem {
  std::unique_ptr<OrbitSystem> system;
  std::unique_ptr<OrbitMonitor> monitor;
  ContinuationOptions options;
  Eigen::VectorXd start;
};
OrbitContinuationProblem MakeOrbitContinuation(const OrbitContinuationSetup& setup);

}  // namespace stickslip
