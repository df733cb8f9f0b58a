// TraceOrbits and AtLeastPeriod (trace.hpp) for any model (model/oscillator_model.hpp). The
// paper's model is compiled once, in trace.cpp, a [model]'s (DynamicLinearOscillator) in
// model_trace.cpp; a program or test tracing another model's orbits includes this header.
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "stickslip/branches/model_bifurcation_branches.hpp"
#include "stickslip/branches/model_type_switch.hpp"
#include "stickslip/branches/trace.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/orbits/linear_oscillator_problem.hpp"
#include "stickslip/orbits/least_period.hpp"
#include "stickslip/orbits/margins.hpp"

namespace stickslip {

namespace trace_detail {


const char* DirectionName(int direction);
bool IsMarginChange(const SpecialPoint& s);
bool IsFamilyEnd(const SpecialPoint* s);
// How a branch's end ends its link, where it is no change of type (kTerminalEvent: decided there).
TraceEnd LinkEndOf(BranchEnd end);
// The margins' sign changes located at the end of `branch`: several events at one place are
// stored as consecutive points of the same orbit (EventLocationOptions::same_point).
std::vector<const SpecialPoint*> ChangesAtEnd(const Branch& branch, double loop_tolerance);

// The continued variable's value on `orbit`.
template <OscillatorModel Model>
double Lambda(const Model& model, const OrbitOfModel<Model>& orbit, const std::string& parameter) {
  const OrbitLayout layout(model.Description(), orbit.signature.size());
  return VariableOf(model, AsBasicOrbit(orbit), *layout.IndexOf(parameter));
}

// One branch of the chain, stepped by hand: it stops at a resonance, and, `to_next_change`, at the
// first located sign change of a margin after its start (the branch then goes past its type
// changes, continue_past_terminal).
template <OscillatorModel Model>
class BranchRunner {
 public:
  BranchRunner(const TraceOptions& options, double total) : options_(options), total_(total) {}

  BasicOrbitBranch<Model> Run(BasicOrbitContinuationSetup<Model> setup, bool to_next_change) {
    setup.options.continue_past_terminal = to_next_change;
    setup.options.progress = {};
    OrbitContinuation continuation(setup);
    std::size_t counted = 0;
    std::size_t special_checked = 0;
    for (bool more = true; more;) {
      more = continuation.Step();
      const Branch& b = continuation.branch();
      // Ended at a resonance (its last point): a change of type before it ends the branch first.
      const bool resonance = b.end == BranchEnd::kStopped;
      const int last = static_cast<int>(b.points.size()) - 1;
      std::optional<BranchStop> stop;
      for (; counted < b.points.size(); ++counted) {
        done_ += 1.0;
        if (options_.progress) options_.progress({done_, std::max(total_, done_), "points", b.points[counted].lambda});
      }
      for (; to_next_change && special_checked < b.special_points.size(); ++special_checked) {
        const SpecialPoint& s = b.special_points[special_checked];
        if (!IsMarginChange(s) || s.point == 0 || (resonance && s.point >= last)) continue;
        // The change the branch starts on, located again a rounding error away (its margin is zero
        // there only to the location's tolerance): no change of its own.
        const Eigen::VectorXd& u0 = b.points.front().u;
        if ((s.u - u0).lpNorm<Eigen::Infinity>() <= options_.loop_tolerance * (1.0 + u0.lpNorm<Eigen::Infinity>())) {
          continue;
        }
        stop = BranchStop{s.point, BranchEnd::kTerminalEvent,
                          fmt::format("{} ({}) changed sign at {} = {:.10g}", s.test_function, s.type,
                                      setup.parameter, s.lambda)};
        break;
      }
      if (stop) return ToOrbitBranch<Model>(continuation.problem(), EndedAt(b, *stop));
    }
    return continuation.template Result<Model>();
  }

