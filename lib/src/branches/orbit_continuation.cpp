#include "stickslip/branches/orbit_continuation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/model/pascal_2014.hpp"
#include "stickslip/branches/model_orbit_continuation.hpp"
#include "stickslip/orbits/slip_resonance.hpp"


namespace stickslip {

namespace {

// The bounds of the physics on a varied variable (the continued parameter, or a curve's released
// one): its valid range (the model's description), and the static friction level at or above the
// kinetic one (eq. 4 for the paper's model) while the other is held. Each with its reason, which
// the end message there gives; of two bounds on a side the narrower holds.
struct PhysicalBounds {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  std::string min_reason, max_reason;
};

PhysicalBounds PhysicalBoundsOf(const OrbitContinuationParts& parts, int variable) {
  const OrbitLayout& layout = parts.variables.layout;
  PhysicalBounds b;
  const auto raise_min = [&b](double bound, std::string reason) {
    if (!(bound > b.min)) return;
    b.min = bound;
    b.min_reason = std::move(reason);
  };
  const auto lower_max = [&b](double bound, std::string reason) {
    if (!(bound < b.max)) return;
    b.max = bound;
    b.max_reason = std::move(reason);
  };
  const std::vector<ParameterDescription>& ranges = parts.system->description().parameters;
  for (std::size_t k = 0; k < ranges.size(); ++k) {
    if (variable != layout.Parameter(static_cast<int>(k))) continue;
    raise_min(ranges[k].minimum, "its valid range: " + ranges[k].range);
    lower_max(ranges[k].maximum, "its valid range: " + ranges[k].range);
  }
  const int kinetic = parts.variables.kinetic_level, static_level = parts.variables.static_level;
  const auto held = [&parts](int v) {
    return v != parts.parameter && std::find(parts.free.begin(), parts.free.end(), v) == parts.free.end();
  };
  const std::string kinetic_name = layout.Name(kinetic), static_name = layout.Name(static_level);
  if (variable == static_level && held(kinetic)) {
    raise_min(parts.start(kinetic), fmt::format("{} >= {} = {:.10g}", static_name, kinetic_name, parts.start(kinetic)));
  }
  if (variable == kinetic && held(static_level) && !parts.tie_static_friction) {
    lower_max(parts.start(static_level),
              fmt::format("{} <= {} = {:.10g}", kinetic_name, static_name, parts.start(static_level)));
  }
  return b;
}

// The continued parameter's range stops at its bounds of the physics: located exactly (EP), where
// narrower than the range asked for with their reasons. A released kinetic level reaching zero ends
// the family by the sliding-friction margin, a domain boundary.
void KeepInPhysicalRanges(const OrbitContinuationParts& parts, ContinuationOptions* options) {
  const PhysicalBounds b = PhysicalBoundsOf(parts, parts.parameter);
  if (b.min > options->lambda_min) {
    options->lambda_min = b.min;
    options->lambda_min_reason = b.min_reason;
  }
  if (b.max < options->lambda_max) {
    options->lambda_max = b.max;
    options->lambda_max_reason = b.max_reason;
  }
}

// A curve's released parameters end it at their bounds of the physics (EP): past them no orbit is
// a motion. A released kinetic level ends it at its zero, by the sliding-friction margin (a domain
// boundary), not at its range's minimum.
void BoundReleasedParameters(const OrbitContinuationParts& parts, ContinuationOptions* options) {
  for (std::size_t i = 0; i < parts.free.size(); ++i) {
    const int variable = parts.free[i];
    PhysicalBounds b = PhysicalBoundsOf(parts, variable);
    if (variable == parts.variables.kinetic_level) b.min = -std::numeric_limits<double>::infinity();
    if (std::isfinite(b.min) || std::isfinite(b.max)) {
      options->unknown_bounds.push_back({.index = static_cast<int>(i), .min = b.min, .max = b.max,
                                         .name = parts.variables.layout.Name(variable)});
    }
  }
}

// The condition's equations in the unknowns of the periodicity equations.
class ConditionEquations final : public ExtraEquations {
 public:
  ConditionEquations(const OrbitProblem& system, std::shared_ptr<const OrbitCondition> condition)
      : system_(system), condition_(std::move(condition)) {}
  int UnknownCount() const override { return condition_->ExtraUnknownCount(); }
  int EquationCount() const override { return condition_->EquationCount(); }
  void Evaluate(const Eigen::VectorXd& u, const Eigen::VectorXd& e, Eigen::VectorXd* residual, Eigen::MatrixXd* d_u,
                Eigen::MatrixXd* d_e) const override {
    Eigen::MatrixXd d_variables;
    condition_->Evaluate(system_, u, e, residual, d_u ? &d_variables : nullptr, d_e);
    if (d_u) *d_u = system_.ToUnknowns(d_variables);
  }

