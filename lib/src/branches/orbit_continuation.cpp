#include "stickslip/branches/orbit_continuation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/model/pascal_2014.hpp"
#include "stickslip/orbits/slip_resonance.hpp"


namespace stickslip {

namespace {

namespace ov = orbit_variables;

// The continued parameter's range stops at its valid range (model/pascal_2014/parameters.hpp), and u_r >= u_s
// (eq. 4) bounds a continuation in either while the other is held: bounds located exactly (EP).
// A released u_s reaching zero ends the family by the sliding-friction margin, a domain boundary.
void KeepInPhysicalRanges(const OrbitContinuationSetup& setup, const std::vector<int>& free, int parameter,
                          ContinuationOptions* options) {
  const int n = setup.start.signature.size();
  const std::vector<ParameterDescription>& ranges = Pascal2014{}.Description().parameters;
  for (int k = 0; k < kParameterCount; ++k) {
    if (parameter != ov::Parameter(n, kAllParameters[k])) continue;
    options->lambda_min = std::max(options->lambda_min, ranges[k].minimum);
    options->lambda_max = std::min(options->lambda_max, ranges[k].maximum);
  }
  const int kinetic = ov::KineticLevel(n), static_level = ov::StaticLevel(n);
  const bool held_kinetic = std::find(free.begin(), free.end(), kinetic) == free.end();
  const bool held_static =
      std::find(free.begin(), free.end(), static_level) == free.end() && !setup.unknowns.tie_static_friction;
  const Eigen::VectorXd start = ov::Pack(setup.start);
  if (parameter == static_level && held_kinetic) options->lambda_min = std::max(options->lambda_min, start(kinetic));
  if (parameter == kinetic && held_static) options->lambda_max = std::min(options->lambda_max, start(static_level));
}

// The condition's equations in the unknowns of the periodicity equations.
class ConditionEquations final : public ExtraEquations {
 public:
  ConditionEquations(const OrbitSystem& system, std::shared_ptr<const OrbitCondition> condition)
      : system_(system), condition_(std::move(condition)) {}
  int UnknownCount() const override { return condition_->ExtraUnknownCount(); }
  int EquationCount() const override { return condition_->EquationCount(); }
  void Evaluate(const Eigen::VectorXd& u, const Eigen::VectorXd& e, Eigen::VectorXd* residual, Eigen::MatrixXd* d_u,
                Eigen::MatrixXd* d_e) const override {
    Eigen::MatrixXd d_variables;
    condition_->Evaluate(system_.ToOrbit(u), e, residual, d_u ? &d_variables : nullptr, d_e);
    if (d_u) *d_u = system_.ToUnknowns(d_variables);
  }

