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

#include <memory>
#include <string>
#include <string_view>

#include <Eigen/Core>

#include "stickslip/branches/orbit_continuation.hpp"
#include "stickslip/model/linear_oscillator.hpp"

namespace stickslip {

// Where a curve starts: a located special point of a branch.
template <OscillatorModel Model>
struct BasicCurveStart {
  OrbitOfModel<Model> orbit;  // the orbit at the located point
  std::string condition;      // "LP", "PD", "SB", "TR", or a margin's column name "margin:G:2"
  std::string parameter;      // the branch's continued parameter, e.g. "omega"
  UnknownChoice unknowns;     // the branch's unknowns (the parameter held)
};
using CurveStart = BasicCurveStart<Pascal2014>;

// The condition BoundaryCurve continues for a special point: its margin for a type change (the
// test function "margin:..."), else its type ("LP", "PD", ...).
std::string CurveCondition(const std::string& type, const std::string& test_function);

// The condition named `condition` (CurveStart's) at the orbit of `problem` at `u`: a margin's
// zero (margin_condition.hpp) or a multiplier's (floquet_condition.hpp). Throws InvalidInput
// naming "condition" for one this gives no curve of there.
std::shared_ptr<const OrbitCondition> MakeCurveCondition(std::string_view condition, const OrbitProblem& problem,
                                                         const Eigen::VectorXd& u);
// Throws InvalidInput naming "second" unless `second` is a parameter the model varies (of
// `layout`, less `unvaried`: an autonomous model's forcing frequency, or -1) other than the
// continued `parameter`, not released in `unknowns` already nor tied to a released one (the
// static level tied to the kinetic).
void CheckSecondParameter(const OrbitLayout& layout, int static_level, int unvaried, const UnknownChoice& unknowns,
                          std::string_view parameter, std::string_view second);

// The setup whose ContinueOrbit follows the curve through `start` in the plane of its parameter and
// `second` (a parameter the model varies, released), with the options, shooting and flow of
// `branch_setup`, for any model. Throws InvalidInput naming "condition" for a point whose
// condition this gives no curve of (an LP of an orbit without forcing among them), and "second" for a second parameter that is the continued one,
// already released, or no parameter the model varies. Compiled for the paper's model and a
// [model]'s (boundary_curve.cpp); for another model include branches/model_boundary_curve.hpp.
template <OscillatorModel Model>
BasicOrbitContinuationSetup<Model> BoundaryCurve(const BasicCurveStart<Model>& start,
                                                 const BasicOrbitContinuationSetup<Model>& branch_setup,
                                                 std::string_view second);

// Compiled once, in boundary_curve.cpp, for the paper's model and a [model]'s.
extern template OrbitContinuationSetup BoundaryCurve(const CurveStart&, const OrbitContinuationSetup&, std::string_view);
extern template BasicOrbitContinuationSetup<DynamicLinearOscillator> BoundaryCurve(
    const BasicCurveStart<DynamicLinearOscillator>&, const BasicOrbitContinuationSetup<DynamicLinearOscillator>&,
    std::string_view);

}  // namespace stickslip
