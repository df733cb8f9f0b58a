// Curves of codimension-one points in the plane of two parameters (issue 13): from a located
// special point of a branch, the periodicity equations with the defining condition of that point
// added (branches/orbit_condition.hpp) and a second parameter released, continued by the engine as
// any branch. Along the curve the monitor watches the other test functions: a margin's sign change
// is the curve meeting another type boundary, the engine's LP a fold of the curve itself (a cusp
// of a fold curve), EP its ends; these are the curve's codimension-two points, special points of
// its result files that later runs restart from.
//   type boundaries  a margin through zero (the located type change's): condition margin = 0, with
//                    the extremum time as an unknown for an interior extremum (velocity:i, G:i,
//                    G1:i) and its stationarity
//   LP, PD, SB, TR   a Floquet multiplier at +1, at -1, a multiplier -1 of the half-period map of an
//                    antisymmetric orbit, a pair mu_i mu_j = 1 (orbits/floquet_gradients.hpp)
#pragma once

#include <string>
#include <string_view>

#include "stickslip/branches/orbit_continuation.hpp"

namespace stickslip {

// Where a curve starts: a located special point of a branch.
struct CurveStart {
  Orbit orbit;            // the orbit at the located point
  std::string condition;  // "LP", "PD", "SB", "TR", or a margin's column name "margin:G:2"
  std::string parameter;  // the branch's continued parameter, e.g. "omega"
  UnknownChoice unknowns;  // the branch's unknowns (the parameter held)
};

// The setup whose ContinueOrbit follows the curve through `start` in the plane of its parameter and
// `second` (chi, eta, omega, u_s or u_r; released), with the options, shooting and flow of
// `branch_setup`. Throws InvalidInput naming "condition" for a point whose condition this gives no
// curve of, and "second" for a second parameter that is the continued one, already released, or
// no parameter.
OrbitContinuationSetup BoundaryCurve(const CurveStart& start, const OrbitContinuationSetup& branch_setup,
                                     std::string_view second);

}  // namespace stickslip
