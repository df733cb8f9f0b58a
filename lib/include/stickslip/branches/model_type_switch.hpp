// TypeChangeAt and SwitchAt (type_switch.hpp) for any model (model/oscillator_model.hpp). The
// paper's model is compiled once, in type_switch.cpp; a program or test switching another model's
// orbit types includes this header.
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "stickslip/branches/type_switch.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/model/exact_simulator.hpp"
#include "stickslip/orbits/margins.hpp"
#include "stickslip/orbits/model_orbit_solver.hpp"

namespace stickslip {

namespace type_switch_detail {

// The static friction level equals the kinetic one: an abnormal stop is possible (eq. 25).
template <OscillatorModel Model>
bool EqualFrictionLevels(const typename Model::Parameters& p) {
  return Model::ParameterAt(p, Model::kStaticLevelParameter) == Model::ParameterAt(p, Model::kKineticLevelParameter);
}

// The exact simulator over one period from the orbit's start: the segments in the orbit's order,
// each starting where the orbit says, and the state back at the start. "" when it is so.
template <OscillatorModel Model>
std::string SimulationDisagrees(const Model& model, const BasicOrbit<Model>& orbit, double tolerance) {
  const double period = PeriodOf(model, orbit);
  BasicSimulationOptions<typename Model::State> options;
  options.duration = period;
  const BasicSimulationResult<Model> r = SimulateExact(model, orbit.parameters, orbit.start, orbit.phi, options);
  if (!r.Completed()) return "the simulation stopped early: " + r.message;
  std::vector<double> starts = {0.0};  // of the listed segments
  for (std::size_t k = 0; k + 1 < orbit.durations.size(); ++k) starts.push_back(starts.back() + orbit.durations[k]);
  if (orbit.signature.antisymmetric()) {
    const std::size_t n = starts.size();
    for (std::size_t k = 0; k < n; ++k) starts.push_back(period / 2 + starts[k]);
  }
  const std::vector<Mode> expected = orbit.signature.FullPeriod();
  std::vector<const BasicSegment<typename Model::State>*> simulated;  // a sliver opened a rounding error
  for (const auto& s : r.segments) {                                   // before the end is the next period's
    if (s.t_start < period - 1e-7) simulated.push_back(&s);
  }
  std::string modes;
  for (const auto* s : simulated) modes += fmt::format("{}{}", modes.empty() ? "" : " ", ToString(s->mode));
  if (simulated.size() != expected.size()) return fmt::format("the simulator went through [{}]", modes);
  for (std::size_t k = 0; k < expected.size(); ++k) {
    if (simulated[k]->mode != expected[k]) return fmt::format("the simulator went through [{}]", modes);
    if (std::abs(simulated[k]->t_start - starts[k]) > tolerance) {
      return fmt::format("segment {} starts at t = {:.12g} in the simulation, {:.12g} on the orbit", k + 1,
                         simulated[k]->t_start, starts[k]);
    }
  }
  const double mismatch = (simulated.back()->end - orbit.start).template lpNorm<Eigen::Infinity>();
  if (mismatch > tolerance)
    return fmt::format("the simulated state after one period is {:.2e} off the start", mismatch);
  return "";
}

UnknownChoice Renamed(const UnknownChoice& unknowns, const SignatureEdit& edit);

// The index of the continued parameter among the model's parameters.
int ParameterIndexOf(const ModelDescription& description, const std::string& name);

// Why the orbit past the boundary is not the adjacent type's motion, "" if it is.
template <OscillatorModel Model>
std::string NotConfirmed(const Model& model, const BasicOrbit<Model>& past, const AdjacentType& adjacent,
                         const TypeSwitchOptions& options) {
  if (adjacent.new_segment >= 0) {
    const double d = past.durations[adjacent.new_segment];
    if (!(d > 0.0)) return fmt::format("the new segment's duration is {:.3g} there", d);
    if (d > options.max_new_duration * PeriodOf(model, past)) {
      return fmt::format("the new segment is not short ({:.3g} of the period)", d / PeriodOf(model, past));
    }
  }
  const Margin smallest = SmallestMargin(AdmissibilityMargins(model, past));
  if (!(smallest.value > 0.0)) return fmt::format("margin {} = {:.3g} there", smallest.Name(), smallest.value);
  return SimulationDisagrees(model, past, options.simulation_tolerance);
}

// One candidate adjacent type tried at a located change: its start (the located orbit edited and
// corrected on the new type, which must be the same orbit, with no margin already negative), then an
// orbit on it just past the boundary, by nudging the parameter either way, or where the new
// segment's length grows as a root of the step (a grazing), by giving that length and solving for
// the parameter. reasons() says, in the order tried, why each way did not confirm it.
template <OscillatorModel Model>
class CandidateTrial {
 public:
  using AnyOrbit = OrbitOfModel<Model>;

