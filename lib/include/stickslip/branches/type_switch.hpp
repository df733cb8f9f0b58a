// Switching to the adjacent orbit type at a located change of type (SK, NS, GR, T0, S0: a margin
// through zero on a branch). Each adjacent type of the margin (orbits/adjacent_type.hpp) is tried:
//  1. its start orbit at the located point (the same state, phase and period, the new segment of
//     zero length) is corrected on the new type with the parameter held (to rounding: it already
//     solves the new type's equations); a margin clearly negative there rules the type out;
//  2. the parameter is nudged a little past the boundary, first the way the located branch was
//     going (the orbit persists across the boundary), then the other way (the new branch turns
//     back: a nonsmooth fold, both types on the same side); the new type is solved there. Where
//     that confirms nothing, the new segment is given short lengths instead and the parameter is
//     solved for (its side says which way the new branch goes);
//  3. the solved orbit is confirmed when the new segment has a positive duration shorter than
//     `max_new_duration` of the period, every margin is positive, and the exact simulator, started
//     from it, goes through the new signature over one period (events where the orbit says, state
//     back to the start).
// The first confirmed candidate is the switch; where none is, the result says why, per candidate.
// For any model (model/oscillator_model.hpp): the paper's model is compiled once (type_switch.cpp);
// a program or test switching another model's types includes branches/model_type_switch.hpp.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "stickslip/branches/orbit_continuation.hpp"
#include "stickslip/orbits/adjacent_type.hpp"
#include "stickslip/orbits/any_orbit.hpp"
#include "stickslip/orbits/orbit_solver.hpp"

namespace stickslip {

// A located change of orbit type on a branch.
template <OscillatorModel Model>
struct BasicLocatedTypeChange {
  OrbitOfModel<Model> orbit;  // the orbit at the located point
  std::string margin;      // the margin through zero, as Margin::Name() gives it: "reversal:1"
  std::string parameter;   // the continued parameter, e.g. "omega"
  int past = 1;            // +1 or -1: the way the parameter goes past the boundary, to the side
                           // where the located type is not admissible
  UnknownChoice unknowns;  // the branch's unknowns (the parameter held)
  Model model{};           // last, so that the paper's model's need not name it
};
using LocatedTypeChange = BasicLocatedTypeChange<Pascal2014>;

// The type change of a branch's special point `special` (a margin's sign change: test function
// "margin:<name>"), the side past it from its tangent and the margin's sign before it. Throws InvalidInput naming
// "special point" when the point is not a margin's sign change.
template <OscillatorModel Model>
BasicLocatedTypeChange<Model> TypeChangeAt(const BasicOrbitBranch<Model>& branch, const SpecialPoint& special,
                                           const BasicOrbitContinuationSetup<Model>& setup);

struct TypeSwitchOptions {
  double nudge = 1e-6;  // the parameter step past the boundary, relative to 1 + |lambda|
  // Where the nudges confirm nothing (a new segment whose length grows as a root of the step), the
  // new segment's duration given instead, as fractions of the period tried in turn, and the
  // parameter solved for.
  std::vector<double> new_durations = {1e-5, 1e-4, 1e-3};
  double max_new_duration = 1e-2;      // the new segment's duration past the boundary, as a fraction of the period
  double simulation_tolerance = 1e-9;  // event times and state after one period, exact simulator
  // The corrected start may differ from the located orbit by this much (OrbitDistance), and a removed
  // segment's located duration may be this fraction of the period: the same motion, to rounding.
  double same_orbit = 1e-9;
  // The margins of the corrected start are zero or positive, to this: a margin clearly negative there
  // means the new segment cannot be short (a new slip accelerating away from its stop, say).
  double start_margin_tolerance = 1e-7;
  OrbitSolverOptions solver;  // for the corrected start and the orbit past the boundary

  // Throws InvalidInput naming the first field out of its valid range.
  void Validate() const;
};

enum class TypeSwitchStatus {
  kConfirmed,       // an adjacent type confirmed by simulation
  kNotConfirmed,    // candidates, none confirmed (reasons per candidate)
  kNoAdjacentType,  // the margin has no adjacent type (a tangential end, the family's end)
};
const char* ToString(TypeSwitchStatus status);

template <OscillatorModel Model>
struct BasicTypeSwitch {
  TypeSwitchStatus status = TypeSwitchStatus::kNotConfirmed;
  std::string reason;  // per candidate tried, why it was or was not confirmed
  // Set when confirmed:
  std::optional<AdjacentType> adjacent;  // the confirmed candidate
  // On the adjacent type at the located parameter, corrected. Where the new segment's length grows
  // as a root of the parameter step (a grazing), the new type's Jacobian is singular here: a
  // branch of the new type then starts from `past`.
  std::optional<OrbitOfModel<Model>> start;
  std::optional<OrbitOfModel<Model>> past;  // on the adjacent type at the nudged parameter, confirmed by simulation
  int direction = 0;          // +1 or -1: the parameter's direction on the new branch
  bool persists = false;      // direction == LocatedTypeChange::past; else a nonsmooth fold
  // The new segment's length grows as a root of the parameter step (the switch was found with that
  // length given): the new type's Jacobian is singular at `start`, so its branch starts from `past`.
  bool singular_start = false;
  const OrbitOfModel<Model>& BranchStart() const { return singular_start ? *past : *start; }  // where confirmed
  UnknownChoice unknowns;     // the located unknowns renamed for the adjacent signature
};
using TypeSwitch = BasicTypeSwitch<Pascal2014>;

// Throws InvalidInput for invalid options, a margin the located orbit does not have, or a parameter
// that is no parameter.
template <OscillatorModel Model>
BasicTypeSwitch<Model> SwitchAt(const BasicLocatedTypeChange<Model>& located, const TypeSwitchOptions& options = {});

extern template LocatedTypeChange TypeChangeAt(const OrbitBranch& branch, const SpecialPoint& special,
                                               const OrbitContinuationSetup& setup);
extern template TypeSwitch SwitchAt(const LocatedTypeChange& located, const TypeSwitchOptions& options);

}  // namespace stickslip
