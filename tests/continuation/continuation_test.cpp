// The continuation engine alone, on problems with known answers.
#include "stickslip/continuation/continuation.hpp"

#include <cmath>

#include <algorithm>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

namespace stickslip {
namespace {

// F(x, lambda) with u = (x, lambda) and an analytic Jacobian.
class ScalarProblem : public NonlinearSystem {
 public:
  int EquationCount() const override { return 1; }
  int UnknownCount() const override { return 2; }
  void Evaluate(const Eigen::VectorXd& u, Eigen::VectorXd* r, JacobianMatrix* j) const override {
    r->resize(1);
    (*r)(0) = F(u(0), u(1));
    if (j) {
      Eigen::MatrixXd m(1, 2);
      m << Fx(u(0), u(1)), Fl(u(0), u(1));
      *j = m;
    }
  }
  virtual double F(double x, double l) const = 0;
  virtual double Fx(double x, double l) const = 0;
  virtual double Fl(double x, double l) const = 0;
};

struct Circle : ScalarProblem {  // x^2 + lambda^2 = 1: folds at lambda = -1 and 1
  double F(double x, double l) const override { return x * x + l * l - 1.0; }
  double Fx(double x, double) const override { return 2 * x; }
  double Fl(double, double l) const override { return 2 * l; }
};

struct Cubic : ScalarProblem {  // lambda = x - x^3/3: folds at (x, lambda) = (+-1, +-2/3)
  double F(double x, double l) const override { return x * x * x / 3.0 - x + l; }
  double Fx(double x, double) const override { return x * x - 1.0; }
  double Fl(double, double) const override { return 1.0; }
};

struct Pitchfork : ScalarProblem {  // x (lambda - x^2) = 0: branch point at the origin
  double F(double x, double l) const override { return x * (l - x * x); }
  double Fx(double x, double l) const override { return l - 3 * x * x; }
  double Fl(double x, double) const override { return x; }
};

ContinuationOptions Options(double ds = 0.05) {
  ContinuationOptions o;
  o.parameter_index = 1;
  o.step.ds = ds;
  o.step.ds_max = 0.2;
  o.max_points = 400;
  return o;
}

std::vector<SpecialPoint> OfType(const Branch& b, const std::string& type) {
  std::vector<SpecialPoint> out;
  for (const SpecialPoint& s : b.special_points) {
    if (s.type == type) out.push_back(s);
  }
  return out;
}

// The circle from (1, 0) towards increasing lambda, for `points` points.
Branch RoundTheCircle(int points) {
  ContinuationOptions o = Options();
  o.max_points = points;
  return Continuation(Circle(), nullptr, o, Eigen::Vector2d(1.0, 0.0)).Run();
}

TEST(PseudoArclength, LocatesBothFoldsOfTheCircle) {
  const Branch b = RoundTheCircle(200);
  const auto folds = OfType(b, "LP");
  ASSERT_GE(folds.size(), 2u);
  EXPECT_NEAR(folds[0].lambda, 1.0, 1e-10);
  EXPECT_NEAR(folds[0].u(0), 0.0, 1e-9);
  EXPECT_NEAR(folds[1].lambda, -1.0, 1e-10);
  for (const BranchPoint& p : b.points) EXPECT_NEAR(p.u.squaredNorm(), 1.0, 1e-10);
}

// Round the circle from (1, 0) towards increasing lambda, the unit tangent is (-lambda, x).
TEST(PseudoArclength, KeepsTheTangentAlongTheBranchAtEachSpecialPoint) {
  const Branch b = RoundTheCircle(100);
  const auto folds = OfType(b, "LP");
  ASSERT_GE(folds.size(), 2u);
  for (const SpecialPoint& s : b.special_points) {
    ASSERT_EQ(s.tangent.size(), 2) << s.type;
    EXPECT_LT((s.tangent - Eigen::Vector2d(-s.lambda, s.u(0))).norm(), 1e-9) << s.type << " at " << s.lambda;
  }
  EXPECT_NEAR(folds[0].tangent(1), 0.0, 1e-9);  // at lambda = 1, heading to x < 0
  EXPECT_NEAR(folds[0].tangent(0), -1.0, 1e-9);
  EXPECT_NEAR(folds[1].tangent(0), 1.0, 1e-9);  // at lambda = -1, heading back to x > 0
}

TEST(PseudoArclength, LocatesTheFoldOfACubicInEitherDirection) {
  const Cubic cubic;
  for (int direction : {1, -1}) {
    ContinuationOptions o = Options();
    o.direction = direction;
    o.lambda_min = -2.0;
    o.lambda_max = 2.0;
    const Branch b = Continuation(cubic, nullptr, o, Eigen::Vector2d(0.0, 0.0)).Run();
    // From the origin lambda rises to the fold at x = 1, then falls for ever (or the mirror).
    const auto folds = OfType(b, "LP");
    ASSERT_EQ(folds.size(), 1u);
    EXPECT_NEAR(folds[0].lambda, direction * 2.0 / 3.0, 1e-10);
    EXPECT_NEAR(folds[0].u(0), direction * 1.0, 1e-5);  // lambda is quadratic in x there
    EXPECT_EQ(b.end, BranchEnd::kParameterBound);
    EXPECT_NEAR(b.points.back().lambda, -direction * 2.0, 1e-10);
  }
}

TEST(PseudoArclength, LocatesThePitchforkBranchPoint) {
  const Pitchfork pitchfork;
  ContinuationOptions o = Options(0.07);
  o.lambda_min = -1.0;
  o.lambda_max = 1.0;
  const Branch b = Continuation(pitchfork, nullptr, o, Eigen::Vector2d(0.0, -0.5)).Run();
  const auto bps = OfType(b, "BP");
  ASSERT_EQ(bps.size(), 1u);
  EXPECT_NEAR(bps[0].lambda, 0.0, 1e-10);
  EXPECT_TRUE(OfType(b, "LP").empty());
}

TEST(PseudoArclength, LocatesUserValuesAndEndsAtTheParameterBound) {
  const Cubic cubic;
  ContinuationOptions o = Options();
  o.lambda_max = 0.5;
  o.user_values = {{1, 0.25, "lambda=0.25"}, {0, 0.1, "x=0.1"}};
  const Branch b = Continuation(cubic, nullptr, o, Eigen::Vector2d(0.0, 0.0)).Run();
  const auto uz = OfType(b, "UZ");
  ASSERT_EQ(uz.size(), 2u);
  EXPECT_NEAR(uz[0].u(0), 0.1, 1e-10);
  EXPECT_NEAR(uz[1].lambda, 0.25, 1e-10);
  EXPECT_EQ(b.end, BranchEnd::kParameterBound);
  EXPECT_NEAR(b.points.back().lambda, 0.5, 1e-10);
  EXPECT_EQ(b.points.back().label, "EP");
}

TEST(PseudoArclength, EndMessageAtABoundGivesTheBoundsReason) {
  const Cubic cubic;
  ContinuationOptions o = Options();
  o.parameter_name = "F_k";
  o.lambda_max = 0.5;
  o.lambda_max_reason = "F_k <= F_s = 0.5";
  const Branch b = Continuation(cubic, nullptr, o, Eigen::Vector2d(0.0, 0.0)).Run();
  ASSERT_EQ(b.end, BranchEnd::kParameterBound);
  EXPECT_EQ(b.end_message, "reached F_k = 0.5 (F_k <= F_s = 0.5)");
  // Without a reason, the bound is the range asked for: nothing more is said.
  o.lambda_max_reason.clear();
  EXPECT_EQ(Continuation(cubic, nullptr, o, Eigen::Vector2d(0.0, 0.0)).Run().end_message, "reached F_k = 0.5");
  // A start on the bound heading out of the range: the lower bound's reason, not the upper's.
  o.lambda_min = 0.0;
  o.lambda_min_reason = "its valid range: F_k >= 0";
  o.lambda_max_reason = "F_k <= F_s = 0.5";
  o.direction = -1;
  EXPECT_EQ(Continuation(cubic, nullptr, o, Eigen::Vector2d(0.0, 0.0)).Run().end_message,
            "at the bound F_k = 0 (its valid range: F_k >= 0)");
  // A start past a bound is an end of its own, which the front ends refuse, with the bound's
  // reason (or the bound, where it is the range asked for).
  o.lambda_min = 0.1;
  o.lambda_min_reason = "its valid range: F_k >= 0.1";
  const Branch outside = Continuation(cubic, nullptr, o, Eigen::Vector2d(0.0, 0.0)).Run();
  EXPECT_EQ(outside.end, BranchEnd::kStartOutsideRange);
  EXPECT_EQ(outside.points.size(), 1u);
  EXPECT_EQ(outside.end_message, "the start, F_k = 0, lies outside the parameter range (its valid range: F_k >= 0.1)");
  o.lambda_min_reason.clear();
  EXPECT_EQ(Continuation(cubic, nullptr, o, Eigen::Vector2d(0.0, 0.0)).Run().end_message,
            "the start, F_k = 0, lies outside the parameter range (F_k >= 0.1)");
}

// A fold of curvature 100: lambda = -50 x^2. Long steps overshoot it and fail, short ones pass.
struct SharpFold : ScalarProblem {
  double F(double x, double l) const override { return l + 50.0 * x * x; }
  double Fx(double x, double) const override { return 100.0 * x; }
  double Fl(double, double) const override { return 1.0; }
};

TEST(StepSize, ShrinksWhereTheCorrectorFailsAndRecoversAfter) {
  const SharpFold fold;
  ContinuationOptions o = Options(0.2);
  o.step.ds_max = 0.4;
  o.corrector.max_iterations = 4;
  o.lambda_min = -1.5;
  o.detect_folds = false;
  o.detect_branch_points = false;
  const Branch b = Continuation(fold, nullptr, o, Eigen::Vector2d(-std::sqrt(1.0 / 50.0), -1.0)).Run();
  EXPECT_EQ(b.end, BranchEnd::kParameterBound);
  double smallest = 1.0;
  std::size_t where = 0;
  for (std::size_t i = 1; i < b.points.size(); ++i) {
    if (b.points[i].ds > 0.0 && b.points[i].ds < smallest) {
      smallest = b.points[i].ds;
      where = i;
    }
  }
  EXPECT_LT(smallest, 0.2 / 4);  // shrank at the fold
  EXPECT_LT(std::abs(b.points[where].lambda), 0.1);
  double largest_after = 0.0;
  for (std::size_t i = where; i < b.points.size(); ++i) largest_after = std::max(largest_after, b.points[i].ds);
  EXPECT_GT(largest_after, 4 * smallest);  // and grew again after it
  for (const BranchPoint& p : b.points) EXPECT_NEAR(fold.F(p.u(0), p.u(1)), 0.0, 1e-10);
  EXPECT_GT(b.points.back().u(0), 0.0);  // went round the fold
  EXPECT_NEAR(b.points.back().lambda, -1.5, 1e-10);
}

// The end message names the parameter and its value to 10 significant digits: the bound as the
// user gave it, not its rounding noise (0.19999999999999993).
TEST(PseudoArclength, EndMessageNamesTheParameterAndItsRoundedValue) {
  const Cubic cubic;
  for (double ds : {0.013, 0.05, 0.15}) {
    for (int direction : {1, -1}) {
      ContinuationOptions o = Options(ds);
      o.parameter_name = "omega";
      o.direction = direction;
      o.lambda_min = -0.3;
      o.lambda_max = 0.2;
      o.detect_folds = false;
      const Branch b = Continuation(cubic, nullptr, o, Eigen::Vector2d(0.0, 0.0)).Run();
      EXPECT_EQ(b.end, BranchEnd::kParameterBound) << "ds = " << ds;
      EXPECT_EQ(b.end_message, direction > 0 ? "reached omega = 0.2" : "reached omega = -0.3") << "ds = " << ds;
    }
  }
}

// However the last step meets the bound (clipped onto it, or crossing it), the branch ends on
// it exactly, with the bound as a located EP, and the same special points either way.
TEST(PseudoArclength, EndsExactlyOnTheBoundWhateverTheStepSize) {
  const Cubic cubic;
  for (double ds : {0.013, 0.02, 0.05, 0.07, 0.1, 0.15}) {
    ContinuationOptions o = Options(ds);
    o.lambda_max = 0.5;
    o.detect_folds = false;
    const Branch b = Continuation(cubic, nullptr, o, Eigen::Vector2d(0.0, 0.0)).Run();
    EXPECT_EQ(b.end, BranchEnd::kParameterBound) << "ds = " << ds;
    EXPECT_EQ(b.points.back().lambda, 0.5) << "ds = " << ds;
    EXPECT_NEAR(cubic.F(b.points.back().u(0), 0.5), 0.0, 1e-12);
    const auto ep = OfType(b, "EP");
    EXPECT_TRUE(std::any_of(ep.begin(), ep.end(), [&](const SpecialPoint& s) {
      return s.test_function == "lambda_max" && s.point == static_cast<int>(b.points.size()) - 1;
    })) << "ds = " << ds << ": " << b.end_message;
  }
}

// A step clipped onto the bound lands short of it by the corrector's second-order error (here
// ~4e-3, near the circle's fold); the steps after it reach the bound although ds_min exceeds what
// is left (before, the step after the clip grew from the clipped length, fell below ds_min and the
// branch ended 'the corrector failed' with no failure).
TEST(PseudoArclength, ReachesTheBoundWhenWhatIsLeftIsBelowTheSmallestStep) {
  const Circle circle;
  ContinuationOptions o = Options(0.25);
  o.step.ds_min = o.step.ds_max = 0.25;
  o.lambda_max = 0.9;
  o.detect_folds = false;
  const Branch b = Continuation(circle, nullptr, o, Eigen::Vector2d(1.0, 0.0)).Run();
  EXPECT_EQ(b.end, BranchEnd::kParameterBound) << b.end_message;
  EXPECT_EQ(b.points.back().lambda, 0.9);
  EXPECT_NEAR(b.points.back().u(0), std::sqrt(1.0 - 0.81), 1e-12);
}

// Up the circle from lambda = -0.8 the slope dlambda/ds grows, so that a step the tangent does not
// clip can cross the bound; the located crossing is put on it too (before, a few ulps past it).
TEST(PseudoArclength, EndsExactlyOnTheBoundWhereAStepCrossesIt) {
  const Circle circle;
  for (double ds : {0.07, 0.1, 0.13, 0.17, 0.2}) {
    for (double bound : {-0.5, -0.3, -0.1}) {
      ContinuationOptions o = Options(ds);
      o.step.ds_max = ds;
      o.lambda_max = bound;
      o.detect_folds = false;
      const Branch b = Continuation(circle, nullptr, o, Eigen::Vector2d(0.6, -0.8)).Run();
      EXPECT_EQ(b.end, BranchEnd::kParameterBound) << b.end_message;
      EXPECT_EQ(b.points.back().lambda, bound) << "ds = " << ds;
      EXPECT_NEAR(b.points.back().u(0), std::sqrt(1.0 - bound * bound), 1e-12);
      for (const BranchPoint& p : b.points) EXPECT_LE(p.lambda, bound) << "ds = " << ds;
    }
  }
}

TEST(PseudoArclength, EndsWhereAnotherUnknownReachesItsBoundLocatedOnTheBranch) {
  // Round the circle x^2 + lambda^2 = 1 from (1, 0) up: x falls to 0.5 at lambda = sqrt(3)/2.
  const Circle circle;
  ContinuationOptions o = Options();
  o.unknown_bounds.push_back({.index = 0, .min = 0.5, .max = 2.0, .name = "x"});
  const Branch b = Continuation(circle, nullptr, o, Eigen::Vector2d(1.0, 0.0)).Run();
  EXPECT_EQ(b.end, BranchEnd::kParameterBound);
  EXPECT_EQ(b.end_message, "reached x = 0.5");
  EXPECT_NEAR(b.points.back().u(0), 0.5, 1e-9);
  EXPECT_NEAR(b.points.back().lambda, std::sqrt(0.75), 1e-9);
  const auto ep = OfType(b, "EP");
  EXPECT_TRUE(std::any_of(ep.begin(), ep.end(), [](const SpecialPoint& s) { return s.test_function == "x_min"; }));
  EXPECT_TRUE(OfType(b, "LP").empty());  // it ends before the fold at lambda = 1
}

TEST(ContinuationOptions, RejectABoundOnLambdaOrAnEmptyBound) {
  ContinuationOptions o = Options();
  o.unknown_bounds.push_back({.index = 1, .min = 0.0, .max = 1.0, .name = "lambda"});
  EXPECT_THROW(o.Validate(), InvalidInput);
  o.unknown_bounds = {{.index = 0, .min = 1.0, .max = 1.0, .name = "x"}};
  EXPECT_THROW(o.Validate(), InvalidInput);
  o.unknown_bounds = {{.index = 5, .min = 0.0, .max = 1.0, .name = "x"}};
  EXPECT_THROW(Continuation(Circle(), nullptr, o, Eigen::Vector2d(1.0, 0.0)), InvalidInput);
}

TEST(PseudoArclength, EndsAtOnceWhenItStartsOnTheBoundItHeadsFor) {
  const Cubic cubic;
  ContinuationOptions o = Options();
  o.lambda_min = 0.0;  // the start, lambda = 0, heading down
  o.direction = -1;
  const Branch b = Continuation(cubic, nullptr, o, Eigen::Vector2d(0.0, 0.0)).Run();
  EXPECT_EQ(b.end, BranchEnd::kParameterBound);
  EXPECT_EQ(b.points.size(), 1u);
}

// A slow corrector that converged shrinks the step, but not below ds_min (below it the branch
// would end as if the corrector had failed); after a failed one it may (the caller ends the branch).
TEST(StepSizeController, GrowsAfterFastStepsShrinksAfterSlowOnesToDsMinHalvesOnFailureAndRespectsDsMax) {
  StepSizeOptions options;
  options.ds = 0.1;
  options.ds_min = 0.04;
  options.ds_max = 0.2;
  const auto c = StepSizeController::Create(options);
  EXPECT_DOUBLE_EQ(c->OnAccepted(0.1, 2), 0.15);
  EXPECT_DOUBLE_EQ(c->OnAccepted(0.15, 1), 0.2);
  EXPECT_DOUBLE_EQ(c->OnAccepted(0.1, 6), 0.05);
  EXPECT_DOUBLE_EQ(c->OnAccepted(0.05, 12), 0.04);
  EXPECT_DOUBLE_EQ(c->OnRejected(0.05), 0.025);
}

// Test functions of (x, lambda) with their declared properties, and the radius of the point as
// a recorded value; counts its evaluations.
class FunctionMonitor final : public Monitor {
 public:
  struct Function {
    TestFunctionInfo info;
    std::function<double(double x, double lambda)> g;
  };
  explicit FunctionMonitor(std::vector<Function> functions) : functions_(std::move(functions)) {}
  std::vector<TestFunctionInfo> TestFunctions() const override {
    std::vector<TestFunctionInfo> info;
    for (const Function& f : functions_) info.push_back(f.info);
    return info;
  }
  std::vector<std::string> RecordedNames() const override { return {"radius"}; }
  void Evaluate(const Eigen::VectorXd& u, Eigen::VectorXd* tests, Eigen::VectorXd* recorded) const override {
    ++evaluations;
    tests->resize(static_cast<int>(functions_.size()));
    for (std::size_t k = 0; k < functions_.size(); ++k) (*tests)(static_cast<int>(k)) = functions_[k].g(u(0), u(1));
    if (recorded) {
      ++recorded_evaluations;
      *recorded = Eigen::VectorXd::Constant(1, u.norm());
    }
  }
  mutable int evaluations = 0;
  mutable int recorded_evaluations = 0;

