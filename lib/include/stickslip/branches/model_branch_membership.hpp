// FindOnBranches (branch_membership.hpp) for any model (model/oscillator_model.hpp): whether an
// orbit lies on one of a trace's branches, and where. The rule is the paper's: the same
// least-period type up to the choice of origin, and at the orbit's value of the branch's parameter
// (every other parameter equal) the branch's orbit there, solved by Newton from the interpolation of
// its points on either side, is the same motion. Both orbits are written over their whole period
// (an antisymmetric one's mirrored half listed), so that every origin is a segment's start: its
// state and phase by the one walk (segment_walk.hpp); the state is compared relative to the orbit's
// size (OrbitSize: a model in physical units), the phase in forcing cycles (not at all without
// forcing, whose phase is pinned by an event).
//
//   const BranchMembership m = FindOnModelBranches(model, found.solution->orbit, branches, {.parameter = "omega"});
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "stickslip/branches/branch_membership.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/orbits/any_orbit.hpp"
#include "stickslip/orbits/least_period.hpp"
#include "stickslip/orbits/model_orbit_solver.hpp"
#include "stickslip/orbits/orbit_origin.hpp"
#include "stickslip/orbits/segment_walk.hpp"
#include "stickslip/orbits/signature_edits.hpp"
#include "stickslip/orbits/verification.hpp"