 private:
  const OrbitSystem& system_;
  std::shared_ptr<const OrbitCondition> condition_;
};

}  // namespace

const NonlinearSystem& OrbitContinuationProblem::Continued() const {
  if (augmented) return *augmented;
  return *system;
}

OrbitContinuationProblem MakeOrbitContinuation(const OrbitContinuationSetup& setup) {
  if (!(setup.max_amplitude > 0.0)) throw InvalidInput("max_amplitude", setup.max_amplitude, "max_amplitude > 0");
  if (!(setup.resonance_approach >= 0.0 && setup.resonance_approach < 1.0)) {
    throw InvalidInput("resonance_approach", setup.resonance_approach, "0 <= resonance_approach < 1");
  }
  const Signature& signature = setup.start.signature;
  const int n = signature.size();
  const std::vector<int> free = FreeIndices(signature, setup.unknowns);
  std::vector<int> unknowns = free;
  unknowns.push_back(ContinuedVariable(signature, free, setup.unknowns.tie_static_friction, setup.parameter));
  const Shooting shooting = ResolveShooting(setup.shooting, n);
  OrbitContinuationProblem problem;
  problem.system = std::make_unique<OrbitSystem>(setup.start, unknowns, setup.unknowns.tie_static_friction,
                                                 shooting, setup.flow);
  std::vector<std::string> unwatched = setup.unwatched;
  std::vector<WatchedColumn> watched;
  if (setup.condition) {
    watched = setup.condition->CodimensionTwoTests();
    problem.extra = std::make_unique<ConditionEquations>(*problem.system, setup.condition);
    problem.augmented = std::make_unique<AugmentedSystem>(*problem.system, *problem.extra);
    for (std::string& name : setup.condition->Defining()) unwatched.push_back(std::move(name));
  }
  problem.monitor = std::make_unique<OrbitMonitor>(*problem.system, setup.start, std::move(unwatched), std::move(watched));
  problem.options = setup.options;
  problem.options.parameter_index = static_cast<int>(free.size());
  problem.options.parameter_name = setup.parameter;
  KeepInPhysicalRanges(setup, free, unknowns.back(), &problem.options);
  if (shooting == Shooting::kMultiple && problem.options.corrector.linear_solver == LinearSolverType::kDenseLu) {
    problem.options.corrector.linear_solver = setup.sparse_solver;
  }
  problem.start = problem.system->Unknowns(setup.start);
  if (setup.condition) {
    const Eigen::VectorXd extra = setup.condition->ExtraUnknowns(setup.start);
    problem.start.conservativeResize(problem.start.size() + extra.size());
    problem.start.tail(extra.size()) = extra;
  }
  return problem;
}

OrbitBranch ToOrbitBranch(const OrbitContinuationProblem& problem, Branch branch) {
  OrbitBranch result;
  result.shooting = problem.system->equations().shooting();
  result.columns = problem.monitor->Columns();
  result.branch = std::move(branch);
  const int unknowns = problem.system->UnknownCount();
  for (const BranchPoint& p : result.branch.points) result.orbits.push_back(problem.system->ToOrbit(p.u.head(unknowns)));
  return result;
}

Branch EndedAt(Branch branch, const BranchStop& stop) {
  branch.points.resize(stop.point + 1);
  std::erase_if(branch.special_points, [&](const SpecialPoint& s) { return s.point > stop.point; });
  BranchPoint& point = branch.points.back();
  if (point.label.empty()) point.label = "EP";
  branch.special_points.push_back(
      {"EP", ToString(stop.why), stop.point, point.lambda, point.u, point.tests, 0.0, true, 0.0, point.tangent});
  branch.end = stop.why;
  branch.end_message = stop.message;
  return branch;
}

OrbitContinuation::OrbitContinuation(const OrbitContinuationSetup& setup)
    : problem_(MakeOrbitContinuation(setup)),
      continuation_(std::make_unique<Continuation>(problem_.Continued(), problem_.monitor.get(), problem_.options,
                                                   problem_.start)),
      max_amplitude_(setup.max_amplitude),
      resonance_approach_(setup.resonance_approach),
      parameter_(setup.parameter) {
  auto recorded = [&](const char* name) {
    for (const PointColumn& c : problem_.monitor->Columns()) {
      if (c.name == name && !c.monitored) return c.index;
    }
    throw std::logic_error(std::string("the orbit monitor records no ") + name);
  };
  amplitude_x1_ = recorded(orbit_columns::kAmplitudeX1);
  amplitude_x2_ = recorded(orbit_columns::kAmplitudeX2);
}

std::optional<BranchStop> OrbitContinuation::Resonance() {
  const Branch& branch = continuation_->branch();
  for (; checked_ < branch.points.size(); ++checked_) {
    const BranchPoint& point = branch.points[checked_];
    const bool start = checked_ == 0;
    std::optional<BranchStop> stop = AmplitudeBound(point, start);
    if (!stop) stop = SlipResonanceApproached(point, start);
    if (stop) {
      stop->point = static_cast<int>(checked_++);
      return stop;
    }
  }
  return std::nullopt;
}

// max |x1|, |x2| over the orbit as the monitor recorded it, exact; nan where undefined.
double OrbitContinuation::Amplitude(const BranchPoint& point) const {
  const double x1 = point.recorded(amplitude_x1_), x2 = point.recorded(amplitude_x2_);
  return std::isnan(x1) || std::isnan(x2) ? std::numeric_limits<double>::quiet_NaN() : std::max(x1, x2);
}

std::optional<BranchStop> OrbitContinuation::AmplitudeBound(const BranchPoint& point, bool start) const {
  // nan (no bound) stops too.
  const double amplitude = Amplitude(point);
  if (amplitude <= max_amplitude_) return std::nullopt;
  return BranchStop{0, BranchEnd::kStopped,
                    fmt::format("resonance: the amplitude max(|x1|, |x2|) = {:.6g} {} max_amplitude = {:g} at "
                                "{} = {:.10g}{}",
                                amplitude, start ? "of the start is above" : "passed", max_amplitude_, parameter_,
                                point.lambda, start ? " (a larger max_amplitude continues it)" : "")};
}

// Approaching: nearer than at the point before, the amplitude larger (the start only sets both,
// so that a branch starting near a resonance may leave it). A branch whose amplitude falls as it
// nears omega_k is bounded there (a large enough u_s folds it back): it goes on.
std::optional<BranchStop> OrbitContinuation::SlipResonanceApproached(const BranchPoint& point, bool start) {
  const std::optional<SlipResonance> near =
      NearestSlipResonance(problem_.system->ToOrbit(point.u.head(problem_.system->UnknownCount())));
  const std::optional<ResonanceDistance> before = start ? std::nullopt : last_;
  last_ = near ? std::optional<ResonanceDistance>({near->distance, Amplitude(point)}) : std::nullopt;
  if (!near || !before || !(near->distance < before->distance && near->distance <= resonance_approach_ &&
                            last_->amplitude > before->amplitude)) {
    return std::nullopt;
  }
  return BranchStop{0, BranchEnd::kStopped,
                    fmt::format("resonance: at omega_{} = {:.10g}, a natural frequency of the undamped slip, which the "
                                "orbit, never sticking, approached to {:.4g} (relative; resonance_approach = {:g}) at "
                                "{} = {:.10g}, its amplitude growing",
                                near->index, near->frequency, near->distance, resonance_approach_, parameter_,
                                point.lambda)};
}

bool OrbitContinuation::Step() {
  if (ended_) return false;
  const bool more = continuation_->Step();
  if (const std::optional<BranchStop> stop = Resonance()) {
    ended_ = EndedAt(continuation_->branch(), *stop);
    return false;
  }
  return more;
}

OrbitBranch ContinueOrbit(const OrbitContinuationSetup& setup,
                          const std::function<void(const Branch&)>& observer) {
  OrbitContinuation continuation(setup);
  while (continuation.Step()) {
    if (observer) observer(continuation.branch());
  }
  return continuation.Result();
}

}  // namespace stickslip