 private:
  const TraceOptions& options_;
  double total_ = 0.0;
  double done_ = 0.0;
};

// A point the chain visited: where a branch began or ended.
template <OscillatorModel Model>
struct Visit {
  std::string signature;
  double lambda = 0.0;
  OrbitOfModel<Model> orbit;
  int direction = 0;  // 0 down, 1 up
  int link = 0;       // 0-based in its direction's chain
  bool end = false;   // a branch's end, else its start
};

// What the next branch of a direction is.
template <OscillatorModel Model>
struct Next {
  explicit Next(BasicOrbitContinuationSetup<Model> first) : setup(std::move(first)) {}
  BasicOrbitContinuationSetup<Model> setup;
  LinkStart start = LinkStart::kTraceStart;
  std::string margin;
  std::optional<BasicTypeSwitch<Model>> type_switch;
  bool past = false;  // the same type followed past its change, up to the next margin's sign change
};

template <OscillatorModel Model>
class Tracer {
 public:
  using AnyOrbit = OrbitOfModel<Model>;
  using Setup = BasicOrbitContinuationSetup<Model>;
  using OrbitBranch = BasicOrbitBranch<Model>;
  using TypeSwitch = BasicTypeSwitch<Model>;

  Tracer(const Setup& start, const TraceOptions& options)
      : start_(start),
        options_(options),
        runner_(options, 2.0 * options.max_branches * start.options.max_points),
        next_{Next<Model>(start), Next<Model>(start)} {
    result_.parameter = start.parameter;
    for (Next<Model>& next : next_) next.setup.max_amplitude = options.max_amplitude;  // every branch's, followed ones too
    next_[0].setup.options.direction = -1;
    next_[1].setup.options.direction = 1;
  }

  BasicTraceResult<Model> Run() {
    if (!options_.allow_inadmissible) {
      if (std::optional<std::string> why = StartIsNoMotion()) {
        for (int d = 0; d < 2; ++d) End(d, TraceEnd::kNotAMotion, *why);
        return std::move(result_);
      }
    }
    // Each round adds a branch to every running direction, and a direction holds at most
    // max_branches: at most max_branches rounds.
    for (int round = 0; round < options_.max_branches && (running_[0] || running_[1]); ++round) {
      for (int d = 0; d < 2; ++d) {
        if (running_[d]) Advance(d);
      }
    }
    return std::move(result_);
  }

 private:
  BasicTraceDirection<Model>& Chain(int d) { return d == 0 ? result_.down : result_.up; }

  // Why the start, solved at its parameter as `stickslip solve` solves it, is not a motion of the
  // system (a margin below -start_boundary_tolerance: a start on a type boundary, a restart from a
  // change of type, is one); nullopt when it is, or when it does not converge (the trace's first
  // branch then reports that).
  std::optional<std::string> StartIsNoMotion() const {
    OrbitSolverOptions solver;
    solver.shooting = start_.shooting;
    solver.sparse_solver = start_.sparse_solver;
    const BasicOrbitSolution<Model> solved =
        SolveOrbit<Model>(model(), start_.start, FreeIndices(VariableSetOf(model(), start_.start.signature), start_.unknowns),
                          start_.unknowns.tie_static_friction, solver);
    if (!solved.summary.Converged()) return std::nullopt;
    const Margin smallest = SmallestMargin(AdmissibilityMargins(model(), AsBasicOrbit(solved.orbit)));
    if (!(smallest.value < -start_.options.start_boundary_tolerance)) return std::nullopt;
    return fmt::format("the start is not a motion of the system: margin {} = {:.6g} < 0 at {} = {:.10g} ('{}'); "
                       "allow_inadmissible traces it all the same",
                       smallest.Name(), smallest.value, start_.parameter, Lambda(model(), solved.orbit, start_.parameter),
                       solved.orbit.signature.ToString());
  }

  void End(int d, TraceEnd end, std::string message) {
    running_[d] = false;
    Chain(d).end = end;
    Chain(d).message = std::move(message);
  }

  std::optional<Visit<Model>> Visited(const AnyOrbit& orbit, double lambda, int d, int link) const {
    const double tolerance = options_.loop_tolerance;
    const std::string signature = orbit.signature.ToString();
    for (const Visit<Model>& v : visits_) {
      if (v.direction == d && v.link == link) continue;  // this branch's own start
      // The trace's start, where both directions' first branches begin: a first branch that ends
      // there met a change of type at the start, no loop.
      if (link == 0 && v.link == 0 && !v.end) continue;
      if (v.signature != signature) continue;
      if (!(std::abs(v.lambda - lambda) <= tolerance * (1.0 + std::abs(lambda)))) continue;
      if (OrbitDistance(model(), AsBasicOrbit(v.orbit), AsBasicOrbit(orbit)) <= tolerance) return v;
    }
    return std::nullopt;
  }

