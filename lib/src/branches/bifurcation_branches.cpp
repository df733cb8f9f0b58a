#include "stickslip/branches/bifurcation_branches.hpp"

#include <string>

#include <fmt/format.h>

#include "stickslip/continuation/branch_switching.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/orbits/signature_edits.hpp"

namespace stickslip {

namespace ov = orbit_variables;

namespace {

// The held durations of the unfolded type: every copy of a held duration of the original.
UnknownChoice Unfolded(const UnknownChoice& choice, int listed, int repeats) {
  UnknownChoice unfolded = choice;
  unfolded.fix.clear();
  for (const std::string& name : choice.fix) {
    const std::optional<int> index = ov::IndexOf(listed, name);
    if (!index || *index < ov::Duration(0) || *index >= ov::Duration(listed)) {
      unfolded.fix.push_back(name);
      continue;
    }
    for (int k = 0; k < repeats; ++k) {
      unfolded.fix.push_back(ov::Name(listed * repeats, *index + k * listed));
    }
  }
  return unfolded;
}

}  // namespace

BifurcationBranchStart BranchFromBifurcation(const SpecialPoint& special, const OrbitContinuationSetup& setup,
                                             int side) {
  if (special.type != "BP" && special.type != "PD" && special.type != "SB") {
    throw InvalidInput("special point", special.type,
                       "a branch point (BP), a period doubling (PD) or a symmetry breaking (SB)");
  }
  if (side != 1 && side != -1) throw InvalidInput("side", side, "+1 or -1");
  const OrbitContinuationProblem original = MakeOrbitContinuation(setup);
  const Orbit at = ToOrbit(*original.system, special.u);
  OrbitContinuationSetup next = setup;
  if (special.type == "BP") {
    next.start = at;
    const BranchPointDirections d = SecondBranchDirection(*original.system, special.u, special.tangent);
    next.options.start_direction = side * d.second;
    return {std::move(next), d.singularity, at};
  }
  // The tangent on the orbit's variables (the leading unknowns are variables, in the order of
  // free(); multiple shooting's interior states follow), repeated over the unfolded segments.
  const int n = at.signature.size();
  const std::vector<int>& free = original.system->free();
  Eigen::VectorXd tangent = Eigen::VectorXd::Zero(ov::Count(n));
  for (std::size_t k = 0; k < free.size(); ++k) tangent(free[k]) = special.tangent(static_cast<int>(k));
  if (setup.unknowns.tie_static_friction) {
    tangent(ov::StaticLevel(n)) = tangent(ov::KineticLevel(n));
  }
  next.start = Unfolded(at, special.type == "PD" ? 2 : 1);
  const int m = next.start.signature.size();
  next.unknowns = Unfolded(setup.unknowns, n, m / n);
  next.shooting = ShootingChoice::kSingle;
  next.options.start_direction.resize(0);
  const OrbitContinuationProblem doubled = MakeOrbitContinuation(next);
  Eigen::VectorXd repeated(ov::Count(m));
  repeated.head(ov::Duration(0)) = tangent.head(ov::Duration(0));
  for (int j = 0; j < m; ++j) repeated(ov::Duration(j)) = tangent(ov::Duration(j % n));
  repeated.tail(kParameterCount) = tangent.tail(kParameterCount);
  const std::vector<int>& doubled_free = doubled.system->free();
  Eigen::VectorXd known(static_cast<Eigen::Index>(doubled_free.size()));
  for (std::size_t k = 0; k < doubled_free.size(); ++k) known(static_cast<int>(k)) = repeated(doubled_free[k]);
  const BranchPointDirections d = SecondBranchDirection(*doubled.system, doubled.start, known);
  next.options.start_direction = side * d.second;
  Orbit twice = next.start;
  return {std::move(next), d.singularity, std::move(twice)};
}

BifurcationBranchStart BranchFromBifurcation(const std::string& type, const OrbitContinuationSetup& setup,
                                             int side) {
  if (type != "PD" && type != "SB") {
    throw InvalidInput("special point", type,
                       "a period doubling (PD) or a symmetry breaking (SB): at a branch point (BP) the "
                       "branch's own tangent is needed, which result files do not keep");
  }
  OrbitContinuationSetup on_point = setup;
  on_point.options.max_points = 1;
  on_point.options.start_direction.resize(0);
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