  CandidateTrial(const BasicLocatedTypeChange<Model>& located, const Margin& margin, const AdjacentType& adjacent,
                 const TypeSwitchOptions& options, int parameter, std::string name)
      : located_(located),
        margin_(margin),
        adjacent_(adjacent),
        options_(options),
        name_(std::move(name)),
        parameter_(parameter),
        lambda_(Model::ParameterAt(located.orbit.parameters, parameter_)),
        unknowns_(Renamed(located.unknowns, adjacent.edit)),
        free_(FreeIndices(VariableSetOf(located.model, adjacent.edit.signature), unknowns_)) {}

  // The confirmed switch, or nullopt (reasons() says why).
  std::optional<BasicTypeSwitch<Model>> Run() {
    if (std::optional<std::string> why = NotVanished()) return Fail(*why);
    const BasicOrbitSolution<Model> start = Solve(AdjacentStart(located_.orbit, margin_, adjacent_), free_);
    if (std::optional<std::string> why = BadStart(start)) return Fail(*why);
    if (std::optional<BasicTypeSwitch<Model>> confirmed = ByNudges(start.orbit)) return confirmed;
    return ByGivenDuration(start.orbit);
  }

  const std::vector<std::string>& reasons() const { return reasons_; }

 private:
  const Model& model() const { return located_.model; }

  BasicOrbitSolution<Model> Solve(const AnyOrbit& guess, const std::vector<int>& free) const {
    return SolveOrbit<Model>(model(), guess, free, unknowns_.tie_static_friction, options_.solver);
  }

  double Period(const AnyOrbit& orbit) const { return PeriodOf(model(), AsBasicOrbit(orbit)); }

  std::nullopt_t Fail(std::string why) {
    reasons_.push_back(std::move(why));
    return std::nullopt;
  }

  // A removal needs the segment removed to have vanished at the located point.
  std::optional<std::string> NotVanished() const {
    const bool removal = adjacent_.new_segment < 0 && adjacent_.kind != TypeEdit::kSplitAtAbnormalStop;
    const double vanished = located_.orbit.durations[adjacent_.segment];
    if (!removal || std::abs(vanished) <= options_.same_orbit * Period(located_.orbit)) return std::nullopt;
    return fmt::format("{}: segment {} has not vanished (duration {:.3g})", name_, adjacent_.segment + 1, vanished);
  }

  std::optional<std::string> BadStart(const BasicOrbitSolution<Model>& start) const {
    if (!start.summary.Converged()) return name_ + ": the start does not solve the new type's equations";
    const double moved = OrbitDistance(model(), AsBasicOrbit(start.orbit), AsBasicOrbit(located_.orbit));
    if (!(moved <= options_.same_orbit)) {
      return fmt::format("{}: the corrected start moved {:.3g} off the located orbit", name_, moved);
    }
    // A margin already negative at the start: the new type is not a motion next to the located
    // orbit on either side (a new slip that accelerates away from its stop, a new stick that the
    // force does not leave at once).
    const Margin at_start = SmallestMargin(AdmissibilityMargins(model(), AsBasicOrbit(start.orbit)));
    if (!(at_start.value >= -options_.start_margin_tolerance)) {
      return fmt::format("{}: margin {} = {:.3g} at the start, so the new segment cannot stay short", name_,
                         at_start.Name(), at_start.value);
    }
    return std::nullopt;
  }

  BasicTypeSwitch<Model> Confirmed(const AnyOrbit& start, const AnyOrbit& past, const std::string& side,
                                   bool singular_start) const {
    const int direction = Model::ParameterAt(past.parameters, parameter_) > lambda_ ? 1 : -1;
    return {.status = TypeSwitchStatus::kConfirmed,
            .reason = fmt::format("'{}' ({}) {}: confirmed by simulation; {}", adjacent_.edit.signature.ToString(),
                                  adjacent_.bifurcation, side, adjacent_.motion),
            .adjacent = adjacent_,
            .start = start,
            .past = past,
            .direction = direction,
            .persists = direction == located_.past,
            .singular_start = singular_start,
            .unknowns = unknowns_};
  }