  // The next branch of direction d follows the same type on from the end of `branch`, the way
  // the branch was going.
  void SameTypeOn(int d, const OrbitBranch& branch, const Setup& setup, LinkStart how,
                  std::string margin, std::optional<TypeSwitch> type_switch) {
    const BranchPoint& end = branch.branch.points.back();
    const int lambda = type_switch_detail::ParameterUnknown(setup, branch.orbits.back().signature);
    const double along = end.tangent.size() > lambda ? end.tangent(lambda) : 0.0;
    Next<Model>& next = next_[d];
    next.setup = setup;
    next.setup.start = branch.orbits.back();
    next.setup.options.direction = along > 0.0 ? 1 : along < 0.0 ? -1 : setup.options.direction;
    next.start = how;
    next.margin = std::move(margin);
    next.type_switch = std::move(type_switch);
    next.past = how == LinkStart::kFollowedPast;
  }

  // Whether every margin of `orbit` but `crossed` is positive, and `crossed` was negative before
  // the end of the branch: the orbit is a motion again on the branch's way on.
  bool AdmissibleAgain(const OrbitBranch& branch, const std::string& crossed) const {
    for (const Margin& m : AdmissibilityMargins(model(), AsBasicOrbit(branch.orbits.back()))) {
      if (std::string(orbit_columns::kMarginPrefix) + m.Name() != crossed && !(m.value > 0.0)) return false;
    }
    const std::vector<TestFunctionInfo>& functions = branch.branch.test_functions;
    const auto function = std::find_if(functions.begin(), functions.end(),
                                       [&](const TestFunctionInfo& f) { return f.name == crossed; });
    const std::size_t last = branch.branch.points.size() - 1;
    if (function == functions.end() || last == 0) return false;
    return branch.branch.points[last - 1].tests(function - functions.begin()) < 0.0;
  }

  // The branches that leave the located BP, PD and SB of `branch`: where each starts, and the
  // branch itself while fewer than follow_bifurcations have been followed.
  std::vector<BasicBifurcationMet<Model>> BifurcationsOn(const OrbitBranch& branch, const Setup& setup) {
    std::vector<BasicBifurcationMet<Model>> met;
    for (const SpecialPoint& s : branch.branch.special_points) {
      if (!s.located || (s.type != "BP" && s.type != "PD" && s.type != "SB")) continue;
      BasicBifurcationMet<Model> m;
      m.point = s.point;
      m.type = s.type;
      m.lambda = s.lambda;
      try {
        const BasicBifurcationBranchStart<Model> start = BranchFromBifurcation(s, setup);
        m.signature = start.at.signature.ToString();
        m.singularity = start.singularity;
        if (followed_ < options_.follow_bifurcations) {
          ++followed_;
          Setup follow = start.setup;
          follow.options.progress = {};
          m.followed = ContinueOrbit(follow);
        }
      } catch (const std::exception& e) {
        m.message = e.what();
      }
      met.push_back(std::move(m));
    }
    return met;
  }

  void Advance(int d) {
    BasicTraceDirection<Model>& chain = Chain(d);
    Next<Model>& next = next_[d];
    OrbitBranch branch = runner_.Run(next.setup, next.past);
    if (branch.orbits.empty()) {
      End(d, TraceEnd::kContinuationFailed,
          fmt::format("branch {} of the {} chain did not start: {}", chain.links.size() + 1, DirectionName(chain.direction),
                      branch.branch.end_message));
      return;
    }
    const int link_index = static_cast<int>(chain.links.size());
    const Setup setup = next.setup;
    BasicTraceLink<Model> link{.branch = std::move(branch),
                               .signature = {},
                               .direction = next.setup.options.direction,
                               .start = next.start,
                               .margin = next.margin,
                               .type_switch = next.type_switch,
                               .end = TraceEnd::kContinuationFailed,
                               .message = {},
                               .bifurcations = {},
                               .other_switches = {}};
    const OrbitBranch& b = link.branch;
    link.end = LinkEndOf(b.branch.end);
    link.message = b.branch.end_message;
    link.signature = b.orbits.front().signature.ToString();
    link.bifurcations = BifurcationsOn(b, setup);
    visits_.push_back({link.signature, Lambda(model(), b.orbits.front(), start_.parameter), b.orbits.front(), d, link_index, false});
    const double lambda = Lambda(model(), b.orbits.back(), start_.parameter);
    const std::string where = fmt::format("{} = {:.10g}", start_.parameter, lambda);
    bool goes_on = false;
    if (b.branch.end == BranchEnd::kTerminalEvent) {
      goes_on = AtTypeChange(d, link_index, lambda, where, setup, &link);
    } else {
      visits_.push_back({link.signature, lambda, b.orbits.back(), d, link_index, true});
    }
    chain.links.push_back(std::move(link));
    const BasicTraceLink<Model>& added = chain.links.back();
    if (!goes_on) {
      End(d, added.end, added.message);
    } else if (static_cast<int>(chain.links.size()) >= options_.max_branches) {
      End(d, TraceEnd::kMaxBranches, fmt::format("max_branches = {} reached at {}", options_.max_branches, where));
    }
  }

