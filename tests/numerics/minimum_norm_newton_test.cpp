// Minimum-norm Newton (numerics/minimum_norm_newton.hpp) against closed forms: on a system whose
// solutions form a circle it moves the guess along the gradient, radially, to the circle's point
// nearest it, and reports the family's dimension; on an isolated root it is Newton's method.
#include <cmath>

#include <gtest/gtest.h>

#include "stickslip/numerics/minimum_norm_newton.hpp"

namespace stickslip {
namespace {

// F(x, y) = (g, 2 g) with g = x^2 + y^2 - 1: every point of the unit circle solves it, and the
// Jacobian, rows 2 (x, y) and 4 (x, y), has rank 1 there (nullity 1: the circle's tangent).
class Circle final : public NonlinearSystem {
 public:
  int EquationCount() const override { return 2; }
  int UnknownCount() const override { return 2; }
  void Evaluate(const Eigen::VectorXd& u, Eigen::VectorXd* residual, JacobianMatrix* jacobian) const override {
    const double g = u.squaredNorm() - 1.0;
    *residual = Eigen::Vector2d(g, 2.0 * g);
    if (jacobian) {
      Eigen::MatrixXd j(2, 2);
      j << 2.0 * u(0), 2.0 * u(1), 4.0 * u(0), 4.0 * u(1);
      *jacobian = j;
    }
  }
};

// F(x, y) = (x - 1, x + y + 1): the one root (1, -2).
class Lines final : public NonlinearSystem {
 public:
  int EquationCount() const override { return 2; }
  int UnknownCount() const override { return 2; }
  void Evaluate(const Eigen::VectorXd& u, Eigen::VectorXd* residual, JacobianMatrix* jacobian) const override {
    *residual = Eigen::Vector2d(u(0) - 1.0, u(0) + u(1) + 1.0);
    if (jacobian) *jacobian = Eigen::MatrixXd((Eigen::Matrix2d() << 1.0, 0.0, 1.0, 1.0).finished());
  }
};

TEST(MinimumNormNewton, MovesAGuessToTheNearestMemberOfAFamilyAndGivesItsDimension) {
  for (const Eigen::Vector2d& guess : {Eigen::Vector2d(2.0, 0.5), Eigen::Vector2d(-0.3, 0.2), Eigen::Vector2d(0.7, -1.1)}) {
    const MinimumNormNewtonResult r = SolveMinimumNorm(Circle(), guess);
    ASSERT_TRUE(r.newton.summary.Converged()) << r.newton.summary.message;
    EXPECT_EQ(r.nullity, 1);
    EXPECT_LT((r.newton.solution - guess.normalized()).lpNorm<Eigen::Infinity>(), 1e-10) << guess.transpose();
  }
}

TEST(MinimumNormNewton, IsNewtonsMethodAtAnIsolatedRoot) {
  const MinimumNormNewtonResult r = SolveMinimumNorm(Lines(), Eigen::Vector2d(10.0, 3.0));
  ASSERT_TRUE(r.newton.summary.Converged()) << r.newton.summary.message;
  EXPECT_EQ(r.nullity, 0);
  EXPECT_EQ(r.newton.summary.iterations, 1);  // linear: one step
  EXPECT_LT((r.newton.solution - Eigen::Vector2d(1.0, -2.0)).lpNorm<Eigen::Infinity>(), 1e-12);
}

// A bounded loop whatever the system: no solution (g = 1 + x^2 + y^2 > 0) ends at max-iterations.
TEST(MinimumNormNewton, EndsAtItsIterationLimitWhereThereIsNoSolution) {
  class NoRoot final : public NonlinearSystem {
   public:
    int EquationCount() const override { return 1; }
    int UnknownCount() const override { return 1; }
    void Evaluate(const Eigen::VectorXd& u, Eigen::VectorXd* residual, JacobianMatrix* jacobian) const override {
      *residual = Eigen::VectorXd::Constant(1, 1.0 + u(0) * u(0));
      if (jacobian) *jacobian = Eigen::MatrixXd::Constant(1, 1, 2.0 * u(0));
    }
  };
  MinimumNormNewtonOptions options;
  options.max_iterations = 12;
  const MinimumNormNewtonResult r = SolveMinimumNorm(NoRoot(), Eigen::VectorXd::Constant(1, 0.5), options);
  EXPECT_FALSE(r.newton.summary.Converged());
  EXPECT_LE(r.newton.summary.iterations, 12);
}

}  // namespace
}  // namespace stickslip