  // Why `past` does not confirm the candidate, "" if it does.
  std::string WhyNot(const BasicOrbitSolution<Model>& past) const {
    if (!past.summary.Converged()) return "no convergence on the new type";
    return NotConfirmed(model(), AsBasicOrbit(past.orbit), adjacent_, options_);
  }

  // An orbit past the boundary, the parameter nudged either way from the start.
  std::optional<BasicTypeSwitch<Model>> ByNudges(const AnyOrbit& start) {
    const double step = options_.nudge * (1.0 + std::abs(lambda_));
    std::vector<std::pair<BasicOrbitSolution<Model>, std::string>> tries;  // an orbit past the boundary, how found
    for (const int direction : {located_.past, -located_.past}) {
      AnyOrbit guess = start;
      Model::ParameterAt(guess.parameters, parameter_) = lambda_ + direction * step;
      tries.emplace_back(Solve(guess, free_), direction == located_.past ? "past the boundary" : "before the boundary");
    }
    for (const auto& [past, side] : tries) {
      const std::string why = WhyNot(past);
      if (why.empty()) return Confirmed(start, past.orbit, side, false);
      reasons_.push_back(fmt::format("{} {}: {}", name_, side, why));
    }
    return std::nullopt;
  }

  // Where the new segment's length grows as a root of the parameter step (a grazing, where the
  // Jacobian is singular at the start, and Newton may find the other root), give the length,
  // centred on the grazing time for a split, and solve for the parameter; longer lengths where
  // the shortest leaves the end condition too flat to solve (a slip starting with x2'' = 0).
  std::optional<BasicTypeSwitch<Model>> ByGivenDuration(const AnyOrbit& start) {
    const OrbitLayout layout(model().Description(), start.signature.size());
    for (const double fraction : adjacent_.new_segment >= 0 ? options_.new_durations : std::vector<double>{}) {
      AnyOrbit guess = start;
      const double length = fraction * Period(guess);
      guess.durations[adjacent_.new_segment] = length;
      if (adjacent_.kind == TypeEdit::kSplit) {
        guess.durations[adjacent_.new_segment - 1] -= std::min(length / 2, guess.durations[adjacent_.new_segment - 1]);
        guess.durations[adjacent_.new_segment + 1] -= std::min(length / 2, guess.durations[adjacent_.new_segment + 1]);
      }
      std::vector<int> released = free_;
      const auto held = std::find(released.begin(), released.end(), layout.Duration(adjacent_.new_segment));
      if (held == released.end()) break;  // the new segment's duration is held by the user's fix
      released.erase(held);
      released.push_back(layout.Parameter(parameter_));
      const BasicOrbitSolution<Model> given = Solve(guess, released);
      const std::string side = fmt::format("with the new segment's duration given ({:g} of the period)", fraction);
      const std::string why = WhyNot(given);
      if (why.empty()) return Confirmed(start, given.orbit, side, true);
      reasons_.push_back(fmt::format("{} {}: {}", name_, side, why));
    }
    return std::nullopt;
  }

