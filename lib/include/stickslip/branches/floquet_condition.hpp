// The defining conditions of the smooth bifurcations of periodic orbits, for their curves in two
// parameters (branches/boundary_curve.hpp), with the monodromy matrix M (orbits/stability.hpp):
//   LP  a multiplier +1: a fold of the orbit branch             A = M - I
//   PD  a multiplier -1: a period doubling                      A = M + I
//   SB  of an antisymmetric orbit, a multiplier -1 of the half-period map with the mirror, H =
//       -M_half: a symmetry-breaking pitchfork                  A = I - M_half
//   TR  a pair with mu_i mu_j = 1, on the unit circle: a torus  A = M^[2] - I, M^[2] the second
//       compound matrix (its 2 x 2 minors), whose eigenvalues are the products mu_i mu_j (i < j)
// each as the minimally augmented test function sigma of A (Govaerts, Numerical Methods for
// Bifurcations of Dynamical Equilibria, 2000; BifurcationKit's codim2/MinAugFold.jl):
//   [A b; c^T 0] [v; sigma] = [0; 1],   [A^T c; b^T 0] [w; sigma] = [0; 1],
// zero exactly where A is singular, with the exact derivative dsigma/dz = -w^T (dA/dz) v
// (orbits/floquet_gradients.hpp). The borders b, c are A's left and right singular vectors of
// its smallest singular value at the curve's start: the bordered matrix stays regular while A's
// null vectors stay away from being orthogonal to them.
//
// A PD of an antisymmetric orbit is not of codimension one (det(M + I) = |det(H - iI)|^2 cannot
// change sign there): its curve is the SB's. Along a TR curve the pair may turn real (mu_i mu_j =
// 1 with mu_i != conj(mu_j): a neutral saddle, no torus), which the recorded multipliers show.
#pragma once

#include <memory>
#include <string_view>

#include "stickslip/branches/orbit_condition.hpp"

namespace stickslip {

// The condition of `type` ("LP", "PD", "SB", "TR") with its borders from the orbit of `problem` at
// `u`, at (or near) such a point. Throws InvalidInput naming "condition" for another type, a PD or SB where
// it is not of codimension one, or a start where A is not near singular (its smallest singular
// value, relative to the largest, above `max_singularity`) or, for TR, where no complex pair lies
// near the unit circle.
std::shared_ptr<const OrbitCondition> FloquetCondition(std::string_view type, const OrbitProblem& problem,
                                                       const Eigen::VectorXd& u, double max_singularity = 1e-4);

}  // namespace stickslip
