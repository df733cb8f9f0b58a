// A type boundary's defining condition (issue 13): the admissibility margin of a given name
// (orbits/margins.hpp: "reversal:1", "G:3", "velocity:2") is zero. Added to the periodicity
// equations of the orbit's own type with a second parameter released (branches/boundary_curve.hpp),
// it defines the curve in the plane of two parameters where that type changes. The margin is
// identified by its name; its position in AdmissibilityMargins depends only on the signature.
//
//   end margins       duration:i of a stick, stop-slope:i, reversal:i, stick-entry:i,
//                     abnormal-stop:i, exit-slope:i, and G:i, G1:i where their minimum over the
//                     stick lies at its start or end at the start orbit: one equation, the margin
//                     itself, with its exact gradient (orbits/margin_gradients.hpp, MarginGradients).
//   interior extrema  velocity:i, and G:i, G1:i where their minimum lies inside the stick at the
//                     start orbit: the minimum's time is an unknown of the condition, tau, the time
//                     elapsed in the segment (from the segment's start, not from the orbit's
//                     origin: the time within the segment is what the closed form is evaluated at,
//                     and it stays inside (0, d_i) whatever the earlier durations do), with two
//                     equations, f(tau) = 0 and f_tau(tau) = 0 (MarginGradientAt: exact in the
//                     variables and in tau, f_tau_tau).
//
// Refused (InvalidInput naming "condition"): a margin the orbit type has not; a slip's duration:i
// (at zero length a slip's end condition, x2' = 0, holds identically: the periodicity equations
// lose an equation there and give no regular curve; a slip can shrink to nothing only where the
// acceleration at its start does, at the zero of the margin of the end before it, which the
// message names); sliding-friction (u_s = 0 ends the physical family: no boundary between orbit
// types); an interior margin with no interior minimum at the start orbit (velocity:i = +inf there)
// or one that is not defined there (NaN); an interior minimum of the constraint that ends the stick
// (G:i into slip+, G1:i into slip-) with exit-slope:i <= 0 at the start orbit (no maximum between
// the minimum and the exit: they are one double root, the tangential exit, whose regular condition
// is exit-slope:i; continued as an interior minimum it has tau = d_i, a Jacobian of deficient rank
// all along the curve and a spurious BP at every sign change of the rounding in tau - d_i).
//
// Along the curve, the margins that sit on zero identically (Defining()) are recorded, not watched:
//   every margin                its own column;
//   duration:i of a stick       also stick-entry of the slip before it, and the constraint that
//                               ends the stick (G1:i into slip-, G:i into slip+), whose value at
//                               the stick's start is zero at zero length;
//   stick-entry:i               also the constraint of the stick after it that the force entered
//                               at (G:i+1 where s = -eta u_r, G1:i+1 where s = +eta u_r);
//   G:i, G1:i at the stick's start  also stick-entry of the slip before it;
//   stop-slope:i, exit-slope:i  also the multipliers' tests (PD, TR, SB): at a tangential stop or
//                               exit the saltation matrix divides by the slope, so they mean
//                               nothing there (measured: 79 and 185 sign changes through poles
//                               along the §5.1 and §6 exit-slope curves when they were watched).
// Not watched either, since the curve cannot tell: a second interior minimum of the same function
// reaching zero (the condition follows the one it started on).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "stickslip/branches/orbit_condition.hpp"
#include "stickslip/orbits/margins.hpp"

namespace stickslip {

class MarginCondition final : public OrbitCondition {
 public:
  // `margin` is the margin's name ("G:3", as Margin::Name() gives it), the orbit of `problem` at
  // `u` one of the type near or on the boundary (where the interior minimum is chosen and its time
  // read). Throws InvalidInput naming "condition" (the value "margin:<name>") for the refusals above.
  MarginCondition(const OrbitProblem& problem, const Eigen::VectorXd& u, std::string_view margin);

  std::string Name() const override;  // "margin:G:3", the monitor's column
  int ExtraUnknownCount() const override { return interior_ ? 1 : 0; }
  // The interior minimum's time in its segment at the orbit (found by AdmissibilityMargins' root
  // finder); nothing for an end margin.
  Eigen::VectorXd ExtraUnknowns(const OrbitProblem& problem, const Eigen::VectorXd& u) const override;
  // End margin: {margin}. Interior: {f(tau), f_tau(tau)}, extra = {tau}.
  void Evaluate(const OrbitProblem& problem, const Eigen::VectorXd& u, const Eigen::VectorXd& extra,
                Eigen::VectorXd* residual, Eigen::MatrixXd* d_variables, Eigen::MatrixXd* d_extra) const override;
  std::vector<std::string> Defining() const override { return defining_; }

  bool Interior() const { return interior_; }

 private:
  Margin margin_;  // base, kind and segment (the value and time are the start orbit's)
  int index_ = 0;  // in AdmissibilityMargins
  bool interior_ = false;
  std::vector<std::string> defining_;
};

}  // namespace stickslip
