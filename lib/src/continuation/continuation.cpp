#include "stickslip/continuation/continuation.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "arclength_corrector.hpp"
#include "event_location.hpp"
#include "events.hpp"

namespace stickslip {

const char* ToString(BranchEnd end) {
  switch (end) {
    case BranchEnd::kRunning: return "running";
    case BranchEnd::kMaxPoints: return "max-points";
    case BranchEnd::kParameterBound: return "parameter-bound";
    case BranchEnd::kStepTooSmall: return "step-too-small";
    case BranchEnd::kTerminalEvent: return "terminal-event";
    case BranchEnd::kStartFailed: return "start-failed";
    case BranchEnd::kStartOutsideRange: return "start-outside-range";
    case BranchEnd::kFoldAtStart: return "fold-at-start";
    case BranchEnd::kStopped: return "stopped";
    case BranchEnd::kClosedLoop: break;
  }
  return "closed-loop";
}

void ClosedLoopOptions::Validate() const {
  if (!(tolerance > 0.0 && tolerance < 1.0)) throw InvalidInput("closed_loop.tolerance", tolerance, "0 < tolerance < 1");
  if (!(alignment > 0.0 && alignment <= 1.0)) throw InvalidInput("closed_loop.alignment", alignment, "0 < alignment <= 1");
  if (!(departure >= 1.0 && departure <= 1e6)) {
    throw InvalidInput("closed_loop.departure", departure, "1 <= departure <= 1e6");
  }
  if (!(landing > 0.0 && landing <= 1e-3)) throw InvalidInput("closed_loop.landing", landing, "0 < landing <= 1e-3");
}

void ContinuationOptions::Validate() const {
  if (parameter_index < 0) throw InvalidInput("parameter_index", parameter_index, "parameter_index >= 0");
  if (direction != 1 && direction != -1) throw InvalidInput("direction", direction, "+1 or -1");
  step.Validate();
  if (!(lambda_min < lambda_max)) {
    throw InvalidInput("lambda_min", lambda_min, fmt::format("lambda_min < lambda_max ({})", lambda_max));
  }
  if (max_points < 1) throw InvalidInput("max_points", max_points, "max_points >= 1");
  if (start_iterations < 1) throw InvalidInput("start_iterations", start_iterations, "start_iterations >= 1");
  // Any length: the norm may overflow (components of 1e300) or underflow (1e-300) where the vector does not.
  if (start_direction.size() > 0 && !(start_direction.allFinite() && start_direction.cwiseAbs().maxCoeff() > 0.0)) {
    throw InvalidInput("start_direction", start_direction.stableNorm(), "a finite nonzero vector, or empty");
  }
  if (!(bound_tolerance >= 0.0)) throw InvalidInput("bound_tolerance", bound_tolerance, "bound_tolerance >= 0");
  if (!(start_boundary_tolerance >= 0.0)) {
    throw InvalidInput("start_boundary_tolerance", start_boundary_tolerance, "start_boundary_tolerance >= 0");
  }
  if (!(location.tolerance > 0.0)) throw InvalidInput("location.tolerance", location.tolerance, "> 0");
  if (location.corrector_iterations < 1) {
    throw InvalidInput("location.corrector_iterations", location.corrector_iterations, ">= 1");
  }
  if (location.max_iterations < 1) throw InvalidInput("location.max_iterations", location.max_iterations, ">= 1");
  if (!(location.same_point >= 0.0)) throw InvalidInput("location.same_point", location.same_point, ">= 0");
  if (!(location.fold_noise >= 0.0)) throw InvalidInput("location.fold_noise", location.fold_noise, ">= 0");
  closed_loop.Validate();
  for (const UnknownBound& b : unknown_bounds) {
    if (b.index < 0 || b.index == parameter_index) {
      throw InvalidInput("unknown_bounds.index", b.index, "an unknown's index >= 0, not parameter_index (lambda_min/max bound it)");
    }
    if (!(b.min < b.max)) throw InvalidInput("unknown_bounds.min", b.min, fmt::format("min < max ({})", b.max));
  }
}

// The setup, fixed for the branch (options, corrector, step-size controller, events), and the
// per-step state (the last point, the next one, the step size).
struct Continuation::State {
  ContinuationOptions options;
  detail::ArclengthCorrector corrector;
  std::unique_ptr<StepSizeController> step_size;
  std::vector<detail::Event> events;
  Eigen::VectorXd start;
  detail::Sample last;      // the last accepted point
  double ds = 0.0;          // the next step to try
  detail::Sample next;      // the step's corrected point, not yet accepted
  double next_ds = 0.0;     // ... at this arclength from the last
  double asked_ds = 0.0;    // ... by a step of this length, before a clip onto a bound
  bool on_bound = false;    // ... put exactly on a parameter bound
  bool on_upper = false;    // ... lambda_max (else lambda_min)
  bool closes_loop = false;  // ... the start again: the branch is closed
  // For ClosedLoopOptions: the start as the branch left it (its tangent oriented by the first
  // step), the farthest any point lay from it, and the longest step so far.
  Eigen::VectorXd start_u, start_tangent;
  double farthest = 0.0;
  double longest_step = 0.0;
  bool started = false;
  bool ended = false;

