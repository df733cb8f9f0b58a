#include "stickslip/numerics/minimum_norm_newton.hpp"

#include <cmath>
#include <optional>
#include <string>
#include <variant>

#include <Eigen/SVD>
#include <fmt/format.h>

namespace stickslip {

namespace {

Eigen::MatrixXd Dense(const JacobianMatrix& jacobian) {
  if (const auto* dense = std::get_if<Eigen::MatrixXd>(&jacobian)) return *dense;
  return Eigen::MatrixXd(std::get<SparseMatrix>(jacobian));
}

}  // namespace

MinimumNormNewtonResult SolveMinimumNorm(const NonlinearSystem& system, const Eigen::VectorXd& guess,
                                         const MinimumNormNewtonOptions& options) {
  MinimumNormNewtonResult result;
  NewtonSummary& summary = result.newton.summary;
  Eigen::VectorXd& u = result.newton.solution;
  u = guess;
  for (int iteration = 0;; ++iteration) {
    Eigen::VectorXd residual;
    JacobianMatrix jacobian;
    system.Evaluate(u, &residual, &jacobian);
    const double norm = residual.allFinite() ? residual.lpNorm<Eigen::Infinity>() : INFINITY;
    summary.residual_norms.push_back(norm);
    summary.iterations = iteration;
    const Eigen::MatrixXd j = Dense(jacobian);
    if (!std::isfinite(norm) || !j.allFinite()) {
      summary.termination = NewtonTermination::kDiverged;
      summary.message = std::isfinite(norm) ? "a non-finite Jacobian" : "a non-finite residual";
      return result;
    }
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(j, Eigen::ComputeFullV | Eigen::ComputeFullU);
    svd.setThreshold(options.rank_tolerance);
    const int rank = static_cast<int>(svd.rank());
    result.nullity = static_cast<int>(svd.cols()) - rank;
    result.null_space = svd.matrixV().rightCols(result.nullity);
    const Eigen::VectorXd& s = svd.singularValues();
    summary.condition_number = s.size() > 0 && s(s.size() - 1) > 0.0 ? s(0) / s(s.size() - 1) : INFINITY;
    if (norm <= options.residual_tolerance) {
      summary.termination = NewtonTermination::kConverged;
      return result;
    }
    if (iteration == options.max_iterations) {
      summary.termination = NewtonTermination::kMaxIterations;
      summary.message = fmt::format("max|F| = {:.3g} after {} minimum-norm steps", norm, iteration);
      return result;
    }
    const Eigen::VectorXd next = u - svd.solve(residual);
    if (const std::optional<std::string> outside = system.DomainError(next)) {
      summary.termination = NewtonTermination::kLeftDomain;
      summary.message = *outside;
      return result;
    }
    u = next;
  }
}

}  // namespace stickslip