  // The end of `link` (branch link_index of direction d) at a change of type: where the chain came
  // back to, the family's end, the same type followed on, or the switch to an adjacent type. True
  // if the chain goes on.
  bool AtTypeChange(int d, int link_index, double lambda, const std::string& where, const Setup& setup,
                    BasicTraceLink<Model>* link) {
    const OrbitBranch& b = link->branch;
    const std::optional<Visit<Model>> visited = Visited(b.orbits.back(), lambda, d, link_index);
    visits_.push_back({link->signature, lambda, b.orbits.back(), d, link_index, true});
    const std::vector<const SpecialPoint*> changes = ChangesAtEnd(b.branch, options_.loop_tolerance);
    if (visited) {
      CameBack(d, *visited, where, link);
      return false;
    }
    if (std::any_of(changes.begin(), changes.end(), IsFamilyEnd)) {
      // The kinetic level reaching 0 ends the physical family: an end of the trace like a bound,
      // not a failure, and no type goes past it.
      link->end = TraceEnd::kFamilyEnd;
      link->message = fmt::format("{} reached 0 at {}: the end of the physical family",
                                  model().Description().parameters[Model::kKineticLevelParameter].name, where);
      return false;
    }
    if (changes.empty()) {
      link->end = TraceEnd::kContinuationFailed;
      return false;
    }
    if (!next_[d].past) return Switch(d, b, setup, changes, link);
    // A stretch followed past a change ends at the next change of a margin's sign.
    const std::string crossed = changes.front()->test_function;
    const bool again = AdmissibleAgain(b, crossed);
    link->end = TraceEnd::kSameTypeOn;
    link->message =
        fmt::format("{}; {}", link->message, again ? "the orbit is admissible again" : "the same type followed on");
    SameTypeOn(d, b, setup, again ? LinkStart::kAdmissibleAgain : LinkStart::kFollowedPast,
               crossed.substr(orbit_columns::kMarginPrefix.size()), std::nullopt);
    return true;
  }

  // `link` of direction d ended where the chain had been (`visited`): a loop. Where that is the
  // other direction's last end, the two chains met and both end.
  void CameBack(int d, const Visit<Model>& visited, const std::string& where, BasicTraceLink<Model>* link) {
    link->end = TraceEnd::kLoop;
    const BasicTraceDirection<Model>& other = Chain(visited.direction);
    link->message = fmt::format("the chain came back at {} to where branch {} of the {} chain {} ('{}')", where,
                                visited.link + 1, DirectionName(other.direction), visited.end ? "ended" : "began",
                                link->signature);
    const int o = visited.direction;
    if (o != d && running_[o] && visited.end && visited.link + 1 == static_cast<int>(other.links.size())) {
      End(o, TraceEnd::kLoop,
          fmt::format("the {} chain came to its end at {}: the chains met", DirectionName(Chain(d).direction), where));
    }
  }

  // The next branch of direction d starts on the confirmed switch `sw` at `margin`.
  void TakeSwitch(int d, const Setup& setup, const std::string& margin, TypeSwitch sw) {
    Next<Model>& next = next_[d];
    next.setup = setup;
    next.setup.start = sw.BranchStart();
    next.setup.unknowns = sw.unknowns;
    next.setup.options.direction = sw.direction;
    next.setup = AtLeastPeriod(std::move(next.setup));
    // User values address the unknowns of the start's signature.
    if (next.setup.start.signature.ToString() != start_.start.signature.ToString()) {
      next.setup.options.user_values.clear();
    } else {
      next.setup.options.user_values = start_.options.user_values;
    }
    next.start = LinkStart::kSwitch;
    next.margin = margin;
    next.type_switch = std::move(sw);
    next.past = false;
  }