  State(const NonlinearSystem& problem, const Monitor* monitor, ContinuationOptions o, Eigen::VectorXd s,
        std::unique_ptr<StepSizeController> controller, const std::vector<TestFunctionInfo>& monitored)
      : options(std::move(o)), corrector(problem, monitor, options),
        step_size(controller ? std::move(controller) : StepSizeController::Create(options.step)),
        events(detail::MakeEvents(options, monitored)), start(std::move(s)) {}

  double Lambda(const Eigen::VectorXd& u) const { return u(options.parameter_index); }
};

namespace {

BranchPoint MakePoint(const detail::Sample& s, double lambda, double ds, std::string label) {
  return {s.u, lambda, ds, s.iterations, s.tests, s.recorded, s.tangent, std::move(label)};
}

// The special point at the branch's last point.
void MarkLastPoint(Branch* b, std::string type, std::string test_function, double value = 0.0, bool located = true,
                   double bracket = 0.0) {
  const BranchPoint& p = b->points.back();
  b->special_points.push_back({std::move(type), std::move(test_function), static_cast<int>(b->points.size()) - 1,
                               p.lambda, p.u, p.tests, value, located, bracket, p.tangent});
}

}  // namespace

Continuation::Continuation(const NonlinearSystem& problem, const Monitor* monitor, ContinuationOptions options,
                           Eigen::VectorXd start, std::unique_ptr<StepSizeController> step_size) {
  options.Validate();
  if (problem.UnknownCount() != problem.EquationCount() + 1) {
    throw std::invalid_argument(fmt::format(
        "continuation needs one unknown more than equations: {} equations, {} unknowns",
        problem.EquationCount(), problem.UnknownCount()));
  }
  if (start.size() != problem.UnknownCount()) {
    throw std::invalid_argument(fmt::format("the start point has {} unknowns, the problem {}", start.size(),
                                            problem.UnknownCount()));
  }
  if (options.start_direction.size() != 0 && options.start_direction.size() != start.size()) {
    throw std::invalid_argument(fmt::format("start_direction has {} components, the problem {} unknowns",
                                            options.start_direction.size(), start.size()));
  }
  for (const UnknownBound& b : options.unknown_bounds) {
    if (b.index >= start.size()) {
      throw InvalidInput("unknown_bounds.index", b.index, fmt::format("0 <= index < {} (the unknowns)", start.size()));
    }
  }
  if (options.parameter_index >= start.size()) {
    throw InvalidInput("parameter_index", options.parameter_index,
                       fmt::format("0 <= parameter_index < {} (the unknowns)", start.size()));
  }
  if (monitor) {
    branch_.test_functions = monitor->TestFunctions();
    branch_.recorded = monitor->RecordedNames();
  }
  state_ = std::make_unique<State>(problem, monitor, std::move(options), std::move(start), std::move(step_size),
                                   branch_.test_functions);
}

Continuation::~Continuation() = default;

bool Continuation::Step() {
  if (state_->ended) return false;
  if (!state_->started) return Start();
  return PredictAndCorrect() && HeadsTheAskedWay() && LeavesTheStartOnThePositiveSides() && ClosesTheLoop() &&
         RecordEvents() && Accept();
}

Branch Continuation::Run() {
  while (Step()) {
  }
  return branch_;
}

namespace {

// Whether the branch ends on an end point its last step located (a parameter bound, a family's
// end: an EP test function): that EP is the end, one end label a point, and the branch's end
// and message say why. A start is no such point: a branch that ends there gets its end's EP.
bool EndsOnALocatedEndPoint(const Branch& b) {
  if (b.special_points.empty()) return false;
  const SpecialPoint& s = b.special_points.back();
  return s.type == "EP" && s.test_function != "start" && s.point == static_cast<int>(b.points.size()) - 1;
}

// " (F_k <= F_s = 0.4)": the reason of the upper or lower parameter bound, where there is one.
std::string BoundReason(const ContinuationOptions& o, bool upper) {
  const std::string& reason = upper ? o.lambda_max_reason : o.lambda_min_reason;
  return reason.empty() ? "" : " (" + reason + ")";
}

// "reached omega = 0.69": a bound's end message (10 digits: a located bound of another unknown
// lies within rounding of it), with the parameter bound's reason.
std::string BoundReached(const std::string& name, double value, const std::string& reason = "") {
  return fmt::format("reached {} = {:.10g}{}", name, value, reason);
}

std::string MaxPointsReached(const ContinuationOptions& o, double lambda) {
  return fmt::format("max_points = {} reached at {} = {:.10g}", o.max_points, o.parameter_name, lambda);
}

}  // namespace

bool Continuation::End(BranchEnd why, std::string message) {
  state_->ended = true;
  branch_.end = why;
  branch_.end_message = std::move(message);
  if (!branch_.points.empty() && !EndsOnALocatedEndPoint(branch_)) {
    if (branch_.points.back().label.empty()) branch_.points.back().label = "EP";
    MarkLastPoint(&branch_, "EP", ToString(why));
  }
  return false;
}

bool Continuation::Start() {
  State& st = *state_;
  const ContinuationOptions& o = st.options;
  st.started = true;
  std::optional<detail::Sample> start = st.corrector.Start(st.start);
  if (!start) return End(BranchEnd::kStartFailed, st.corrector.last_failure());
  st.last = std::move(*start);
  st.ds = st.step_size->Initial();
  branch_.points.push_back(MakePoint(st.last, st.Lambda(st.last.u), 0.0, "EP"));
  // Seen from the first step, a terminal function on its zero is on it exactly (the stored start
  // keeps its computed values).
  for (int k = 0; k < st.last.tests.size(); ++k) {
    if (branch_.test_functions[k].terminal && std::abs(st.last.tests(k)) <= o.start_boundary_tolerance) {
      st.last.tests(k) = 0.0;
    }
  }
  MarkLastPoint(&branch_, "EP", "start");
  Report();
  const double lambda = st.Lambda(st.last.u);
  if (lambda < o.lambda_min || lambda > o.lambda_max) {
    const bool below = lambda < o.lambda_min;
    const std::string& reason = below ? o.lambda_min_reason : o.lambda_max_reason;
    const std::string bound = fmt::format("{} {} {:.10g}", o.parameter_name, below ? ">=" : "<=", below ? o.lambda_min : o.lambda_max);
    return End(BranchEnd::kStartOutsideRange, fmt::format("the start, {} = {:.10g}, lies outside the parameter range ({})",
                                                          o.parameter_name, lambda, reason.empty() ? bound : reason));
  }
  if (o.max_points <= 1) return End(BranchEnd::kMaxPoints, MaxPointsReached(o, st.Lambda(st.last.u)));
  return true;
}

// A step that would cross a parameter bound is shortened to end on it, so that a bound at the
// edge of the problem's domain can be reached.
bool Continuation::PredictAndCorrect() {
  State& st = *state_;
  const ContinuationOptions& o = st.options;
  double ds = st.ds;
  while (true) {
    if (ds < o.step.ds_min) {
      return End(BranchEnd::kStepTooSmall,
                 fmt::format("the corrector failed down to ds = {:.3e} < ds_min = {:.3e} at {} = {:.10g}; last "
                             "failure: {}",
                             ds, o.step.ds_min, o.parameter_name, st.Lambda(st.last.u), st.corrector.last_failure()));
    }
    const double rate = st.last.tangent(o.parameter_index);
    const double bound = rate > 0.0 ? o.lambda_max : o.lambda_min;
    const double to_bound = rate != 0.0 ? (bound - st.Lambda(st.last.u)) / rate : ds;
    // Standing on the bound and heading out of the range (a start on a range end): done.
    if (rate != 0.0 && to_bound <= 0.0) {
      return End(BranchEnd::kParameterBound,
                 fmt::format("at the bound {} = {:.10g}{}", o.parameter_name, st.Lambda(st.last.u),
                             BoundReason(o, rate > 0.0)));
    }
    // Only a finite bound can be reached (and tolerance times an infinite bound is no test).
    const bool clipped = rate != 0.0 && std::isfinite(bound) && to_bound <= ds;
    if (std::optional<detail::Sample> next = st.corrector.Corrected(st.last, clipped ? to_bound : ds,
                                                                    detail::Attempt::kStep)) {
      st.next = std::move(*next);
      st.next_ds = clipped ? to_bound : ds;
      st.asked_ds = ds;
      // The corrector keeps lambda on the bound only to second order in the step; where it lands
      // within rounding of it, the point is put on it, and the bound event records it. If that
      // fails, the branch still ends on the corrected point.
      st.on_bound = clipped && std::abs(st.Lambda(st.next.u) - bound) <= o.bound_tolerance * (1.0 + std::abs(bound));
      st.on_upper = rate > 0.0;
      if (st.on_bound) {
        if (std::optional<detail::Sample> exact = st.corrector.OnBound(st.last, st.next, bound)) {
          st.next = std::move(*exact);
        }
      }
      return true;
    }
    ds = st.step_size->OnRejected(ds);
    st.ds = ds;
  }
}

// A start on a fold (a restart from an LP) has a tangent across the lambda axis, oriented at
// random: the first step shows which way lambda runs. Against the asked direction the other side
// is tried; where both run that way, the branch folds at the start and goes no further this way.
bool Continuation::HeadsTheAskedWay() {
  State& st = *state_;
  const ContinuationOptions& o = st.options;
  if (branch_.points.size() != 1 || std::abs(st.last.tangent(o.parameter_index)) > o.location.fold_noise) return true;
  auto heads_right = [&] { return (st.Lambda(st.next.u) - st.Lambda(st.last.u)) * o.direction >= 0.0; };
  if (heads_right()) return true;
  st.last.tangent = -st.last.tangent;
  if (!PredictAndCorrect()) return false;
  if (heads_right()) return true;
  return End(BranchEnd::kFoldAtStart,
             fmt::format("the branch folds at the start, {0} = {1:.10g}: on both sides it runs towards {2} {0}",
                         o.parameter_name, st.Lambda(st.last.u), o.direction > 0 ? "decreasing" : "increasing"));
}

// A start may lie on a terminal function's zero (on a type boundary: an orbit with a segment of
// zero length). That is no sign change, but where the first step makes it negative the branch
// beyond is on the wrong side: it ends at the start.
bool Continuation::LeavesTheStartOnThePositiveSides() {
  State& st = *state_;
  if (branch_.points.size() != 1) return true;  // a later zero was counted by the step reaching it
  for (const detail::Event& e : st.events) {
    if (!e.terminal || e.g(st.last) != 0.0 || !(e.g(st.next) < 0.0)) continue;
    MarkLastPoint(&branch_, e.type, e.name);
    return End(BranchEnd::kTerminalEvent,
               fmt::format("{} ({}) is zero at the start and the first step leaves its {} side", e.name, e.type,
                           e.positive_side));
  }
  return true;
}

// The step from the last point to the next passes the start (within the tolerance of its chord,
// heading the way the branch left the start), after the branch has been away from it: the loop is
// closed. The step is taken again, onto the start: from the last point at the arclength where the
// start lies along the last tangent, so that the corrector lands on the start itself and the
// special points before it are located as on any step.
bool Continuation::ClosesTheLoop() {
  State& st = *state_;
  const ClosedLoopOptions& o = st.options.closed_loop;
  if (branch_.points.size() == 1) {
    st.start_u = st.last.u;
    st.start_tangent = st.last.tangent;  // oriented along the branch by HeadsTheAskedWay
  }
  const Eigen::VectorXd chord = st.next.u - st.last.u;
  const double length = chord.norm();
  st.longest_step = std::max(st.longest_step, length);
  if (!o.detect || !(st.farthest > o.departure * st.longest_step) || !(length > 0.0)) return true;
  const Eigen::VectorXd to_start = st.start_u - st.last.u;
  const double along = std::clamp(to_start.dot(chord) / (length * length), 0.0, 1.0);
  if (!((to_start - along * chord).norm() <= o.tolerance * length)) return true;
  if (!(st.start_tangent.dot(chord) >= o.alignment * length)) return true;
  // The step onto the start must land on it: a sheet of the branch that merely passes near the
  // start (a thin Z, its sheets closer than a step) lands elsewhere, and the step stands as it was.
  const double s = st.last.tangent.dot(to_start);
  if (!(s > 0.0)) return true;
  std::optional<detail::Sample> onto = st.corrector.Corrected(st.last, s, detail::Attempt::kStep);
  if (!onto || !((onto->u - st.start_u).norm() <= o.landing * (1.0 + st.start_u.norm()))) return true;
  st.next = std::move(*onto);
  st.next_ds = s;
  st.on_bound = false;
  st.closes_loop = true;
  return true;
}

void Continuation::Report() const {
  const State& st = *state_;
  if (!st.options.progress) return;
  st.options.progress({static_cast<double>(branch_.points.size()), static_cast<double>(st.options.max_points),
                       "points", branch_.points.back().lambda});
}

namespace {

// A step that crosses a bound of the parameter locates it only to the location's tolerance (a few
// ulps past it, outside the range): the point is put on it, as a clipped step's end is, where the
// corrector at the fixed bound converges.
detail::Sample OnParameterBound(const ContinuationOptions& o, detail::ArclengthCorrector& corrector,
                                const detail::Sample& last, const detail::Event& event, const detail::Sample& located) {
  if (!event.bound || event.bound_index != o.parameter_index) return located;
  const double bound = event.name == "lambda_max" ? o.lambda_max : o.lambda_min;
  std::optional<detail::Sample> exact = corrector.OnBound(last, located, bound);
  return exact ? std::move(*exact) : located;
}

}  // namespace

bool Continuation::RecordEvents() {
  State& st = *state_;
  const EventLocationOptions& location = st.options.location;
  for (const std::vector<detail::Located>& point :
       detail::DetectAndLocate(st.events, st.last, st.next, st.next_ds, st.corrector, location)) {
    // A restart from a special point finds it again at the start (a TR, an LP): it is the
    // start's own, no new one.
    if (branch_.points.size() == 1 && point.front().s <= location.same_point * location.tolerance) continue;
    // Likewise at the end of a closed branch: the step onto the start finds the start's own.
    if (st.closes_loop && st.next_ds - point.front().s <= location.same_point * location.tolerance) continue;
    std::optional<std::pair<BranchEnd, std::string>> ending;
    for (const detail::Located& l : point) {
      const detail::Event& e = *l.event;
      const detail::Sample sample = OnParameterBound(st.options, st.corrector, st.last, e, l.sample);
      branch_.points.push_back(MakePoint(sample, st.Lambda(sample.u), 0.0, e.type));
      MarkLastPoint(&branch_, e.type, e.name, l.value, l.located, l.bracket);
      if (ending) continue;
      if (e.bound) {
        const bool on_parameter = e.bound_index == st.options.parameter_index;
        ending.emplace(BranchEnd::kParameterBound,
                       BoundReached(e.bound_name, sample.u(e.bound_index),
                                    on_parameter ? BoundReason(st.options, e.name == "lambda_max") : ""));
      } else if (e.terminal && l.value_before > 0.0) {
        // A terminal function ends the branch only when it leaves its positive side.
        ending.emplace(BranchEnd::kTerminalEvent,
                       fmt::format("{} ({}) left its {} side", e.name, e.type, e.positive_side));
      }
    }
    if (ending) return End(ending->first, ending->second);
  }
  return true;
}

bool Continuation::Accept() {
  State& st = *state_;
  // An event recorded at the step's end (not located inside the step) put this point on the branch
  // already: once is enough.
  if (branch_.points.empty() || branch_.points.back().u != st.next.u) {
    branch_.points.push_back(MakePoint(st.next, st.Lambda(st.next.u), st.next_ds, ""));
  }
  st.farthest = std::max(st.farthest, (st.next.u - st.start_u).norm());
  Report();
  if (st.closes_loop) {
    return End(BranchEnd::kClosedLoop,
               fmt::format("the branch came back to its start, {} = {:.10g}, after {} points: a closed branch",
                           st.options.parameter_name, st.Lambda(st.next.u), branch_.points.size() - 1));
  }
  if (st.on_bound) {
    return End(BranchEnd::kParameterBound, BoundReached(st.options.parameter_name, st.Lambda(st.next.u),
                                                        BoundReason(st.options, st.on_upper)));
  }
  // A clip onto a bound is no sign of difficulty: the next step grows from the asked one, so that
  // a clipped step that lands short of the bound is not followed by one below ds_min.
  st.ds = st.step_size->OnAccepted(st.asked_ds, st.next.iterations);
  st.last = std::move(st.next);
  if (static_cast<int>(branch_.points.size()) >= st.options.max_points) {
    return End(BranchEnd::kMaxPoints, MaxPointsReached(st.options, st.Lambda(st.last.u)));
  }
  return true;
}

}  // namespace stickslip
