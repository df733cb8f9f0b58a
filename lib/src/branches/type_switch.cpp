#include "stickslip/branches/type_switch.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "stickslip/invalid_input.hpp"
#include "stickslip/model/simulation.hpp"

namespace stickslip {

namespace {

namespace ov = orbit_variables;

// The static friction level equals the kinetic one: an abnormal stop is possible (eq. 25).
bool EqualFrictionLevels(const Parameters& p) {
  return Pascal2014::ParameterAt(p, Pascal2014::kStaticLevelParameter) ==
         Pascal2014::ParameterAt(p, Pascal2014::kKineticLevelParameter);
}

// The exact simulator over one period from the orbit's start: the segments in the orbit's order,
// each starting where the orbit says, and the state back at the start. "" when it is so.
std::string SimulationDisagrees(const Orbit& orbit, double tolerance) {
  const double period = orbit.Period();
  SimulationOptions options;
  options.duration = period;
  const SimulationResult r = SimulateExact(orbit.parameters, orbit.InitialState(), orbit.phi, options);
  if (!r.Completed()) return "the simulation stopped early: " + r.message;
  std::vector<double> starts = orbit.SegmentTimes();
  starts.pop_back();
  if (orbit.signature.antisymmetric()) {
    const std::size_t n = starts.size();
    for (std::size_t k = 0; k < n; ++k) starts.push_back(period / 2 + starts[k]);
  }
  const std::vector<Mode> expected = orbit.signature.FullPeriod();
  std::vector<const Segment*> simulated;  // a sliver opened a rounding error before the end is the next period's
  for (const Segment& s : r.segments) {
    if (s.t_start < period - 1e-7) simulated.push_back(&s);
  }
  std::string modes;
  for (const Segment* s : simulated) modes += fmt::format("{}{}", modes.empty() ? "" : " ", ToString(s->mode));
  if (simulated.size() != expected.size()) return fmt::format("the simulator went through [{}]", modes);
  for (std::size_t k = 0; k < expected.size(); ++k) {
    if (simulated[k]->mode != expected[k]) return fmt::format("the simulator went through [{}]", modes);
    if (std::abs(simulated[k]->t_start - starts[k]) > tolerance) {
      return fmt::format("segment {} starts at t = {:.12g} in the simulation, {:.12g} on the orbit", k + 1,
                         simulated[k]->t_start, starts[k]);
    }
  }
  const double mismatch = (simulated.back()->end - orbit.InitialState()).lpNorm<Eigen::Infinity>();
  if (mismatch > tolerance)
    return fmt::format("the simulated state after one period is {:.2e} off the start", mismatch);
  return "";
}

UnknownChoice Renamed(const UnknownChoice& unknowns, const SignatureEdit& edit) {
  UnknownChoice renamed = unknowns;
  for (std::string& name : renamed.release) name = edit.Renamed(name);
  for (std::string& name : renamed.fix) name = edit.Renamed(name);
  return renamed;
}

ParameterId ParameterIdOf(std::string_view name) {
  const std::optional<ParameterId> id = ParameterFromString(name);
  if (!id) throw InvalidInput("parameter", std::string(name), "chi, eta, omega, u_s, u_r");
  return *id;
}

// Why the orbit past the boundary is not the adjacent type's motion, "" if it is.
std::string NotConfirmed(const Orbit& past, const AdjacentType& adjacent, const TypeSwitchOptions& options) {
  if (adjacent.new_segment >= 0) {
    const double d = past.durations[adjacent.new_segment];
    if (!(d > 0.0)) return fmt::format("the new segment's duration is {:.3g} there", d);
    if (d > options.max_new_duration * past.Period()) {
      return fmt::format("the new segment is not short ({:.3g} of the period)", d / past.Period());
    }
  }
  const Margin smallest = SmallestMargin(AdmissibilityMargins(past));
  if (!(smallest.value > 0.0)) return fmt::format("margin {} = {:.3g} there", smallest.Name(), smallest.value);
  return SimulationDisagrees(past, options.simulation_tolerance);
}

TypeSwitch Confirmed(const LocatedTypeChange& located, const AdjacentType& adjacent, const Orbit& start,
                     const Orbit& past, const std::string& side, const UnknownChoice& unknowns, double lambda,
                     bool singular_start) {
  const ParameterId parameter = ParameterIdOf(located.parameter);
  const int direction = past.parameters[parameter] > lambda ? 1 : -1;
  return {.status = TypeSwitchStatus::kConfirmed,
          .reason = fmt::format("'{}' ({}) {}: confirmed by simulation; {}", adjacent.edit.signature.ToString(),
                                adjacent.bifurcation, side, adjacent.motion),
          .adjacent = adjacent,
          .start = start,
          .past = past,
          .direction = direction,
          .persists = direction == located.past,
          .singular_start = singular_start,
          .unknowns = unknowns};
}

// One candidate adjacent type tried at a located change: its start (the located orbit edited and
// corrected on the new type, which must be the same orbit, with no margin already negative), then an
// orbit on it just past the boundary, by nudging the parameter either way, or where the new
// segment's length grows as a root of the step (a grazing), by giving that length and solving for
// the parameter. reasons() says, in the order tried, why each way did not confirm it.
class CandidateTrial {
 public:
  CandidateTrial(const LocatedTypeChange& located, const Margin& margin, const AdjacentType& adjacent,
                 const TypeSwitchOptions& options, ParameterId parameter, std::string name)
      : located_(located),
        margin_(margin),
        adjacent_(adjacent),
        options_(options),
        name_(std::move(name)),
        parameter_(parameter),
        lambda_(located.orbit.parameters[parameter_]),
        unknowns_(Renamed(located.unknowns, adjacent.edit)),
        free_(FreeIndices(adjacent.edit.signature, unknowns_)) {}

