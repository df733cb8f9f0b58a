// Branch switching at a simple branch point (AUTO's ISW = -1, BifurcationKit's continuation from
// a bifurcation point): where two branches cross, the Jacobian J (n x (n+1)) of the problem has a
// two-dimensional null space that holds both tangents. Given the tangent of the branch that led
// there, the second branch leaves along the null vector orthogonal to it: a Continuation started
// on the point with ContinuationOptions::start_direction set to that vector (or its opposite)
// follows the second branch. At a transcritical point the second branch's own tangent is not
// orthogonal to the first, but its first point, corrected on the hyperplane orthogonal to the
// direction, still lies on it.
//
//   const BranchPointDirections d = SecondBranchDirection(problem, bp.u, bp.tangent);
//   options.start_direction = d.second;
//   Continuation(problem, monitor, options, bp.u).Run();
#pragma once

#include <Eigen/Core>

#include "stickslip/numerics/newton.hpp"

namespace stickslip {

struct BranchPointDirections {
  Eigen::VectorXd second;  // unit, orthogonal to the known tangent, in the null space of J
  // sigma_n / sigma_1, the smallest singular value of J relative to the largest: zero at an exact
  // branch point, the location's rounding at a located one (1e-9, say); not small where the
  // point is no branch point (then `second` is no tangent of anything).
  double singularity = 0.0;
};

// v / |v| for a finite nonzero v of any length: where |v|^2 would overflow (components of 1e300)
// or lose digits to underflow (1e-300), v is scaled first (Eigen's stableNormalized); elsewhere
// the plain quotient, to the bit.
Eigen::VectorXd UnitDirection(const Eigen::VectorXd& v);

// Throws std::invalid_argument if u or known_tangent do not have the problem's unknown count or
// known_tangent is zero or not finite.
BranchPointDirections SecondBranchDirection(const NonlinearSystem& problem, const Eigen::VectorXd& u,
                                            const Eigen::VectorXd& known_tangent);

}  // namespace stickslip