 private:
  std::vector<Function> functions_;
};

TEST(Monitor, RecordsItsValuesOnlyAtThePointsTheBranchKeeps) {
  const Circle circle;
  // x changes sign twice a turn round the circle: each location corrects many trial points.
  FunctionMonitor monitor({{{.name = "x", .type = "XZ"}, [](double x, double) { return x; }}});
  ContinuationOptions o = Options();
  o.max_points = 60;
  const Branch b = Continuation(circle, &monitor, o, Eigen::Vector2d(1.0, 0.0)).Run();
  ASSERT_GE(OfType(b, "XZ").size(), 2u);
  EXPECT_EQ(b.recorded, std::vector<std::string>{"radius"});
  for (const BranchPoint& p : b.points) {
    ASSERT_EQ(p.recorded.size(), 1);
    EXPECT_NEAR(p.recorded(0), 1.0, 1e-10);
  }
  // Every kept point once, and at most the step that the branch's end left unkept.
  EXPECT_GE(monitor.recorded_evaluations, static_cast<int>(b.points.size()));
  EXPECT_LE(monitor.recorded_evaluations, static_cast<int>(b.points.size()) + 1);
  EXPECT_GT(monitor.evaluations, monitor.recorded_evaluations + 10);
}

// g = 1/(lambda - 1/2) changes sign at lambda = 1/2 through a pole, not a zero.
TEST(Monitor, ASignChangeThroughAPoleIsASpecialPointOnlyIfTheFunctionDeclaresNoPoles) {
  const Cubic cubic;
  for (bool may_have_poles : {false, true}) {
    FunctionMonitor monitor({{{.name = "pole", .type = "PO", .may_have_poles = may_have_poles},
                              [](double, double l) { return 1.0 / (l - 0.5); }}});
    ContinuationOptions o = Options();
    o.lambda_max = 0.6;
    const Branch b = Continuation(cubic, &monitor, o, Eigen::Vector2d(0.0, 0.0)).Run();
    EXPECT_EQ(b.end, BranchEnd::kParameterBound);
    EXPECT_EQ(OfType(b, "PO").size(), may_have_poles ? 0u : 1u);
  }
}

// x = lambda, with no solution (the residual not finite) within 1e-3 of lambda = 1/2: as where a
// saltation matrix blows up, the corrector fails at the trial points next to the sign change, which
// is then not located. 1/(lambda - 1/2) changes sign there through a pole, lambda - 1/2 through a
// zero: only the zero is a special point.
struct LineWithAHole : ScalarProblem {
  double F(double x, double l) const override { return std::abs(l - 0.5) < 1e-3 ? NAN : x - l; }
  double Fx(double, double) const override { return 1.0; }
  double Fl(double, double) const override { return -1.0; }
};

TEST(Monitor, ASignChangeThroughAPoleWhereTheCorrectorFailsIsNoSpecialPoint) {
  const LineWithAHole line;
  FunctionMonitor monitor({{{.name = "pole", .type = "PO", .may_have_poles = true},
                            [](double, double l) { return 1.0 / (l - 0.5); }},
                           {{.name = "zero", .type = "ZE", .may_have_poles = true},
                            [](double, double l) { return l - 0.5; }}});
  ContinuationOptions o = Options();
  o.lambda_max = 0.8;
  o.detect_folds = false;
  o.detect_branch_points = false;
  const Branch b = Continuation(line, &monitor, o, Eigen::Vector2d(0.0, 0.0)).Run();
  EXPECT_EQ(b.end, BranchEnd::kParameterBound);
  EXPECT_TRUE(OfType(b, "PO").empty());
  const std::vector<SpecialPoint> zero = OfType(b, "ZE");
  ASSERT_EQ(zero.size(), 1u);
  EXPECT_FALSE(zero[0].located);  // recorded at the end of the step across the hole
  EXPECT_GT(zero[0].lambda, 0.5);
  // That point is on the branch once, not again as the step's end.
  for (std::size_t k = 1; k < b.points.size(); ++k) EXPECT_NE(b.points[k].u, b.points[k - 1].u) << "point " << k;
}

// x = lambda, a margin that is +inf ("none yet") until its interior minimum appears at lambda =
// 0.5 and then 0.7 - lambda: a step from lambda = 0.1 to 0.9 goes from +inf to -0.2, a change
// located at the zero, 0.7; one that jumps from +inf to -1 at 0.5 is located at the jump. From
// -inf, or from NaN ("not defined"), a step is no change.
struct Line : ScalarProblem {
  double F(double x, double l) const override { return x - l; }
  double Fx(double, double) const override { return 1.0; }
  double Fl(double, double) const override { return -1.0; }
};

TEST(Monitor, AStepFromPlusInfinityToANegativeValueIsAChangeLocatedWhereTheValueCrossesZero) {
  const Line line;
  const auto born = [](double value_after) {
    return [value_after](double, double l) { return l < 0.5 ? INFINITY : value_after - l; };
  };
  FunctionMonitor monitor({{{.name = "born", .type = "BO"}, born(0.7)},
                           {{.name = "jump", .type = "JU"}, born(-0.5)},
                           {{.name = "from-minus", .type = "FM"}, [](double, double l) { return l < 0.5 ? -INFINITY : l; }},
                           {{.name = "undefined", .type = "UN"}, [](double, double l) { return l < 0.5 ? NAN : 0.7 - l; }}});
  ContinuationOptions o = Options(0.8 * std::sqrt(2.0));  // one step, lambda 0.1 to 0.9
  o.step.ds_max = o.step.ds;
  o.lambda_max = 1.0;
  o.detect_folds = false;
  o.detect_branch_points = false;
  const Branch b = Continuation(line, &monitor, o, Eigen::Vector2d(0.1, 0.1)).Run();
  const std::vector<SpecialPoint> zero = OfType(b, "BO"), jump = OfType(b, "JU");
  ASSERT_EQ(zero.size(), 1u);
  EXPECT_TRUE(zero[0].located);
  EXPECT_NEAR(zero[0].lambda, 0.7, 1e-9);
  ASSERT_EQ(jump.size(), 1u);
  EXPECT_NEAR(jump[0].lambda, 0.5, 1e-6);
  EXPECT_TRUE(OfType(b, "FM").empty());
  EXPECT_TRUE(OfType(b, "UN").empty());
}

TEST(Monitor, ATerminalFunctionEndsTheBranchWhereItLeavesItsPositiveSide) {
  const Cubic cubic;
  FunctionMonitor monitor({{{.name = "below-half", .type = "BH", .terminal = true, .positive_side = "lower"},
                            [](double, double l) { return 0.5 - l; }}});
  const Branch b = Continuation(cubic, &monitor, Options(), Eigen::Vector2d(0.0, 0.0)).Run();
  EXPECT_EQ(b.end, BranchEnd::kTerminalEvent);
  EXPECT_EQ(b.end_message, "below-half (BH) left its lower side");
  EXPECT_NEAR(b.points.back().lambda, 0.5, 1e-10);
}

// A start on a terminal function's zero: the circle from (1, 0), where lambda is exactly zero.
Branch FromTheZeroOfATerminalLambda(int direction) {
  FunctionMonitor monitor({{{.name = "lambda", .type = "LZ", .terminal = true}, [](double, double l) { return l; }}});
  ContinuationOptions o = Options();
  o.direction = direction;
  return Continuation(Circle(), &monitor, o, Eigen::Vector2d(1.0, 0.0)).Run();
}

TEST(Monitor, AStartOnATerminalZeroGoesOnWhenTheFirstStepKeepsItPositive) {
  const Branch b = FromTheZeroOfATerminalLambda(+1);
  // Over the fold at lambda = 1, lambda leaves its positive side half way round, at (-1, 0).
  EXPECT_EQ(b.end, BranchEnd::kTerminalEvent);
  EXPECT_GT(b.points.size(), 3u);
  EXPECT_NEAR(b.points.back().u(0), -1.0, 1e-10);
  EXPECT_NEAR(b.points.back().lambda, 0.0, 1e-10);
  EXPECT_EQ(OfType(b, "LZ").size(), 1u);
}

TEST(Monitor, AStartOnATerminalZeroEndsThereWhenTheFirstStepMakesItNegative) {
  const Branch b = FromTheZeroOfATerminalLambda(-1);
  EXPECT_EQ(b.end, BranchEnd::kTerminalEvent);
  ASSERT_EQ(b.points.size(), 1u);
  EXPECT_EQ(b.points[0].lambda, 0.0);
  EXPECT_NE(b.end_message.find("lambda (LZ)"), std::string::npos) << b.end_message;
  const auto zero = OfType(b, "LZ");
  ASSERT_EQ(zero.size(), 1u);
  EXPECT_EQ(zero[0].point, 0);
}

// Keeps the step fixed and counts the accepted steps it is told of.
class FixedStep final : public StepSizeController {
 public:
  FixedStep(double ds, int* accepted) : ds_(ds), accepted_(accepted) {}
  double Initial() const override { return ds_; }
  double OnAccepted(double, int) override {
    ++*accepted_;
    return ds_;
  }
  double OnRejected(double ds) override { return 0.5 * ds; }

