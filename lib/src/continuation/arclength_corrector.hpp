// The predictor and corrector of pseudo-arclength continuation (Keller): from an accepted point
// u_a with unit tangent t, the predictor u_a + s t, corrected by Newton on
// [F(u); t.(u - u_a) - s] = 0; then the tangent there, oriented along the branch.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include <Eigen/Core>

#include "stickslip/continuation/continuation.hpp"

namespace stickslip::detail {

// A point of the branch with everything a test function may need there.
struct Sample {
  Eigen::VectorXd u;        // every unknown, lambda included
  Eigen::VectorXd tangent;  // unit tangent, oriented along the branch
  int det_sign = 0;         // sign of det [J; t^T], for branch points
  Eigen::VectorXd tests;    // the monitor's test functions
  Eigen::VectorXd recorded;  // the monitor's recorded values, at points the branch may keep
  int iterations = 0;       // corrector iterations that found it
};

// Why a point is corrected. A step may fail and be shortened; a point while locating an event
// cannot, so its corrector is allowed more iterations. Trial points of the location are not kept:
// they go without the recorded values.
enum class Attempt { kStep, kLocationTrial, kLocated };

class ArclengthCorrector {
 public:
  // Keeps references to all three: they must outlive it.
  ArclengthCorrector(const NonlinearSystem& problem, const Monitor* monitor, const ContinuationOptions& options);

  // `guess` corrected at its lambda, with the tangent towards options.direction in lambda (at a
  // fold, across the lambda axis, either way); with options.start_direction, the point at
  // arclength options.step.ds from `guess` along it;
  // nullopt if Newton fails or the bordered Jacobian is singular (why: last_failure()).
  std::optional<Sample> Start(const Eigen::VectorXd& guess);
  // The point at arclength s from `from` along its tangent; nullopt if the corrector fails
  // (why: last_failure()).
  std::optional<Sample> Corrected(const Sample& from, double s, Attempt attempt);
  // `near`, a point corrected from `from` to within rounding of the parameter bound, moved onto
  // it exactly (Newton with the parameter held at the bound); nullopt if that fails.
  std::optional<Sample> OnBound(const Sample& from, const Sample& near, double bound);
  const std::string& last_failure() const { return last_failure_; }

 private:
  // `sample` (its u and iterations) with the unit tangent at u, oriented as `reference`, the
  // determinant sign, the test functions and, if `record`, the recorded values; nullopt if the
  // bordered matrix is singular. `bordered`, where given, is [J; reference^T] at u already
  // evaluated (by the Newton run that corrected u with `reference` as its border).
  std::optional<Sample> Completed(Sample sample, const Eigen::VectorXd& reference, bool record,
                                  const std::optional<JacobianMatrix>& bordered = std::nullopt);

  const NonlinearSystem& problem_;
  const Monitor* monitor_;
  const ContinuationOptions& options_;
  std::unique_ptr<LinearSolver> solver_;
  std::string last_failure_;  // why the corrector last failed, for the end message
};

}  // namespace stickslip::detail