  // The confirmed switch, or nullopt (reasons() says why).
  std::optional<TypeSwitch> Run() {
    if (std::optional<std::string> why = NotVanished()) return Fail(*why);
    const OrbitSolution start = SolveOrbit(AdjacentStart(located_.orbit, margin_, adjacent_), free_,
                                           unknowns_.tie_static_friction, options_.solver);
    if (std::optional<std::string> why = BadStart(start)) return Fail(*why);
    if (std::optional<TypeSwitch> confirmed = ByNudges(start.orbit)) return confirmed;
    return ByGivenDuration(start.orbit);
  }

  const std::vector<std::string>& reasons() const { return reasons_; }

 private:
  std::nullopt_t Fail(std::string why) {
    reasons_.push_back(std::move(why));
    return std::nullopt;
  }

  // A removal needs the segment removed to have vanished at the located point.
  std::optional<std::string> NotVanished() const {
    const bool removal = adjacent_.new_segment < 0 && adjacent_.kind != TypeEdit::kSplitAtAbnormalStop;
    const double vanished = located_.orbit.durations[adjacent_.segment];
    if (!removal || std::abs(vanished) <= options_.same_orbit * located_.orbit.Period()) return std::nullopt;
    return fmt::format("{}: segment {} has not vanished (duration {:.3g})", name_, adjacent_.segment + 1, vanished);
  }

  std::optional<std::string> BadStart(const OrbitSolution& start) const {
    if (!start.summary.Converged()) return name_ + ": the start does not solve the new type's equations";
    const double moved = OrbitDistance(start.orbit, located_.orbit);
    if (!(moved <= options_.same_orbit)) {
      return fmt::format("{}: the corrected start moved {:.3g} off the located orbit", name_, moved);
    }
    // A margin already negative at the start: the new type is not a motion next to the located
    // orbit on either side (a new slip that accelerates away from its stop, a new stick that the
    // force does not leave at once).
    const Margin at_start = SmallestMargin(AdmissibilityMargins(start.orbit));
    if (!(at_start.value >= -options_.start_margin_tolerance)) {
      return fmt::format("{}: margin {} = {:.3g} at the start, so the new segment cannot stay short", name_,
                         at_start.Name(), at_start.value);
    }
    return std::nullopt;
  }

  // An orbit past the boundary, the parameter nudged either way from the start.
  std::optional<TypeSwitch> ByNudges(const Orbit& start) {
    const double step = options_.nudge * (1.0 + std::abs(lambda_));
    std::vector<std::pair<OrbitSolution, std::string>> tries;  // an orbit past the boundary, how it was found
    for (const int direction : {located_.past, -located_.past}) {
      Orbit guess = start;
      guess.parameters[parameter_] = lambda_ + direction * step;
      tries.emplace_back(SolveOrbit(guess, free_, unknowns_.tie_static_friction, options_.solver),
                         direction == located_.past ? "past the boundary" : "before the boundary");
    }
    for (const auto& [past, side] : tries) {
      const std::string why =
          past.summary.Converged() ? NotConfirmed(past.orbit, adjacent_, options_) : "no convergence on the new type";
      if (why.empty()) return Confirmed(located_, adjacent_, start, past.orbit, side, unknowns_, lambda_, false);
      reasons_.push_back(fmt::format("{} {}: {}", name_, side, why));
    }
    return std::nullopt;
  }