 private:
  double ds_;
  int* accepted_;
};

TEST(Continuation, TakesItsStepsFromAnInjectedStepSizeController) {
  const Circle circle;
  ContinuationOptions o = Options();  // the default controller would grow the steps to 0.2
  o.max_points = 20;
  o.detect_folds = false;
  int accepted = 0;
  const Branch b =
      Continuation(circle, nullptr, o, Eigen::Vector2d(1.0, 0.0), std::make_unique<FixedStep>(0.03, &accepted)).Run();
  ASSERT_EQ(b.points.size(), 20u);
  EXPECT_EQ(accepted, 19);
  for (std::size_t i = 1; i < b.points.size(); ++i) {
    EXPECT_EQ(b.points[i].ds, 0.03);
    // On the unit circle a step s along the tangent turns the point by asin(s).
    const double turned = std::atan2(b.points[i].lambda, b.points[i].u(0)) -
                          std::atan2(b.points[i - 1].lambda, b.points[i - 1].u(0));
    EXPECT_NEAR(turned, std::asin(0.03), 1e-10);
  }
}

TEST(Continuation, CanBeSteppedOnePointAtATime) {
  const Circle circle;
  ContinuationOptions o = Options();
  o.max_points = 10;
  Continuation c(circle, nullptr, o, Eigen::Vector2d(1.0, 0.0));
  int steps = 0;
  while (c.Step()) {
    ++steps;
    EXPECT_EQ(static_cast<int>(c.branch().points.size()), steps);
  }
  EXPECT_EQ(c.branch().end, BranchEnd::kMaxPoints);
  EXPECT_EQ(static_cast<int>(c.branch().points.size()), 10);
}

TEST(Continuation, MaxPointsEndNamesTheLimitAndWhereItStopped) {
  const Circle circle;
  ContinuationOptions o = Options();
  o.max_points = 3;
  o.parameter_name = "omega";
  const Branch b = Continuation(circle, nullptr, o, Eigen::Vector2d(1.0, 0.0)).Run();
  ASSERT_EQ(b.end, BranchEnd::kMaxPoints);
  EXPECT_EQ(b.end_message, fmt::format("max_points = 3 reached at omega = {:.10g}", b.points.back().lambda));
  o.max_points = 1;
  EXPECT_EQ(Continuation(circle, nullptr, o, Eigen::Vector2d(1.0, 0.0)).Run().end_message,
            "max_points = 1 reached at omega = 0");
}

// The InvalidInput that `f` throws, if any.
std::optional<InvalidInput> ThrownInvalidInput(const std::function<void()>& f) {
  try {
    f();
  } catch (const InvalidInput& e) {
    return e;
  }
  return std::nullopt;
}

TEST(ContinuationOptions, RejectInconsistentStepBounds) {
  ContinuationOptions o = Options();
  o.step.ds_min = 1.0;
  const std::optional<InvalidInput> e = ThrownInvalidInput([&] { o.Validate(); });
  ASSERT_TRUE(e.has_value()) << "ds_min > ds was accepted";
  EXPECT_EQ(e->field(), "ds_min");
  EXPECT_EQ(e->value(), "1");
}

TEST(Continuation, ThrowsInvalidInputNamingTheInvalidField) {
  const Circle circle;
  const std::vector<std::pair<std::function<void(ContinuationOptions*)>, std::string>> cases = {
      {[](ContinuationOptions* o) { o->step.ds = 0.0; }, "ds"},
      {[](ContinuationOptions* o) { o->direction = 0; }, "direction"},
      {[](ContinuationOptions* o) { o->location.tolerance = 0.0; }, "location.tolerance"},
      {[](ContinuationOptions* o) { o->parameter_index = 2; }, "parameter_index"},  // unknowns: x, lambda
  };
  for (const auto& [invalidate, field] : cases) {
    ContinuationOptions o = Options();
    invalidate(&o);
    const std::optional<InvalidInput> e =
        ThrownInvalidInput([&] { Continuation(circle, nullptr, o, Eigen::Vector2d(1.0, 0.0)); });
    ASSERT_TRUE(e.has_value()) << field << " was accepted";
    EXPECT_EQ(e->field(), field);
  }
}

}  // namespace
}  // namespace stickslip

