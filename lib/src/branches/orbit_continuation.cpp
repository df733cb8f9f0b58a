#include "stickslip/branches/orbit_continuation.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

namespace stickslip {

namespace ov = orbit_variables;

OrbitContinuationProblem MakeOrbitContinuation(const OrbitContinuationSetup& setup) {
  const Signature& signature = setup.start.signature;
  const int n = signature.size();
  const FreeVariables free = ResolveUnknowns(signature, setup.unknowns);
  if (!free.error.empty()) throw std::invalid_argument(free.error);
  const std::optional<int> parameter = ov::IndexOf(n, setup.parameter);
  if (!parameter) {
    throw std::invalid_argument(fmt::format("parameter = '{}' is not a variable of the orbit", setup.parameter));
  }
  std::vector<int> unknowns = free.indices;
  if (std::find(unknowns.begin(), unknowns.end(), *parameter) != unknowns.end()) {
    throw std::invalid_argument(fmt::format(
        "parameter = '{}' is already an unknown: continue in a variable that is held", setup.parameter));
  }
  if (setup.unknowns.tie_static_friction && *parameter == ov::Parameter(n, ParameterId::kStaticFriction)) {
    throw std::invalid_argument("parameter = 'u_r' is tied to u_s: continue in u_s");
  }
  unknowns.push_back(*parameter);
  const Shooting shooting = ResolveShooting(setup.shooting, n);
  OrbitContinuationProblem problem;
  problem.system = std::make_unique<OrbitSystem>(setup.start, unknowns, setup.unknowns.tie_static_friction,
                                                 shooting, setup.flow);
  problem.monitor = std::make_unique<OrbitMonitor>(*problem.system, setup.start);
  problem.options = setup.options;
  problem.options.parameter_index = static_cast<int>(free.indices.size());
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
