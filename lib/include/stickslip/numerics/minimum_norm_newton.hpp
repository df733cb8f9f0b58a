// Newton's method for a square system whose solutions are not isolated: through each runs a family
// of solutions, along which the Jacobian is rank-deficient (an undamped oscillator forced at
// r = 1/(2n) of its natural frequency has a continuum of periodic orbits: Csernak, Stepan & Shaw,
// Nonlinear Dyn. 2007). Newton's step is undefined there; the minimum-norm least-squares step
// (the SVD's pseudo-inverse, truncated at the rank) moves the iterate only across the family, to
// its nearest member, and the family's dimension is the Jacobian's nullity at that member.
#pragma once

#include <Eigen/Core>

#include "stickslip/numerics/newton.hpp"

namespace stickslip {

struct MinimumNormNewtonOptions {
  int max_iterations = 30;
  double residual_tolerance = 1e-12;  // converged when max|F| <= this
  // A singular value is zero below this, relative to the largest.
  double rank_tolerance = 1e-9;
};

struct MinimumNormNewtonResult {
  NewtonResult newton;  // its summary's termination: converged, max-iterations, diverged or left-domain
  int nullity = 0;      // of the Jacobian at the last iterate: the family's dimension where converged
  Eigen::MatrixXd null_space;  // its orthonormal basis (UnknownCount x nullity)
};

// Dense Jacobians (a sparse one is made dense: the systems it serves are small). A Jacobian that is
// not finite ends it as diverged.
MinimumNormNewtonResult SolveMinimumNorm(const NonlinearSystem& system, const Eigen::VectorXd& guess,
                                         const MinimumNormNewtonOptions& options = {});

}  // namespace stickslip
