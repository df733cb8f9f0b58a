// "Is this orbit on a branch already?": whether an orbit (a found one, a brute-force attractor's
// exact orbit) lies on one of the branches a trace gave, and where.
//
// An orbit lies on a branch when, at the orbit's value of the branch's parameter (all other
// parameters equal), the branch's orbit there is the same motion: the same least-period type
// (orbits/least_period.hpp: a period-1 orbit written over three periods is the period-1 orbit) up to
// the choice of origin (orbits/orbit_origin.hpp: FindOrbit and a trace may start the period at
// different segment ends), and the same state and phase at that origin. The branch's orbit at the
// parameter is the one Newton converges to at that value from the branch's points on either side,
// interpolated linearly, or the interpolation itself where Newton fails (at a fold, where the
// equations at a fixed parameter are singular); a branch that folds back passes some values
// several times: each passage is tried.
//
//   const BranchMembership m = FindOnBranches(found.solution->orbit, BranchesOf(trace), {});
//   if (m.on_branch) std::cout << "branch " << m.branch << ", point " << m.point;
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "stickslip/branches/orbit_continuation.hpp"
#include "stickslip/branches/trace.hpp"
#include "stickslip/orbits/least_period.hpp"
#include "stickslip/orbits/orbit.hpp"
#include "stickslip/orbits/orbit_solver.hpp"

namespace stickslip {

struct BranchMembershipOptions {
  std::string parameter = "omega";  // the branches' continued variable (an orbit variable's name)
  // Same motion: every parameter other than `parameter` within tolerance (1 + |p|), and at the
  // common origin |X - Y|_inf <= tolerance (1 + |Y|_inf) for the states x10, x20, v10 and the
  // phases within tolerance 2 pi (modulo 2 pi). From kMinTolerance to kMaxTolerance.
  double tolerance = 1e-6;
  LeastPeriodOptions least_period;  // the reduction of both orbits to their least period
  OrbitSolverOptions solver;        // Newton at the orbit's parameter value

  static constexpr double kMinTolerance = 1e-14;
  static constexpr double kMaxTolerance = 1e-1;
  void Validate() const;  // throws InvalidInput naming "tolerance" or "parameter" (the paper's names)
  void ValidateTolerances() const;  // Validate but the parameter, which another model names (tolerance, least_period)
};

struct BranchMembership {
  bool on_branch = false;
  int branch = -1;  // index into the branches searched, where on_branch
  // The branch's point on the near side of the passage (its points `point` and `point` + 1 bracket
  // the parameter value), where on_branch.
  int point = -1;
  // The smallest distance seen (relative state or phase, as the tolerance), over every passage of a
  // branch of the same least-period type; infinity when none was of that type.
  double distance = std::numeric_limits<double>::infinity();
  std::string message;  // one line: where it lies, or why on none
};

// Whether `orbit` lies on one of `branches` (the first it lies on, in the order given). Throws
// InvalidInput for invalid options or an orbit whose durations do not match its signature.
BranchMembership FindOnBranches(const Orbit& orbit, const std::vector<const OrbitBranch*>& branches,
                                const BranchMembershipOptions& options = {});

// Every branch of a trace, in the order searched: the down direction's links, then the up's.
std::vector<const OrbitBranch*> BranchesOf(const TraceResult& trace);

}  // namespace stickslip