namespace stickslip {

namespace membership_detail {

// Whether some origin of `candidate` gives `signature`: the same type, another origin.
bool SameTypeUpToOrigin(const Signature& signature, const Signature& candidate);

// Where a passage of a branch brackets a parameter value: points i and i + 1, a fraction t of the way.
struct Passage {
  int point = 0;
  double t = 0.0;
};

// The passages of a branch whose successive parameter values are `values` by `value`, each interval
// widened by tolerance (1 + |value|): a start located at a branch's end lies a rounding error outside it.
std::vector<Passage> PassagesBy(const std::vector<double>& values, double value, double tolerance);

// The message of an orbit (of type `signature`, at `parameter` = value) on none of `count` branches,
// the nearest of its type `distance` from it (infinity: none of its type passes there).
std::string OnNoneMessage(std::size_t count, const std::string& parameter, double value, const Signature& signature,
                          double distance);

template <OscillatorModel Model>
BasicOrbit<Model> LeastPeriodOf(const Model& model, const BasicOrbit<Model>& orbit, const LeastPeriodOptions& options) {
  return Unfolded(ReduceToLeastPeriod(model, orbit, options).orbit, 1);
}

// The smallest mismatch between `orbit` and `candidate` over the candidate's origins whose
// signature is the orbit's: the state relative to the candidate's size, the phase in forcing cycles
// (modulo one; a forced model's only). Infinity when no origin gives the orbit's signature. Both are
// written over their whole period (LeastPeriodOf): every origin is the start of a listed segment.
template <OscillatorModel Model>
double MismatchOverOrigins(const Model& model, const BasicOrbit<Model>& orbit, const BasicOrbit<Model>& candidate) {
  const double size = OrbitSize(model, candidate);
  std::vector<std::pair<typename Model::State, double>> origins;  // the start state and phase of each segment
  WalkSegments(model, candidate, Extent::kListed, PhaseRule::kFromOrigin,
               [&](const SegmentVisit<double, Model>& s) { origins.emplace_back(s.start, s.phase); });
  double best = std::numeric_limits<double>::infinity();
  for (int j = 0; j < candidate.signature.size(); ++j) {
    if (WithOriginAt(candidate.signature, j) != orbit.signature) continue;
    const auto& [start, phase] = origins[j];
    double mismatch = (orbit.start - start).template lpNorm<Eigen::Infinity>() / size;
    if (!model.Autonomous()) {
      const double turn = std::remainder(phase - orbit.phi, 2.0 * std::numbers::pi);
      mismatch = std::max(mismatch, std::abs(turn) / (2.0 * std::numbers::pi));
    }
    if (std::isfinite(mismatch)) best = std::min(best, mismatch);
  }
  return best;
}

// The branch's orbit at `target`'s parameters: Newton from points i and i + 1 interpolated (start,
// phase and durations), or where it does not converge (a fold) the interpolation itself.
template <OscillatorModel Model>
BasicOrbit<Model> BranchOrbitAt(const Model& model, const BasicOrbitBranch<Model>& branch, Passage passage,
                                const BasicOrbit<Model>& target, const BranchMembershipOptions& options) {
  const BasicOrbit<Model>& a = AsBasicOrbit(branch.orbits[passage.point]);
  const BasicOrbit<Model>& b = AsBasicOrbit(branch.orbits[passage.point + 1]);
  const double t = passage.t;
  BasicOrbit<Model> guess = a;
  guess.parameters = target.parameters;
  guess.start = (1.0 - t) * a.start + t * b.start;
  // The phase the short way round: two points a stored reduction to [0, 2 pi) put either side of 0.
  guess.phi = a.phi + t * std::remainder(b.phi - a.phi, 2.0 * std::numbers::pi);
  for (std::size_t k = 0; k < guess.durations.size(); ++k) guess.durations[k] = (1.0 - t) * a.durations[k] + t * b.durations[k];
  const OrbitVariableSet variables = VariableSetOf(model, guess.signature);
  const UnknownChoice unknowns = UnknownsAtFixedParameters(variables);
  try {
    const BasicOrbitSolution<Model> solved =
        SolveOrbit(model, guess, FreeIndices(variables, unknowns), unknowns.tie_static_friction, options.solver);
    return solved.summary.Converged() ? solved.orbit : guess;
  } catch (const InvalidInput&) {  // an abnormal stop: not square at fixed parameters
    return guess;
  }
}

// Every parameter but the continued one (index `skip`) equal within tolerance (relative to 1 + |b|).
template <OscillatorModel Model>
bool OtherParametersAgree(const typename Model::Parameters& a, const typename Model::Parameters& b, int skip,
                          int count, double tolerance) {
  for (int k = 0; k < count; ++k) {
    const double x = Model::ParameterAt(a, k);
    const double y = Model::ParameterAt(b, k);
    if (k != skip && std::abs(x - y) > tolerance * (1.0 + std::abs(y))) return false;
  }
  return true;
}

}  // namespace membership_detail

// Whether `orbit` lies on one of `branches` (the first it lies on, in the order given), the
// branches' parameter options.parameter by the model's name. Throws InvalidInput for invalid options
// (a parameter the model does not have) or durations that do not match the orbit's signature.
template <OscillatorModel Model>
BranchMembership FindOnModelBranches(const Model& model, const BasicOrbit<Model>& orbit,
                                     const std::vector<const BasicOrbitBranch<Model>*>& branches,
                                     const BranchMembershipOptions& options) {
  namespace detail = membership_detail;
  options.ValidateTolerances();
  const ModelDescription& description = model.Description();
  const std::optional<int> parameter = description.ParameterIndex(options.parameter);
  if (!parameter) throw InvalidInput("parameter", fmt::format("'{}'", options.parameter), "one of the model's parameters");
  const int count = static_cast<int>(description.parameters.size());
  const BasicOrbit<Model> least = detail::LeastPeriodOf(model, orbit, options.least_period);
  const double value = Model::ParameterAt(least.parameters, *parameter);
  BranchMembership membership;
  for (int b = 0; b < static_cast<int>(branches.size()); ++b) {
    const BasicOrbitBranch<Model>& branch = *branches[b];
    if (branch.orbits.empty()) continue;
    const BasicOrbit<Model>& first = AsBasicOrbit(branch.orbits.front());
    if (!detail::SameTypeUpToOrigin(least.signature, detail::LeastPeriodOf(model, first, options.least_period).signature)) {
      continue;
    }
    std::vector<double> values;
    for (const auto& o : branch.orbits) values.push_back(Model::ParameterAt(AsBasicOrbit(o).parameters, *parameter));
    for (const detail::Passage& passage : detail::PassagesBy(values, value, options.tolerance)) {
      const auto& near = AsBasicOrbit(branch.orbits[passage.t <= 0.5 ? passage.point : passage.point + 1]);
      if (!detail::OtherParametersAgree<Model>(least.parameters, near.parameters, *parameter, count, options.tolerance)) continue;
      const BasicOrbit<Model> there = detail::BranchOrbitAt(model, branch, passage, least, options);
      const double distance = detail::MismatchOverOrigins(model, least, detail::LeastPeriodOf(model, there, options.least_period));
      if (distance < membership.distance) membership.distance = distance;
      if (distance <= options.tolerance) {
        membership = {true, b, passage.point, distance,
                      fmt::format("on branch {} between its points {} and {} ({} = {}), {:.2g} from it", b, passage.point,
                                  passage.point + 1, options.parameter, value, distance)};
        return membership;
      }
    }
  }
  membership.message =
      detail::OnNoneMessage(branches.size(), options.parameter, value, least.signature, membership.distance);
  return membership;
}

}  // namespace stickslip