namespace stickslip {
namespace {

// A start on a fold: at (0, 1) the circle's tangent is (1, 0), across the lambda axis, and both
// sides run towards decreasing lambda (lambda = sqrt(1 - x^2)).
TEST(PseudoArclength, StartsOnAFoldTowardsTheSideTheBranchRunsTo) {
  ContinuationOptions o = Options();
  o.max_points = 5;
  o.direction = -1;
  const Branch down = Continuation(Circle(), nullptr, o, Eigen::Vector2d(0.0, 1.0)).Run();
  ASSERT_EQ(down.end, BranchEnd::kMaxPoints) << down.end_message << " after " << down.points.size();
  for (std::size_t k = 1; k < down.points.size(); ++k) {
    const BranchPoint& p = down.points[k];
    EXPECT_LT(p.lambda, down.points[k - 1].lambda);
    EXPECT_NEAR(p.u(0) * p.u(0) + p.lambda * p.lambda, 1.0, 1e-10);
  }
  o.direction = 1;
  const Branch up = Continuation(Circle(), nullptr, o, Eigen::Vector2d(0.0, 1.0)).Run();
  EXPECT_EQ(up.end, BranchEnd::kFoldAtStart) << up.end_message;
  EXPECT_EQ(up.points.size(), 1u);
  EXPECT_NE(up.end_message.find("decreasing lambda"), std::string::npos) << up.end_message;
}

// A restart from a located fold is the fold itself: the first step does not report it again.
TEST(PseudoArclength, DoesNotReportTheStartsOwnFoldAgain) {
  ContinuationOptions o = Options();
  o.max_points = 20;
  o.direction = -1;
  const Branch b = Continuation(Circle(), nullptr, o, Eigen::Vector2d(0.0, 1.0)).Run();
  for (const SpecialPoint& lp : OfType(b, "LP")) EXPECT_NEAR(lp.lambda, -1.0, 1e-9);  // the other fold only
}

}  // namespace
}  // namespace stickslip