  // Where the new segment's length grows as a root of the parameter step (a grazing, where the
  // Jacobian is singular at the start, and Newton may find the other root), give the length,
  // centred on the grazing time for a split, and solve for the parameter; longer lengths where
  // the shortest leaves the end condition too flat to solve (a slip starting with x2'' = 0).
  std::optional<TypeSwitch> ByGivenDuration(const Orbit& start) {
    for (const double fraction : adjacent_.new_segment >= 0 ? options_.new_durations : std::vector<double>{}) {
      Orbit guess = start;
      const double length = fraction * guess.Period();
      guess.durations[adjacent_.new_segment] = length;
      if (adjacent_.kind == TypeEdit::kSplit) {
        guess.durations[adjacent_.new_segment - 1] -= std::min(length / 2, guess.durations[adjacent_.new_segment - 1]);
        guess.durations[adjacent_.new_segment + 1] -= std::min(length / 2, guess.durations[adjacent_.new_segment + 1]);
      }
      std::vector<int> released = free_;
      const auto held = std::find(released.begin(), released.end(), ov::Duration(adjacent_.new_segment));
      if (held == released.end()) break;  // the new segment's duration is held by the user's fix
      released.erase(held);
      released.push_back(ov::Parameter(guess.signature.size(), parameter_));
      const OrbitSolution given = SolveOrbit(guess, released, unknowns_.tie_static_friction, options_.solver);
      const std::string side = fmt::format("with the new segment's duration given ({:g} of the period)", fraction);
      const std::string why =
          given.summary.Converged() ? NotConfirmed(given.orbit, adjacent_, options_) : "no convergence on the new type";
      if (why.empty()) return Confirmed(located_, adjacent_, start, given.orbit, side, unknowns_, lambda_, true);
      reasons_.push_back(fmt::format("{} {}: {}", name_, side, why));
    }
    return std::nullopt;
  }

