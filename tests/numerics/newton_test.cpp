#include "stickslip/numerics/newton.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace stickslip {
namespace {

// The report of a failure names the termination, the iterations and the last residual; the
// condition number only where it was estimated (a number >= 1: 0 means it was not).
TEST(NewtonSummary, BriefReportGivesTheConditionNumberOnlyWhereItWasEstimated) {
  NewtonSummary s;
  s.termination = NewtonTermination::kLineSearchFailed;
  s.iterations = 7;
  s.residual_norms = {1.0, 1.709e-4};
  s.message = "no step along the Newton direction lowers |F|";
  EXPECT_EQ(s.BriefReport(),
            "line-search-failed after 7 iteration(s), residual 1.709e-04: no step along the Newton direction lowers |F|");
  s.condition_number = 7427.0;
  EXPECT_EQ(s.BriefReport(), "line-search-failed after 7 iteration(s), residual 1.709e-04, condition 7.427e+03: no step "
                             "along the Newton direction lowers |F|");
}

// x^2 = 2 and x y = 1, counting how often the residual and the Jacobian are evaluated.
class CountingSystem final : public NonlinearSystem {
 public:
  int EquationCount() const override { return 2; }
  int UnknownCount() const override { return 2; }
  void Evaluate(const Eigen::VectorXd& u, Eigen::VectorXd* residual, JacobianMatrix* jacobian) const override {
    ++(jacobian ? jacobians : residuals_only);
    *residual = Eigen::Vector2d(u(0) * u(0) - 2.0, u(0) * u(1) - 1.0);
    if (jacobian) *jacobian = Eigen::MatrixXd(Eigen::Matrix2d{{2.0 * u(0), 0.0}, {u(1), u(0)}});
  }
  mutable int jacobians = 0, residuals_only = 0;
};

// A full Newton step's residual comes with its Jacobian, which serves the next iteration and,
// at the root, the caller: no residual is evaluated twice, and the Jacobian returned is the one
// at the root (against the closed form).
TEST(SolveNewton, ReturnsTheJacobianAtTheRootAndEvaluatesEachIterateOnce) {
  CountingSystem system;
  NewtonOptions options;
  options.estimate_condition = false;
  const NewtonResult r = SolveNewton(system, Eigen::Vector2d(1.5, 0.5), options);
  ASSERT_TRUE(r.summary.Converged());
  EXPECT_NEAR(r.solution(0), std::sqrt(2.0), 1e-14);
  EXPECT_NEAR(r.solution(1), 1.0 / std::sqrt(2.0), 1e-14);
  EXPECT_EQ(system.residuals_only, 0);
  EXPECT_EQ(system.jacobians, r.summary.iterations + 1);
  ASSERT_TRUE(r.jacobian.has_value());
  const Eigen::MatrixXd& j = std::get<Eigen::MatrixXd>(*r.jacobian);
  EXPECT_DOUBLE_EQ(j(0, 0), 2.0 * r.solution(0));
  EXPECT_DOUBLE_EQ(j(1, 0), r.solution(1));
  EXPECT_DOUBLE_EQ(j(1, 1), r.solution(0));
}

}  // namespace
}  // namespace stickslip
