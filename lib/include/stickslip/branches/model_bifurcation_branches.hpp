// BranchFromBifurcation (bifurcation_branches.hpp) for any model (model/oscillator_model.hpp). The
// paper's model is compiled once, in bifurcation_branches.cpp; a program or test that leaves
// another model's bifurcations includes this header.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "stickslip/branches/bifurcation_branches.hpp"
#include "stickslip/branches/model_orbit_continuation.hpp"
#include "stickslip/continuation/branch_switching.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/orbits/signature_edits.hpp"

namespace stickslip {

namespace bifurcation_detail {

// The held durations of the unfolded type: every copy of a held duration of the original.
UnknownChoice Unfolded(const ModelDescription& model, const UnknownChoice& choice, int listed, int repeats);

// The tangent on the orbit's variables (the leading unknowns are variables, in the order of
// free(); multiple shooting's interior states follow) repeated over the `unfolded` segments of
// the unfolded type, on the unfolded problem's unknowns `unfolded_free`.
Eigen::VectorXd UnfoldedTangent(const ModelDescription& model, const OrbitVariableSet& variables,
                                const std::vector<int>& free,
                                const Eigen::VectorXd& tangent, bool tie_static_friction, int unfolded,
                                const std::vector<int>& unfolded_free);

}  // namespace bifurcation_detail

template <OscillatorModel Model>
BasicBifurcationBranchStart<Model> BranchFromBifurcation(const SpecialPoint& special,
                                                         const BasicOrbitContinuationSetup<Model>& setup, int side) {
  if (special.type != "BP" && special.type != "PD" && special.type != "SB") {
    throw InvalidInput("special point", special.type,
                       "a branch point (BP), a period doubling (PD) or a symmetry breaking (SB)");
  }
  if (side != 1 && side != -1) throw InvalidInput("side", side, "+1 or -1");
  const OrbitContinuationProblem original = MakeOrbitContinuation(setup);
  const OrbitOfModel<Model> at = ModelProblemOf<Model>(*original.system).OrbitOfModelAt(special.u);
  BasicOrbitContinuationSetup<Model> next = setup;
  if (special.type == "BP") {
    next.start = at;
    const BranchPointDirections d = SecondBranchDirection(*original.system, special.u, special.tangent);
    next.options.start_direction = side * d.second;
    return {std::move(next), d.singularity, at};
  }
  const int n = at.signature.size();
  next.start = Unfolded(at, special.type == "PD" ? 2 : 1);
  const int m = next.start.signature.size();
  next.unknowns = bifurcation_detail::Unfolded(setup.model.Description(), setup.unknowns, n, m / n);
  next.shooting = ShootingChoice::kSingle;
  next.options.start_direction.resize(0);
  const OrbitContinuationProblem unfolded = MakeOrbitContinuation(next);
  const Eigen::VectorXd known = bifurcation_detail::UnfoldedTangent(
      setup.model.Description(), VariableSetOf(setup.model, at.signature), original.system->free(), special.tangent,
      setup.unknowns.tie_static_friction, m, unfolded.system->free());
  const BranchPointDirections d = SecondBranchDirection(*unfolded.system, unfolded.start, known);
  next.options.start_direction = side * d.second;
  OrbitOfModel<Model> twice = next.start;
  return {std::move(next), d.singularity, std::move(twice)};
}

template <OscillatorModel Model>
BasicBifurcationBranchStart<Model> BranchFromBifurcation(const std::string& type,
                                                         const BasicOrbitContinuationSetup<Model>& setup, int side) {
  if (type != "PD" && type != "SB") {
    throw InvalidInput("special point", type,
                       "a period doubling (PD) or a symmetry breaking (SB): at a branch point (BP) the "
                       "branch's own tangent is needed, which result files do not keep");
  }
  BasicOrbitContinuationSetup<Model> on_point = setup;
  on_point.options.max_points = 1;
  on_point.options.start_direction.resize(0);
  // The known tangent towards increasing lambda, whatever the setup's direction: the second
  // direction's sign follows the known tangent's, so that only `side` picks the half.
  on_point.options.direction = 1;
  const OrbitContinuationProblem problem = MakeOrbitContinuation(on_point);
  const Branch branch = Continuation(*problem.system, nullptr, problem.options, problem.start).Run();
  if (branch.points.empty()) {
    throw InvalidInput::WithMessage("special point", fmt::format("special point: the {} does not lie on a branch of its "
                                                                 "type: {}", type, branch.end_message));
  }
  SpecialPoint special;
  special.type = type;
  special.u = branch.points.front().u;
  special.lambda = branch.points.front().lambda;
  special.tangent = branch.points.front().tangent;
  return BranchFromBifurcation(special, setup, side);
}

}  // namespace stickslip