  // The switch at the end of `b` (every margin located there, in turn); true if the chain goes on.
  bool Switch(int d, const OrbitBranch& b, const Setup& setup, const std::vector<const SpecialPoint*>& changes,
              BasicTraceLink<Model>* link) {
    std::vector<std::string> reasons;
    bool any_candidate = false;
    bool taken = false;
    std::optional<TypeSwitch> first;
    for (const SpecialPoint* s : changes) {
      const BasicLocatedTypeChange<Model> located = TypeChangeAt(b, *s, setup);
      TypeSwitch sw = SwitchAt(located, options_.type_switch);
      if (sw.status == TypeSwitchStatus::kConfirmed && taken) {
        link->other_switches.push_back(std::move(sw));
      } else if (sw.status == TypeSwitchStatus::kConfirmed) {
        link->end = TraceEnd::kSwitched;
        link->message = fmt::format("{}: {}", located.margin, sw.reason);
        TakeSwitch(d, setup, located.margin, std::move(sw));
        taken = true;
        if (!options_.record_other_switches) return true;
      } else if (!taken) {
        any_candidate = any_candidate || sw.status == TypeSwitchStatus::kNotConfirmed;
        reasons.push_back(fmt::format("{}: {}", located.margin, sw.reason));
        if (!first) first = std::move(sw);
      }
    }
    if (taken) return true;
    const std::string why = fmt::format("{}", fmt::join(reasons, "; "));
    if (options_.follow_past_unswitched) {
      link->end = TraceEnd::kSameTypeOn;
      link->message = fmt::format("no switch ({}); the same type followed on past the change", why);
      const std::string margin = changes.front()->test_function.substr(orbit_columns::kMarginPrefix.size());
      SameTypeOn(d, b, setup, LinkStart::kFollowedPast, margin, std::move(first));
      return true;
    }
    link->end = any_candidate ? TraceEnd::kNotConfirmed : TraceEnd::kNoAdjacentType;
    link->message = why;
    return false;
  }

  const Model& model() const { return start_.model; }

  const Setup& start_;
  const TraceOptions& options_;
  BranchRunner<Model> runner_;
  BasicTraceResult<Model> result_;
  std::array<Next<Model>, 2> next_;
  std::array<bool, 2> running_ = {true, true};
  std::vector<Visit<Model>> visits_;
  int followed_ = 0;  // branches followed from a BP, PD or SB so far
};

}  // namespace trace_detail

template <OscillatorModel Model>
BasicOrbitContinuationSetup<Model> AtLeastPeriod(BasicOrbitContinuationSetup<Model> setup) {
  const BasicLeastPeriodOrbit<Model> reduced = ReduceToLeastPeriod<Model>(setup.model, setup.start);
  if (reduced.status != LeastPeriodStatus::kReduced) return setup;
  setup.start = reduced.orbit;
  setup.unknowns = UnknownsAtFixedParameters(VariableSetOf(setup.model, reduced.orbit.signature));
  return setup;
}

template <OscillatorModel Model>
BasicTraceResult<Model> TraceOrbits(const BasicOrbitContinuationSetup<Model>& start, const TraceOptions& options) {
  options.Validate();
  // The switches nudge the continued variable as a parameter of the model (a duration or a start
  // variable held is none).
  type_switch_detail::ParameterIndexOf(start.model.Description(), start.parameter);
  if (start.options.continue_past_terminal) {
    throw InvalidInput("continue_past_terminal", "true",
                       "false: a trace decides at every change of type (follow_past_unswitched follows a type past one)");
  }
  return trace_detail::Tracer<Model>(start, options).Run();
}

// A model whose size comes with its data (a user's [model]): compiled once, in model_trace.cpp.
extern template BasicTraceResult<DynamicLinearOscillator> TraceOrbits(
    const BasicOrbitContinuationSetup<DynamicLinearOscillator>& start, const TraceOptions& options);
extern template BasicOrbitContinuationSetup<DynamicLinearOscillator> AtLeastPeriod(
    BasicOrbitContinuationSetup<DynamicLinearOscillator> setup);
extern template BasicBifurcationBranchStart<DynamicLinearOscillator> BranchFromBifurcation(
    const SpecialPoint&, const BasicOrbitContinuationSetup<DynamicLinearOscillator>&, int);
extern template BasicBifurcationBranchStart<DynamicLinearOscillator> BranchFromBifurcation(
    const std::string&, const BasicOrbitContinuationSetup<DynamicLinearOscillator>&, int);

}  // namespace stickslip
