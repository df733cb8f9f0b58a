#include "arclength_corrector.hpp"

#include <algorithm>

#include "bordered_systems.hpp"
#include "stickslip/continuation/branch_switching.hpp"

namespace stickslip::detail {

ArclengthCorrector::ArclengthCorrector(const NonlinearSystem& problem, const Monitor* monitor,
                                       const ContinuationOptions& options)
    : problem_(problem), monitor_(monitor), options_(options),
      solver_(LinearSolver::Create(options.corrector.linear_solver)) {}

std::optional<Sample> ArclengthCorrector::Completed(Sample sample, const Eigen::VectorXd& reference, bool record,
                                                   const std::optional<JacobianMatrix>& bordered) {
  if (bordered) {
    if (!solver_->Factorize(*bordered)) return std::nullopt;
  } else {
    Eigen::VectorXd f;
    JacobianMatrix j;
    problem_.Evaluate(sample.u, &f, &j);
    if (!solver_->Factorize(AppendRow(j, reference))) return std::nullopt;
  }
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(sample.u.size());
  rhs(sample.u.size() - 1) = 1.0;
  sample.tangent = solver_->Solve(rhs);
  // With A = [J; r^T] and A t~ = e (so r.t~ = 1: t keeps the orientation of r), the rank-one
  // update to B = [J; t^T], t = t~/|t~|, gives det B = det A (1 + (t - r).t~) = det A |t~|: one
  // factorisation serves.
  sample.det_sign = solver_->DeterminantSign();
  sample.tangent /= sample.tangent.norm();
  if (monitor_) monitor_->Evaluate(sample.u, &sample.tests, record ? &sample.recorded : nullptr);
  return sample;
}

std::optional<Sample> ArclengthCorrector::Start(const Eigen::VectorXd& guess) {
  if (options_.start_direction.size() > 0) {
    Sample branch_point;
    branch_point.u = guess;
    branch_point.tangent = UnitDirection(options_.start_direction);
    std::optional<Sample> first = Corrected(branch_point, options_.step.ds, Attempt::kLocated);
    if (!first) last_failure_ = "the first point along start_direction does not converge: " + last_failure_;
    return first;
  }
  const FixedParameterSystem fixed(problem_, guess, options_.parameter_index);
  NewtonOptions newton = options_.corrector;
  newton.max_iterations = std::max(newton.max_iterations, options_.start_iterations);
  const NewtonResult r = SolveNewton(fixed, fixed.Reduce(guess), newton);
  if (!r.summary.Converged()) {
    last_failure_ = "the start point does not converge: " + r.summary.BriefReport();
    return std::nullopt;
  }
  Sample sample;
  sample.u = fixed.Expand(r.solution);
  sample.iterations = r.summary.iterations;
  Eigen::VectorXd axis = Eigen::VectorXd::Zero(guess.size());
  axis(options_.parameter_index) = options_.direction;
  // At a fold the tangent is orthogonal to the lambda axis and [J; axis^T] singular: a generic
  // border gives the tangent there (its orientation is settled by the first step).
  const Eigen::VectorXd generic = Eigen::VectorXd::LinSpaced(guess.size(), 1.0, 2.0).normalized();
  std::optional<Sample> started = Completed(sample, axis, true);
  if (!started) started = Completed(std::move(sample), generic, true);
  if (!started) last_failure_ = "the bordered Jacobian is singular at the start point";
  return started;
}

std::optional<Sample> ArclengthCorrector::Corrected(const Sample& from, double s, Attempt attempt) {
  const BorderedSystem bordered(problem_, from.tangent, from.u, s);
  NewtonOptions newton = options_.corrector;
  if (attempt != Attempt::kStep) {
    newton.max_iterations = std::max(newton.max_iterations, options_.location.corrector_iterations);
  }
  NewtonResult r = SolveNewton(bordered, from.u + s * from.tangent, newton);
  if (!r.summary.Converged()) {
    last_failure_ = r.summary.BriefReport();
    return std::nullopt;
  }
  Sample sample;
  sample.u = std::move(r.solution);
  sample.iterations = r.summary.iterations;
  // The corrector's Jacobian at the root is the bordered matrix with from.tangent as its border.
  return Completed(std::move(sample), from.tangent, attempt != Attempt::kLocationTrial, r.jacobian);
}

std::optional<Sample> ArclengthCorrector::OnBound(const Sample& from, const Sample& near, double bound) {
  Eigen::VectorXd target = near.u;
  target(options_.parameter_index) = bound;
  const FixedParameterSystem fixed(problem_, target, options_.parameter_index);
  const NewtonResult r = SolveNewton(fixed, fixed.Reduce(target), options_.corrector);
  if (!r.summary.Converged()) return std::nullopt;
  Sample sample;
  sample.u = fixed.Expand(r.solution);
  sample.iterations = near.iterations + r.summary.iterations;
  return Completed(std::move(sample), from.tangent, true);
}

}  // namespace stickslip::detail