  const LocatedTypeChange& located_;
  const Margin& margin_;
  const AdjacentType& adjacent_;
  const TypeSwitchOptions& options_;
  std::string name_;
  ParameterId parameter_;
  double lambda_;
  UnknownChoice unknowns_;
  std::vector<int> free_;
  std::vector<std::string> reasons_;
};

}  // namespace

double OrbitDistance(const Orbit& a, const Orbit& b) {
  const double period = std::abs(a.Period() - b.Period());
  const double phase = std::abs(a.phi - b.phi);
  return std::max({(a.InitialState() - b.InitialState()).lpNorm<Eigen::Infinity>(), phase, period});
}

const char* ToString(TypeSwitchStatus status) {
  switch (status) {
    case TypeSwitchStatus::kConfirmed: return "confirmed";
    case TypeSwitchStatus::kNotConfirmed: return "not-confirmed";
    case TypeSwitchStatus::kNoAdjacentType: return "no-adjacent-type";
  }
  return "?";
}

LocatedTypeChange TypeChangeAt(const OrbitBranch& branch, const SpecialPoint& special,
                               const OrbitContinuationSetup& setup) {
  const std::string prefix(orbit_columns::kMarginPrefix);
  if (special.test_function.rfind(prefix, 0) != 0 || special.point < 0 ||
      special.point >= static_cast<int>(branch.orbits.size())) {
    throw InvalidInput("special point", special.type + " " + special.test_function,
                       "a located sign change of a margin on this branch");
  }
  const Orbit& orbit = branch.orbits[special.point];
  const std::size_t lambda = FreeIndices(orbit.signature, setup.unknowns).size();
  const double along = lambda < static_cast<std::size_t>(special.tangent.size()) ? special.tangent(lambda) : 0.0;
  const int way = along > 0.0 ? 1 : along < 0.0 ? -1 : setup.options.direction;
  // A branch that comes from the inadmissible side (a start beyond the boundary, as section 5.2's)
  // has the far side behind it.
  const auto& functions = branch.branch.test_functions;
  const auto function = std::find_if(functions.begin(), functions.end(),
                                     [&](const TestFunctionInfo& f) { return f.name == special.test_function; });
  // The margin at the last regular point before (not another special point located at the same
  // place, nor a start on the boundary).
  bool from_inadmissible = false;
  for (int k = special.point - 1; k >= 0 && function != functions.end(); --k) {
    const BranchPoint& point = branch.branch.points[k];
    const double value = point.tests(function - functions.begin());
    if (!point.label.empty() || !(std::abs(value) > setup.options.start_boundary_tolerance)) continue;
    from_inadmissible = value < 0.0;
    break;
  }
  return {.orbit = orbit,
          .margin = special.test_function.substr(prefix.size()),
          .parameter = setup.parameter,
          .past = from_inadmissible ? -way : way,
          .unknowns = setup.unknowns};
}

void TypeSwitchOptions::Validate() const {
  if (!(nudge > 0.0 && nudge <= 0.1)) throw InvalidInput("nudge", nudge, "0 < nudge <= 0.1");
  if (!(max_new_duration > 0.0 && max_new_duration <= 1.0)) {
    throw InvalidInput("max_new_duration", max_new_duration, "0 < max_new_duration <= 1");
  }
  for (const double d : new_durations) {
    if (!(d > 0.0 && d <= max_new_duration)) {
      throw InvalidInput("new_durations", d, fmt::format("0 < each <= max_new_duration = {}", max_new_duration));
    }
  }
  if (!(simulation_tolerance > 0.0 && simulation_tolerance <= 1e-3)) {
    throw InvalidInput("simulation_tolerance", simulation_tolerance, "0 < simulation_tolerance <= 1e-3");
  }
  if (!(same_orbit > 0.0 && same_orbit <= 1e-3)) throw InvalidInput("same_orbit", same_orbit, "0 < same_orbit <= 1e-3");
  if (!(start_margin_tolerance >= 0.0 && start_margin_tolerance <= 1e-3)) {
    throw InvalidInput("start_margin_tolerance", start_margin_tolerance, "0 <= start_margin_tolerance <= 1e-3");
  }
}

TypeSwitch SwitchAt(const LocatedTypeChange& located, const TypeSwitchOptions& options) {
  options.Validate();
  TypeSwitch result;
  const std::size_t colon = located.margin.find(':');
  const std::string base = located.margin.substr(0, colon);
  const std::vector<Margin> margins = AdmissibilityMargins(located.orbit);
  const auto margin =
      std::find_if(margins.begin(), margins.end(), [&](const Margin& m) { return m.Name() == located.margin; });
  if (margin == margins.end()) {
    throw InvalidInput("margin", located.margin,
                       fmt::format("a margin of the signature '{}'", located.orbit.signature.ToString()));
  }
  const bool equal_friction = located.unknowns.tie_static_friction || EqualFrictionLevels(located.orbit.parameters);
  const std::vector<AdjacentType> candidates =
      AdjacentTypes(base, margin->segment, located.orbit.signature, equal_friction);
  if (candidates.empty()) {
    result.status = TypeSwitchStatus::kNoAdjacentType;
    result.reason = NoAdjacentTypeReason(base);
    if (result.reason.empty()) {
      result.reason = fmt::format(
          "{}: no valid signature without segment {} (the only segment, or neighbours "
          "joined across the orbit's origin)",
          located.margin, margin->segment + 1);
    }
    return result;
  }
  const ParameterId parameter = ParameterIdOf(located.parameter);  // InvalidInput for one that is no parameter
  std::vector<std::string> reasons;
  for (const AdjacentType& adjacent : candidates) {
    const std::string name = fmt::format("'{}' ({})", adjacent.edit.signature.ToString(), adjacent.bifurcation);
    std::optional<CandidateTrial> trial;
    std::optional<std::string> failed;
    try {
      trial.emplace(located, *margin, adjacent, options, parameter, name);
      if (std::optional<TypeSwitch> confirmed = trial->Run()) return std::move(*confirmed);
    } catch (const InvalidInput& e) {
      failed = name + ": " + e.what();
    }
    if (trial) reasons.insert(reasons.end(), trial->reasons().begin(), trial->reasons().end());
    if (failed) reasons.push_back(*failed);
  }
  result.status = TypeSwitchStatus::kNotConfirmed;
  for (const std::string& r : reasons) result.reason += (result.reason.empty() ? "" : "; ") + r;
  return result;
}

}  // namespace stickslip
