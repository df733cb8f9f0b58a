#include "stickslip/branches/orbit_continuation.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

#include "stickslip/orbits/stability.hpp"

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
  // Stability: recorded at every point; the multipliers through -1 and the unit circle are events.
  for (int k = 1; k <= 4; ++k) {
    info_.push_back({fmt::format("floquet:mu{}_re", k), "", false, false});
    info_.push_back({fmt::format("floquet:mu{}_im", k), "", false, false});
  }
  info_.push_back({"stable", "", false, false});
  info_.push_back({"floquet:det(M-I)", "", false, false});  // zero at a fold (LP)
  info_.push_back({"floquet:det(M+I)", "PD", false, true});
  info_.push_back({"floquet:torus", "TR", false, true});
}

Eigen::VectorXd OrbitMonitor::Evaluate(const Eigen::VectorXd& u) const {
  const Orbit orbit = system_.ToOrbit(u);
  const std::vector<Margin> margins = AdmissibilityMargins(orbit);
  const Stability stability = StabilityOf(orbit);
  Eigen::VectorXd values(static_cast<int>(info_.size()));
  int k = 0;
  for (const Margin& m : margins) values(k++) = m.value;
  for (const std::complex<double>& mu : stability.multipliers) {
    values(k++) = mu.real();
    values(k++) = mu.imag();
  }
  values(k++) = stability.stable ? 1.0 : 0.0;
  values(k++) = stability.fold_test;
  values(k++) = stability.flip_test;
  values(k++) = stability.torus_test;
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
  Continuation continuation(*problem.system, problem.monitor.get(), problem.options, problem.start);
  while (continuation.Step()) {
    if (observer) observer(continuation.branch());
  }
  result.branch = continuation.branch();
  for (const BranchPoint& p : result.branch.points) result.orbits.push_back(problem.system->ToOrbit(p.u));
  return result;
}

}  // namespace stickslip
