#include "stickslip/continuation/orbit_continuation.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

namespace stickslip {

namespace ov = orbit_variables;

std::string OrbitTypeChangeCode(const Margin& margin, Mode segment_mode) {
  switch (margin.kind) {
    case MarginKind::kDuration: return segment_mode == Mode::kStick ? "T0" : "S0";
    case MarginKind::kSlipVelocity:
    case MarginKind::kStopSlope: return "NS";
    case MarginKind::kStopForce: return "SK";
    case MarginKind::kFrictionLevel: return "EP";
    case MarginKind::kStickConstraint:
    case MarginKind::kExitSlope: break;
  }
  return "GR";
}

OrbitMonitor::OrbitMonitor(const OrbitSystem& system, const Orbit& start) : system_(system) {
  // The margins' names and kinds depend on the signature only.
  for (const Margin& m : AdmissibilityMargins(start)) {
    const Mode mode = m.segment < 0 ? Mode::kStick : start.signature.segments()[m.segment];
    info_.push_back({"margin:" + m.Name(), OrbitTypeChangeCode(m, mode), true});
  }
}

Eigen::VectorXd OrbitMonitor::Evaluate(const Eigen::VectorXd& u) const {
  const std::vector<Margin> margins = AdmissibilityMargins(system_.ToOrbit(u));
  Eigen::VectorXd values(static_cast<int>(margins.size()));
  for (std::size_t k = 0; k < margins.size(); ++k) values(static_cast<int>(k)) = margins[k].value;
  return values;
}

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
  const bool multiple = setup.shooting == ShootingChoice::kMultiple ||
                        (setup.shooting == ShootingChoice::kAuto && n > OrbitSolverOptions{}.max_single_shooting_segments);
  OrbitContinuationProblem problem;
  problem.system = std::make_unique<OrbitSystem>(setup.start, unknowns, setup.unknowns.tie_static_friction,
                                                 multiple ? Shooting::kMultiple : Shooting::kSingle, setup.flow);
  problem.monitor = std::make_unique<OrbitMonitor>(*problem.system, setup.start);
  problem.options = setup.options;
  problem.options.parameter_index = static_cast<int>(free.indices.size());
  if (multiple && problem.options.corrector.linear_solver == LinearSolverType::kDenseLu) {
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
  Continuation continuation(*problem.system, problem.monitor.get(), problem.options, problem.start);
  while (continuation.Step()) {
    if (observer) observer(continuation.branch());
  }
  result.branch = continuation.branch();
  for (const BranchPoint& p : result.branch.points) result.orbits.push_back(problem.system->ToOrbit(p.u));
  return result;
}

}  // namespace stickslip