 private:
  const OrbitProblem& system_;
  std::shared_ptr<const OrbitCondition> condition_;
};

}  // namespace

const NonlinearSystem& OrbitContinuationProblem::Continued() const {
  if (augmented) return *augmented;
  return *system;
}

void CheckResonanceLimits(double max_amplitude, double resonance_approach) {
  if (!(max_amplitude > 0.0)) throw InvalidInput("max_amplitude", max_amplitude, "max_amplitude > 0");
  if (!(resonance_approach >= 0.0 && resonance_approach < 1.0)) {
    throw InvalidInput("resonance_approach", resonance_approach, "0 <= resonance_approach < 1");
  }
}

OrbitContinuationProblem AssembleOrbitContinuation(OrbitContinuationParts parts) {
  OrbitContinuationProblem problem;
  std::vector<std::string> unwatched = parts.unwatched;
  std::vector<WatchedColumn> watched;
  if (parts.condition) {
    watched = parts.condition->CodimensionTwoTests();
    problem.extra = std::make_unique<ConditionEquations>(*parts.system, parts.condition);
    problem.augmented = std::make_unique<AugmentedSystem>(*parts.system, *problem.extra);
    for (std::string& name : parts.condition->Defining()) unwatched.push_back(std::move(name));
  }
  problem.start = parts.system->Unknowns(parts.start);
  problem.monitor = std::make_unique<OrbitMonitor>(*parts.system, problem.start, std::move(unwatched), std::move(watched));
  problem.options = parts.options;
  problem.options.parameter_index = static_cast<int>(parts.free.size());
  problem.options.parameter_name = parts.parameter_name;
  KeepInPhysicalRanges(parts, &problem.options);
  if (parts.condition) BoundReleasedParameters(parts, &problem.options);
  if (parts.system->shooting() == Shooting::kMultiple &&
      problem.options.corrector.linear_solver == LinearSolverType::kDenseLu) {
    problem.options.corrector.linear_solver = parts.sparse_solver;
  }
  if (parts.condition) {
    problem.start.conservativeResize(problem.start.size() + parts.condition_start.size());
    problem.start.tail(parts.condition_start.size()) = parts.condition_start;
  }
  problem.system = std::move(parts.system);
  return problem;
}

template OrbitContinuationProblem MakeOrbitContinuation(const OrbitContinuationSetup& setup);
template OrbitBranch ToOrbitBranch<Pascal2014>(const OrbitContinuationProblem& problem, Branch branch);

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

OrbitContinuation::OrbitContinuation(OrbitContinuationProblem problem, double max_amplitude, double resonance_approach)
    : problem_(std::move(problem)),
      continuation_(std::make_unique<Continuation>(problem_.Continued(), problem_.monitor.get(), problem_.options,
                                                   problem_.start)),
      max_amplitude_(max_amplitude),
      resonance_approach_(resonance_approach) {
  const std::vector<std::string>& coordinates = problem_.system->description().coordinates;
  for (const std::string& coordinate : coordinates) {
    const std::string name = orbit_columns::AmplitudeOf(coordinate);
    const std::vector<PointColumn>& columns = problem_.monitor->Columns();
    const auto column = std::find_if(columns.begin(), columns.end(),
                                     [&](const PointColumn& c) { return c.name == name && !c.monitored; });
    if (column == columns.end()) throw std::logic_error("the orbit monitor records no " + name);
    amplitudes_.push_back(column->index);
  }
  amplitude_name_ = fmt::format("max(|{}|)", fmt::join(coordinates, "|, |"));
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

// The largest coordinate amplitude over the orbit as the monitor recorded it, exact; nan where undefined.
double OrbitContinuation::Amplitude(const BranchPoint& point) const {
  double amplitude = 0.0;
  for (int index : amplitudes_) {
    const double x = point.recorded(index);
    if (std::isnan(x)) return x;
    amplitude = std::max(amplitude, x);
  }
  return amplitude;
}

std::optional<BranchStop> OrbitContinuation::AmplitudeBound(const BranchPoint& point, bool start) const {
  // nan (no bound) stops too.
  const double amplitude = Amplitude(point);
  if (amplitude <= max_amplitude_) return std::nullopt;
  return BranchStop{0, BranchEnd::kStopped,
                    fmt::format("resonance: the amplitude {} = {:.6g} {} max_amplitude = {:g} at "
                                "{} = {:.10g}{}",
                                amplitude_name_, amplitude, start ? "of the start is above" : "passed", max_amplitude_, problem_.options.parameter_name,
                                point.lambda, start ? " (a larger max_amplitude continues it)" : "")};
}

// Approaching: nearer than at the point before, the amplitude larger (the start only sets both,
// so that a branch starting near a resonance may leave it). A branch whose amplitude falls as it
// nears omega_k is bounded there (a large enough u_s folds it back): it goes on.
std::optional<BranchStop> OrbitContinuation::SlipResonanceApproached(const BranchPoint& point, bool start) {
  const std::optional<SlipResonance> near = problem_.system->NearestSlipResonance(point.u);
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
                                near->index, near->frequency, near->distance, resonance_approach_, problem_.options.parameter_name,
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

OrbitBranch ContinueOrbit(const OrbitContinuationSetup& setup, const std::function<void(const Branch&)>& observer) {
  return ContinueOrbit<Pascal2014>(setup, observer);
}

}  // namespace stickslip
