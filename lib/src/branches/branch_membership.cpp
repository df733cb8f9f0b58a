#include "stickslip/branches/branch_membership.hpp"
#include "stickslip/branches/model_branch_membership.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/orbits/orbit_origin.hpp"
#include "stickslip/orbits/signature_edits.hpp"

namespace stickslip {

namespace ov = orbit_variables;

void BranchMembershipOptions::ValidateTolerances() const {
  if (!(tolerance >= kMinTolerance && tolerance <= kMaxTolerance)) {
    throw InvalidInput("tolerance", tolerance, fmt::format("{} <= tolerance <= {}", kMinTolerance, kMaxTolerance));
  }
  least_period.Validate();
}

void BranchMembershipOptions::Validate() const {
  ValidateTolerances();
  if (!ParameterFromString(parameter)) {
    throw InvalidInput("parameter", fmt::format("'{}'", parameter), "a parameter: chi, eta, omega, u_s, u_r");
  }
}

std::vector<const OrbitBranch*> BranchesOf(const TraceResult& trace) {
  std::vector<const OrbitBranch*> branches;
  for (const TraceDirection* direction : {&trace.down, &trace.up}) {
    for (const TraceLink& link : direction->links) branches.push_back(&link.branch);
  }
  return branches;
}

namespace membership_detail {

bool SameTypeUpToOrigin(const Signature& signature, const Signature& candidate) {
  if (signature.size() != candidate.size() || signature.antisymmetric() != candidate.antisymmetric() ||
      signature.period_multiple() != candidate.period_multiple()) {
    return false;
  }
  for (int j = 0; j < OriginCount(candidate); ++j) {
    if (WithOriginAt(candidate, j) == signature) return true;
  }
  return false;
}

std::vector<Passage> PassagesBy(const std::vector<double>& values, double value, double tolerance) {
  std::vector<Passage> passages;
  const double margin = tolerance * (1.0 + std::abs(value));
  for (int i = 0; i + 1 < static_cast<int>(values.size()); ++i) {
    const double low = values[i];
    const double high = values[i + 1];
    if (value < std::min(low, high) - margin || value > std::max(low, high) + margin) continue;
    passages.push_back({i, high == low ? 0.0 : std::clamp((value - low) / (high - low), 0.0, 1.0)});
  }
  return passages;
}

std::string OnNoneMessage(std::size_t count, const std::string& parameter, double value, const Signature& signature,
                          double distance) {
  const std::string where = fmt::format("on none of {} branches at {} = {}", count, parameter, value);
  return std::isinf(distance) ? fmt::format("{}: none of type '{}' passes there", where, signature.ToString())
                              : fmt::format("{}: the nearest orbit of type '{}' is {:.3g} from it", where,
                                            signature.ToString(), distance);
}

}  // namespace membership_detail

namespace {

// The orbit at its least period when it reduces, else as given; an antisymmetric one over its whole
// period (FindOrbit writes a motion whose half-period symmetry it could not confirm to its
// tolerance as a plain orbit: the same motion).
Orbit LeastPeriodOf(const Orbit& orbit, const LeastPeriodOptions& options) {
  return Unfolded(ReduceToLeastPeriod(orbit, options).orbit, 1);
}

// How far `a` is from `b` as the tolerance measures it: the start states relative to b's, the
// phases in forcing cycles (modulo one).
double OrbitMismatch(const Orbit& a, const Orbit& b) {
  const State x = a.InitialState();
  const State y = b.InitialState();
  const double state = (x - y).lpNorm<Eigen::Infinity>() / (1.0 + y.lpNorm<Eigen::Infinity>());
  const double phase = std::abs(std::remainder(a.phi - b.phi, 2.0 * std::numbers::pi)) / (2.0 * std::numbers::pi);
  const double mismatch = std::max(state, phase);
  return std::isfinite(mismatch) ? mismatch : std::numeric_limits<double>::infinity();
}

// The smallest mismatch between `orbit` and `candidate` from any origin of the candidate whose
// signature is the orbit's; infinity when none is.
double MismatchOverOrigins(const Orbit& orbit, const Orbit& candidate) {
  double best = std::numeric_limits<double>::infinity();
  for (int j = 0; j < OriginCount(candidate.signature); ++j) {
    if (WithOriginAt(candidate.signature, j) != orbit.signature) continue;
    best = std::min(best, OrbitMismatch(orbit, WithOriginAt(candidate, j)));
  }
  return best;
}

// Every parameter of `a` but `skip` equal to b's within tolerance (relative to 1 + |b|).
bool OtherParametersAgree(const Parameters& a, const Parameters& b, ParameterId skip, double tolerance) {
  for (ParameterId id : kAllParameters) {
    if (id != skip && std::abs(a[id] - b[id]) > tolerance * (1.0 + std::abs(b[id]))) return false;
  }
  return true;
}

// The branch's orbit at `orbit`'s parameters: Newton from the points i and i + 1 interpolated at the
// parameter value, or where Newton does not converge (at a fold, singular at a fixed parameter) the
// interpolation itself.
Orbit BranchOrbitAt(const OrbitBranch& branch, int i, double t, const Orbit& orbit,
                                   const BranchMembershipOptions& options) {
  const Eigen::VectorXd a = ov::Pack(branch.orbits[i]);
  const Eigen::VectorXd b = ov::Pack(branch.orbits[i + 1]);
  Orbit guess = ov::Unpack(branch.orbits[i].signature, (1.0 - t) * a + t * b);
  guess.parameters = orbit.parameters;
  const UnknownChoice unknowns = UnknownsAtFixedParameters(guess.signature);
  const OrbitSolution solved =
      SolveOrbit(guess, FreeIndices(guess.signature, unknowns), unknowns.tie_static_friction, options.solver);
  return solved.summary.Converged() ? solved.orbit : guess;
}

// Where `branch` passes `value` of the parameter (PassagesBy).
std::vector<membership_detail::Passage> Passages(const OrbitBranch& branch, ParameterId parameter, double value,
                                                 double tolerance) {
  std::vector<double> values;
  for (const Orbit& orbit : branch.orbits) values.push_back(orbit.parameters[parameter]);
  return membership_detail::PassagesBy(values, value, tolerance);
}

struct PassageMatch {
  int point = -1;
  double distance = std::numeric_limits<double>::infinity();
};

// The passage of `branch` nearest to `least` (the orbit at its least period), and how near.
PassageMatch NearestPassage(const Orbit& least, const OrbitBranch& branch, ParameterId parameter,
                            const BranchMembershipOptions& options) {
  PassageMatch match;
  for (const auto& [i, t] : Passages(branch, parameter, least.parameters[parameter], options.tolerance)) {
    const Orbit& near = branch.orbits[t <= 0.5 ? i : i + 1];
    if (!OtherParametersAgree(least.parameters, near.parameters, parameter, options.tolerance)) continue;
    const Orbit there = BranchOrbitAt(branch, i, t, least, options);
    const double distance = MismatchOverOrigins(least, LeastPeriodOf(there, options.least_period));
    if (distance < match.distance) match = {i, distance};
  }
  return match;
}

}  // namespace

BranchMembership FindOnBranches(const Orbit& orbit, const std::vector<const OrbitBranch*>& branches,
                                const BranchMembershipOptions& options) {
  options.Validate();
  const ParameterId parameter = *ParameterFromString(options.parameter);
  const Orbit least = LeastPeriodOf(orbit, options.least_period);
  BranchMembership membership;
  for (int b = 0; b < static_cast<int>(branches.size()); ++b) {
    const OrbitBranch& branch = *branches[b];
    if (branch.orbits.empty()) continue;
    // Of its orbit, not its signature alone: a signature may repeat a shorter one whose orbit does not.
    const Signature branch_type = LeastPeriodOf(branch.orbits.front(), options.least_period).signature;
    if (!membership_detail::SameTypeUpToOrigin(least.signature, branch_type)) continue;
    const PassageMatch match = NearestPassage(least, branch, parameter, options);
    membership.distance = std::min(membership.distance, match.distance);
    if (match.distance <= options.tolerance) {
      membership = {true, b, match.point, match.distance,
                    fmt::format("on branch {} between its points {} and {} ({} = {}), {:.2g} from it", b, match.point,
                                match.point + 1, options.parameter, least.parameters[parameter], match.distance)};
      return membership;
    }
  }
  membership.message = membership_detail::OnNoneMessage(branches.size(), options.parameter, least.parameters[parameter],
                                                        least.signature, membership.distance);
  return membership;
}

}  // namespace stickslip