namespace stickslip {
namespace {

// The circle is a closed branch: once round, the branch ends on its start, with each fold once.
TEST(ClosedLoop, TheCircleEndsBackOnItsStartAfterOneLap) {
  ContinuationOptions o;
  o.parameter_index = 1;
  o.max_points = 2000;
  const Branch b = Continuation(Circle(), nullptr, o, Eigen::Vector2d(1.0, 0.0)).Run();
  ASSERT_EQ(b.end, BranchEnd::kClosedLoop) << b.end_message;
  EXPECT_STREQ(ToString(b.end), "closed-loop");
  EXPECT_LT((b.points.back().u - b.points.front().u).norm(), 1e-9);
  EXPECT_EQ(b.points.back().label, "EP");
  // One lap of arclength 2 pi, the steps at most ds_max: at least 2 pi / ds_max steps, and far
  // fewer than a second lap would take.
  EXPECT_GE(b.points.size(), static_cast<std::size_t>(2 * M_PI / o.step.ds_max));
  EXPECT_LT(b.points.size(), 2 * static_cast<std::size_t>(2 * M_PI / o.step.ds_max) + 10);
  double turned = 0.0;  // the angle swept, point to point: one full turn
  for (std::size_t k = 1; k < b.points.size(); ++k) {
    const Eigen::VectorXd& p = b.points[k - 1].u;
    const Eigen::VectorXd& q = b.points[k].u;
    turned += std::atan2(p(0) * q(1) - p(1) * q(0), p.dot(q));
    EXPECT_NEAR(q.squaredNorm(), 1.0, 1e-10);
  }
  EXPECT_NEAR(turned, 2 * M_PI, 1e-9);
  const auto folds = OfType(b, "LP");
  ASSERT_EQ(folds.size(), 2u);
  EXPECT_NEAR(folds[0].lambda, 1.0, 1e-10);
  EXPECT_NEAR(folds[1].lambda, -1.0, 1e-10);
  EXPECT_EQ(b.special_points.back().type, "EP");
  EXPECT_EQ(b.special_points.back().test_function, "closed-loop");
}

// A user value just before the start, on the last arc of the lap, is located on the way back to
// the start; one just after the start is not found twice.
TEST(ClosedLoop, FindsEachSpecialPointOnceRoundTheLoop) {
  ContinuationOptions o;
  o.parameter_index = 1;
  o.user_values = {{1, -1e-3, "lambda=-0.001"}, {1, 1e-3, "lambda=0.001"}};
  const Branch b = Continuation(Circle(), nullptr, o, Eigen::Vector2d(1.0, 0.0)).Run();
  ASSERT_EQ(b.end, BranchEnd::kClosedLoop) << b.end_message;
  std::vector<double> at;
  for (const SpecialPoint& s : OfType(b, "UZ")) at.push_back(s.lambda);
  // lambda = 0.001 once near x = 1 and once near x = -1; lambda = -0.001 likewise.
  ASSERT_EQ(at.size(), 4u);
  EXPECT_NEAR(at.front(), 1e-3, 1e-12);
  EXPECT_NEAR(at.back(), -1e-3, 1e-12);
  EXPECT_GT(OfType(b, "UZ").back().u(0), 0.0);  // on the arc back to the start at x = 1
}

// Started on a special point (a located zero of a test function, here lambda = -1e-13, as a restart
// from a stored label is), the lap ends there without reporting it again: the zero lies within the
// same-point distance of the start.
TEST(ClosedLoop, DoesNotReportTheStartsOwnSpecialPointAgainAtTheEnd) {
  FunctionMonitor monitor({{{.name = "lambda", .type = "LZ"}, [](double, double l) { return l + 1e-13; }}});
  ContinuationOptions o;
  o.parameter_index = 1;
  const Branch b = Continuation(Circle(), &monitor, o, Eigen::Vector2d(1.0, 0.0)).Run();
  ASSERT_EQ(b.end, BranchEnd::kClosedLoop) << b.end_message;
  const auto zeros = OfType(b, "LZ");
  ASSERT_EQ(zeros.size(), 1u);  // at x = -1 only
  EXPECT_NEAR(zeros[0].u(0), -1.0, 1e-9);
  EXPECT_LT((b.points.back().u - Eigen::Vector2d(1.0, 0.0)).norm(), 1e-9);
}

TEST(ClosedLoop, WithoutDetectionTheBranchGoesRoundUntilMaxPoints) {
  ContinuationOptions o;
  o.parameter_index = 1;
  o.max_points = 500;
  o.closed_loop.detect = false;
  const Branch b = Continuation(Circle(), nullptr, o, Eigen::Vector2d(1.0, 0.0)).Run();
  EXPECT_EQ(b.end, BranchEnd::kMaxPoints);
  EXPECT_GT(OfType(b, "LP").size(), 2u);  // round and round
}

// The cubic's branch is no loop: it passes near no earlier point and ends at its bound.
TEST(ClosedLoop, AnOpenBranchIsNotClosed) {
  ContinuationOptions o;
  o.parameter_index = 1;
  o.lambda_min = -2.0;
  o.lambda_max = 2.0;
  const Branch b = Continuation(Cubic(), nullptr, o, Eigen::Vector2d(0.0, 0.0)).Run();
  EXPECT_EQ(b.end, BranchEnd::kParameterBound) << b.end_message;
}

// A thin Z, lambda = y^3 - 3y with y = x/a: three sheets 3.4a apart at the start's lambda, closer
// than a step. The branch passes near its start on the third sheet, heading the same way, but
// never returns to it: it runs on to its bound.
struct ThinZ : ScalarProblem {
  double a = 1e-3;
  double F(double x, double l) const override { return l - (x * x * x / (a * a * a) - 3.0 * x / a); }
  double Fx(double x, double) const override { return -(3.0 * x * x / (a * a * a) - 3.0 / a); }
  double Fl(double, double) const override { return 1.0; }
};

TEST(ClosedLoop, ABranchPassingNearItsStartOnAnotherSheetIsNotClosed) {
  for (double a : {1e-2, 3e-3, 1e-3}) {
    ThinZ z;
    z.a = a;
    ContinuationOptions o;
    o.parameter_index = 1;
    o.lambda_min = -10.0;
    o.lambda_max = 10.0;
    o.step.ds_max = 0.2;
    const Branch b = Continuation(z, nullptr, o, Eigen::Vector2d(-1.5 * a, 1.125)).Run();
    EXPECT_EQ(b.end, BranchEnd::kParameterBound) << "a = " << a << ": " << b.end_message;
    EXPECT_EQ(OfType(b, "LP").size(), 2u) << "a = " << a;
  }
}

TEST(ClosedLoopOptions, RejectValuesOutOfRange) {
  for (const auto& [invalidate, field] : std::vector<std::pair<std::function<void(ClosedLoopOptions*)>, std::string>>{
           {[](ClosedLoopOptions* c) { c->tolerance = 0.0; }, "closed_loop.tolerance"},
           {[](ClosedLoopOptions* c) { c->alignment = 1.5; }, "closed_loop.alignment"},
           {[](ClosedLoopOptions* c) { c->departure = 0.5; }, "closed_loop.departure"},
           {[](ClosedLoopOptions* c) { c->landing = 0.0; }, "closed_loop.landing"}}) {
    ContinuationOptions o;
    o.parameter_index = 1;
    invalidate(&o.closed_loop);
    const std::optional<InvalidInput> e = ThrownInvalidInput([&] { o.Validate(); });
    ASSERT_TRUE(e.has_value()) << field;
    EXPECT_EQ(e->field(), field);
  }
}

// The progress callback sees every accepted point once, in order, with the branch's lambda.
TEST(ContinuationProgress, ReportsEveryAcceptedPointWithItsLambda) {
  ContinuationOptions o;
  o.parameter_index = 1;
  o.max_points = 30;
  std::vector<Progress> seen;
  o.progress = [&](const Progress& p) { seen.push_back(p); };
  const Branch b = Continuation(Circle(), nullptr, o, Eigen::Vector2d(1.0, 0.0)).Run();
  ASSERT_EQ(b.end, BranchEnd::kMaxPoints);
  // Located special points are points of the branch too, counted when the step is accepted.
  ASSERT_FALSE(seen.empty());
  EXPECT_EQ(seen.front().done, 1.0);
  EXPECT_EQ(seen.back().done, static_cast<double>(b.points.size()));
  for (std::size_t k = 0; k < seen.size(); ++k) {
    EXPECT_EQ(seen[k].total, 30.0);
    EXPECT_STREQ(seen[k].unit, "points");
    if (k > 0) {
      EXPECT_GT(seen[k].done, seen[k - 1].done);
    }
    EXPECT_EQ(seen[k].value, b.points[static_cast<std::size_t>(seen[k].done) - 1].lambda);
  }
}

}  // namespace
}  // namespace stickslip
