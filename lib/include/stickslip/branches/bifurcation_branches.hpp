// The branch that leaves a smooth bifurcation of a branch of orbits (AUTO's ISW = -1):
//   BP  the second branch through the point, of the same orbit type;
//   PD  a multiplier through -1: the period-2 orbits, of the type unfolded over two periods
//       (orbits/signature_edits.hpp: the whole period's segments twice, period multiple doubled),
//       cross the period-1 orbit traversed twice. In the period-2 problem that orbit is a branch
//       point (shifting the orbit by one period is a symmetry of the problem): the period-2
//       branch leaves it along the null vector of the period-2 Jacobian orthogonal to the
//       traversed-twice branch (continuation/branch_switching.hpp), the eigenvector of the
//       multiplier -1 in the states;
//   SB  a symmetry breaking of an antisymmetric orbit (a multiplier -1 of the half-period map
//       with the mirror, orbits/stability.hpp): the orbits without the symmetry, of the type over
//       the whole period, cross the antisymmetric one there, again as a branch point.
// The returned setup starts on the point; its first point lies ds along the new branch. At a PD
// and an SB the new problem is solved by single shooting (the known branch's tangent is exact
// there: a repetition of the original tangent).
// For any model (model/oscillator_model.hpp): the paper's model is compiled once
// (bifurcation_branches.cpp); another model's includes branches/model_bifurcation_branches.hpp.
#pragma once

#include "stickslip/branches/orbit_continuation.hpp"

namespace stickslip {

template <OscillatorModel Model>
struct BasicBifurcationBranchStart {
  BasicOrbitContinuationSetup<Model> setup;  // ContinueOrbit(setup) follows the new branch
  // sigma_n / sigma_1 of the new problem's Jacobian at the point: zero at an exact branch point,
  // the location's rounding at a located one; not small where the point is no bifurcation.
  double singularity = 0.0;
  OrbitOfModel<Model> at;  // the bifurcation point's orbit as an orbit of the new type (traversed twice at a PD)
};
using BifurcationBranchStart = BasicBifurcationBranchStart<Pascal2014>;

// The branch that leaves `special` (a "BP", "PD" or "SB" of the branch continued from `setup`) on
// the side `side` (+1 or -1: the two halves of the new branch; at a PD they are the same orbits
// shifted by one period, at an SB mirror images). Throws InvalidInput naming "special point" for
// another type, and "side".
template <OscillatorModel Model>
BasicBifurcationBranchStart<Model> BranchFromBifurcation(const SpecialPoint& special,
                                                         const BasicOrbitContinuationSetup<Model>& setup, int side = 1);

// The same from a stored point (a restart: `setup.start` is the orbit of a PD or an SB, `type`
// its type), whose tangent on the branch of `setup` is computed there: the branch is regular at
// a PD and an SB (the crossing lies in the unfolded problem). A BP needs the tangent of the branch
// that located it (the overload above): throws InvalidInput naming "special point" for it, for
// any other type, and where the start does not converge on its branch.
template <OscillatorModel Model>
BasicBifurcationBranchStart<Model> BranchFromBifurcation(const std::string& type,
                                                         const BasicOrbitContinuationSetup<Model>& setup, int side = 1);

extern template BifurcationBranchStart BranchFromBifurcation(const SpecialPoint& special,
                                                             const OrbitContinuationSetup& setup, int side);
extern template BifurcationBranchStart BranchFromBifurcation(const std::string& type,
                                                             const OrbitContinuationSetup& setup, int side);

}  // namespace stickslip