  const BasicLocatedTypeChange<Model>& located_;
  const Margin& margin_;
  const AdjacentType& adjacent_;
  const TypeSwitchOptions& options_;
  std::string name_;
  int parameter_;
  double lambda_;
  UnknownChoice unknowns_;
  std::vector<int> free_;
  std::vector<std::string> reasons_;
};

// Where the continued parameter sits among a branch's unknowns: after the orbit's free variables
// (multiple shooting's interior states follow it).
template <OscillatorModel Model>
int ParameterUnknown(const BasicOrbitContinuationSetup<Model>& setup, const Signature& signature) {
  return static_cast<int>(FreeIndices(VariableSetOf(setup.model, signature), setup.unknowns).size());
}

// Whether the branch came to `special` from the inadmissible side of its margin (a start beyond
// the boundary, as section 5.2's): the margin at the last regular point before it (not another
// special point located at the same place, nor a start on the boundary).
bool FromInadmissibleSide(const Branch& branch, const SpecialPoint& special, double boundary_tolerance);

// Every adjacent type of the located margin tried in turn: the first confirmed, or why none is.
template <OscillatorModel Model>
BasicTypeSwitch<Model> TryAdjacentTypes(const BasicLocatedTypeChange<Model>& located, const Margin& margin,
                                        const std::vector<AdjacentType>& candidates, const TypeSwitchOptions& options) {
  // InvalidInput for one that is no parameter.
  const int parameter = ParameterIndexOf(located.model.Description(), located.parameter);
  std::vector<std::string> reasons;
  for (const AdjacentType& adjacent : candidates) {
    const std::string name = fmt::format("'{}' ({})", adjacent.edit.signature.ToString(), adjacent.bifurcation);
    std::optional<CandidateTrial<Model>> trial;
    std::optional<std::string> failed;
    try {
      trial.emplace(located, margin, adjacent, options, parameter, name);
      if (std::optional<BasicTypeSwitch<Model>> confirmed = trial->Run()) return std::move(*confirmed);
    } catch (const InvalidInput& e) {
      failed = name + ": " + e.what();
    }
    if (trial) reasons.insert(reasons.end(), trial->reasons().begin(), trial->reasons().end());
    if (failed) reasons.push_back(*failed);
  }
  BasicTypeSwitch<Model> result;
  result.status = TypeSwitchStatus::kNotConfirmed;
  for (const std::string& r : reasons) result.reason += (result.reason.empty() ? "" : "; ") + r;
  return result;
}

}  // namespace type_switch_detail

template <OscillatorModel Model>
BasicLocatedTypeChange<Model> TypeChangeAt(const BasicOrbitBranch<Model>& branch, const SpecialPoint& special,
                                           const BasicOrbitContinuationSetup<Model>& setup) {
  const std::string prefix(orbit_columns::kMarginPrefix);
  if (special.test_function.rfind(prefix, 0) != 0 || special.point < 0 ||
      special.point >= static_cast<int>(branch.orbits.size())) {
    throw InvalidInput("special point", special.type + " " + special.test_function,
                       "a located sign change of a margin on this branch");
  }
  const OrbitOfModel<Model>& orbit = branch.orbits[special.point];
  const int lambda = type_switch_detail::ParameterUnknown(setup, orbit.signature);
  const double along = lambda < special.tangent.size() ? special.tangent(lambda) : 0.0;
  const int way = along > 0.0 ? 1 : along < 0.0 ? -1 : setup.options.direction;
  // A branch that comes from the inadmissible side has the far side behind it.
  const bool from_inadmissible =
      type_switch_detail::FromInadmissibleSide(branch.branch, special, setup.options.start_boundary_tolerance);
  return {.orbit = orbit,
          .margin = special.test_function.substr(prefix.size()),
          .parameter = setup.parameter,
          .past = from_inadmissible ? -way : way,
          .unknowns = setup.unknowns,
          .model = setup.model};
}

template <OscillatorModel Model>
BasicTypeSwitch<Model> SwitchAt(const BasicLocatedTypeChange<Model>& located, const TypeSwitchOptions& options) {
  options.Validate();
  const std::size_t colon = located.margin.find(':');
  const std::string base = located.margin.substr(0, colon);
  const std::vector<Margin> margins = AdmissibilityMargins(located.model, AsBasicOrbit(located.orbit));
  const auto margin =
      std::find_if(margins.begin(), margins.end(), [&](const Margin& m) { return m.Name() == located.margin; });
  if (margin == margins.end()) {
    throw InvalidInput("margin", located.margin,
                       fmt::format("a margin of the signature '{}'", located.orbit.signature.ToString()));
  }
  const bool equal_friction = located.unknowns.tie_static_friction ||
                              type_switch_detail::EqualFrictionLevels<Model>(located.orbit.parameters);
  const std::vector<AdjacentType> candidates =
      AdjacentTypes(base, margin->segment, located.orbit.signature, equal_friction, located.model.Description().contact);
  if (!candidates.empty()) return type_switch_detail::TryAdjacentTypes(located, *margin, candidates, options);
  BasicTypeSwitch<Model> result;
  result.status = TypeSwitchStatus::kNoAdjacentType;
  result.reason = NoAdjacentTypeReason(base, located.model.Description().contact);
  if (result.reason.empty()) {
    result.reason = fmt::format(
        "{}: no valid signature without segment {} (the only segment, or neighbours joined across the orbit's "
        "origin)",
        located.margin, margin->segment + 1);
  }
  return result;
}

}  // namespace stickslip
