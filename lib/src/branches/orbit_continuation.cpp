#include "stickslip/branches/orbit_continuation.hpp"


namespace stickslip {

OrbitContinuationProblem MakeOrbitContinuation(const OrbitContinuationSetup& setup) {
  const Signature& signature = setup.start.signature;
  const int n = signature.size();
  const std::vector<int> free = FreeIndices(signature, setup.unknowns);
  std::vector<int> unknowns = free;
  unknowns.push_back(ContinuedVariable(signature, free, setup.unknowns.tie_static_friction, setup.parameter));
  const Shooting shooting = ResolveShooting(setup.shooting, n);
  OrbitContinuationProblem problem;
  problem.system = std::make_unique<OrbitSystem>(setup.start, unknowns, setup.unknowns.tie_static_friction,
                                                 shooting, setup.flow);
  problem.monitor = std::make_unique<OrbitMonitor>(*problem.system, setup.start);
  problem.options = setup.options;
  problem.options.parameter_index = static_cast<int>(free.size());
  if (shooting == Shooting::kMultiple && problem.options.corrector.linear_solver == LinearSolverType::kDenseLu) {
    problem.options.corrector.linear_solver = setup.sparse_solver;
  }
  problem.start = problem.system->Unknowns(setup.start);
  return problem;
}

OrbitBranch ContinueOrbit(const OrbitContinuationSetup& setup,
                          const std::function<void(const Branch&)>& observer) {
  OrbitContinuationProblem problem = MakeOrbitContinuation(setup);
  OrbitBranch result;
  result.shooting = problem.system->equations().shooting();
  result.columns = problem.monitor->Columns();
  Continuation continuation(*problem.system, problem.monitor.get(), problem.options, problem.start);
  while (continuation.Step()) {
    if (observer) observer(continuation.branch());
  }
  result.branch = continuation.branch();
  for (const BranchPoint& p : result.branch.points) result.orbits.push_back(problem.system->ToOrbit(p.u));
  return result;
}

}  // namespace stickslip
