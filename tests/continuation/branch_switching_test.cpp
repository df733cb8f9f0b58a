#include "stickslip/continuation/branch_switching.hpp"

#include <cmath>
#include <functional>
#include <limits>

#include <gtest/gtest.h>

#include "stickslip/continuation/continuation.hpp"
#include "stickslip/invalid_input.hpp"

namespace stickslip {
namespace {

// u = (x, y, lambda): x (lambda - x^2) = 0 and y = 2 x. The trivial branch x = y = 0 meets the
// branch lambda = x^2, y = 2x at the origin (a pitchfork in a system of two equations).
class SlavedPitchfork : public NonlinearSystem {
 public:
  int EquationCount() const override { return 2; }
  int UnknownCount() const override { return 3; }
  void Evaluate(const Eigen::VectorXd& u, Eigen::VectorXd* r, JacobianMatrix* j) const override {
    const double x = u(0), y = u(1), l = u(2);
    *r = Eigen::Vector2d(x * (l - x * x), y - 2.0 * x);
    if (j) {
      Eigen::MatrixXd m(2, 3);
      m << l - 3.0 * x * x, 0.0, x, -2.0, 1.0, 0.0;
      *j = m;
    }
  }
};

// u = (x, lambda): x (lambda - x) = 0. The second branch lambda = x is not orthogonal to the
// trivial one x = 0 (a transcritical point).
class Transcritical : public NonlinearSystem {
 public:
  int EquationCount() const override { return 1; }
  int UnknownCount() const override { return 2; }
  void Evaluate(const Eigen::VectorXd& u, Eigen::VectorXd* r, JacobianMatrix* j) const override {
    const double x = u(0), l = u(1);
    *r = Eigen::VectorXd::Constant(1, x * (l - x));
    if (j) {
      Eigen::MatrixXd m(1, 2);
      m << l - 2.0 * x, x;
      *j = m;
    }
  }
};

ContinuationOptions Options(int parameter_index) {
  ContinuationOptions o;
  o.parameter_index = parameter_index;
  o.step.ds = 0.05;
  o.step.ds_max = 0.1;
  o.lambda_min = -1.0;
  o.lambda_max = 1.0;
  o.max_points = 30;
  return o;
}

// The branch point of the trivial branch from lambda = -0.47 upwards (not -0.5: steps of 0.05
// from there straddle the branch point symmetrically, and the location's first trial lands on it
// exactly, where the bordered Jacobian is singular).
SpecialPoint TrivialBranchPoint(const NonlinearSystem& problem, int parameter_index) {
  Eigen::VectorXd start = Eigen::VectorXd::Zero(problem.UnknownCount());
  start(parameter_index) = -0.47;
  const Branch trivial = Continuation(problem, nullptr, Options(parameter_index), start).Run();
  for (const SpecialPoint& s : trivial.special_points) {
    if (s.type == "BP" && s.located) return s;
  }
  ADD_FAILURE() << "no branch point on the trivial branch";
  return {};
}

// The branch started on `at` along `direction`, of at most max_points points.
Branch BranchAlong(const NonlinearSystem& problem, int parameter_index, const Eigen::VectorXd& at,
                   const Eigen::VectorXd& direction, int max_points) {
  ContinuationOptions o = Options(parameter_index);
  o.start_direction = direction;
  o.max_points = max_points;
  return Continuation(problem, nullptr, o, at).Run();
}

TEST(SecondBranchDirection, IsTheNullVectorOrthogonalToTheTrivialBranch) {
  const SlavedPitchfork problem;
  const SpecialPoint bp = TrivialBranchPoint(problem, 2);
  EXPECT_NEAR(bp.lambda, 0.0, 1e-10);
  const BranchPointDirections d = SecondBranchDirection(problem, bp.u, bp.tangent);
  EXPECT_LT(d.singularity, 1e-8);
  // The null space at the origin: (1, 2, 0) (the second branch) and (0, 0, 1) (the trivial one).
  const Eigen::Vector3d expected = Eigen::Vector3d(1.0, 2.0, 0.0).normalized();
  EXPECT_NEAR(std::abs(d.second.dot(expected)), 1.0, 1e-10);
}

TEST(SecondBranchDirection, LeadsOntoThePitchforksOtherBranchOnEitherSide) {
  const SlavedPitchfork problem;
  const SpecialPoint bp = TrivialBranchPoint(problem, 2);
  const BranchPointDirections d = SecondBranchDirection(problem, bp.u, bp.tangent);
  for (const double sign : {1.0, -1.0}) {
    const Branch branch = BranchAlong(problem, 2, bp.u, sign * d.second, 10);
    ASSERT_EQ(branch.points.size(), 10u) << branch.end_message;
    for (const BranchPoint& p : branch.points) {
      const double x = p.u(0);
      EXPECT_GT(sign * x * d.second(0), 0.0);  // on the side the direction points to
      EXPECT_NEAR(p.u(2), x * x, 1e-10);       // lambda = x^2
      EXPECT_NEAR(p.u(1), 2.0 * x, 1e-10);
    }
  }
}

// The direction's and the tangent's lengths do not matter, even where their norms overflow or
// underflow.
TEST(SecondBranchDirection, TakesATangentAndADirectionOfAnyLength) {
  const SlavedPitchfork problem;
  const SpecialPoint bp = TrivialBranchPoint(problem, 2);
  const BranchPointDirections unit = SecondBranchDirection(problem, bp.u, bp.tangent);
  const Branch reference = BranchAlong(problem, 2, bp.u, unit.second, 3);
  ASSERT_EQ(reference.points.size(), 3u) << reference.end_message;
  for (const double scale : {1e300, 1e-300}) {
    const BranchPointDirections d = SecondBranchDirection(problem, bp.u, scale * bp.tangent);
    EXPECT_NEAR((d.second - unit.second).norm(), 0.0, 1e-15) << scale;
    const Branch branch = BranchAlong(problem, 2, bp.u, scale * unit.second, 3);
    ASSERT_EQ(branch.points.size(), 3u) << scale << ": " << branch.end_message;
    for (int k = 0; k < 3; ++k) EXPECT_NEAR((branch.points[k].u - reference.points[k].u).norm(), 0.0, 1e-14) << scale;
  }
}

TEST(SecondBranchDirection, LeadsOntoATranscriticalBranchThatIsNotOrthogonal) {
  const Transcritical problem;
  const SpecialPoint bp = TrivialBranchPoint(problem, 1);
  const BranchPointDirections d = SecondBranchDirection(problem, bp.u, bp.tangent);
  const Branch branch = BranchAlong(problem, 1, bp.u, d.second, 10);
  ASSERT_EQ(branch.points.size(), 10u) << branch.end_message;
  for (const BranchPoint& p : branch.points) {
    EXPECT_GT(std::abs(p.u(0)), 0.01);
    EXPECT_NEAR(p.u(1), p.u(0), 1e-10);  // lambda = x
  }
}

TEST(SecondBranchDirection, RefusesATangentOfAnotherSizeOrOffTheNullSpace) {
  const Transcritical problem;
  EXPECT_THROW(SecondBranchDirection(problem, Eigen::Vector2d::Zero(), Eigen::Vector3d(1, 0, 0)),
               std::invalid_argument);
  EXPECT_THROW(SecondBranchDirection(problem, Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()),
               std::invalid_argument);
  // Away from the branch point the null space is one line: the trivial tangent (0, 1) lies in
  // it, but no second direction is singular there.
  const BranchPointDirections away = SecondBranchDirection(problem, Eigen::Vector2d(0.0, 0.5), Eigen::Vector2d(0, 1));
  EXPECT_GT(away.singularity, 0.1);
}

TEST(ContinuationOptions, RefusesAStartDirectionThatIsZeroOrNotFinite) {
  ContinuationOptions o = Options(1);
  o.start_direction = Eigen::Vector2d::Zero();
  EXPECT_THROW(o.Validate(), InvalidInput);
  o.start_direction = Eigen::Vector2d(std::numeric_limits<double>::quiet_NaN(), 1.0);
  EXPECT_THROW(o.Validate(), InvalidInput);
  o.start_direction = Eigen::Vector3d(1.0, 0.0, 0.0);  // a size the problem does not have
  EXPECT_THROW(Continuation(Transcritical(), nullptr, o, Eigen::Vector2d(0.0, -0.5)), std::invalid_argument);
}

}  // namespace
}  // namespace stickslip
