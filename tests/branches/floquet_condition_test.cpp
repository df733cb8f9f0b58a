// Curves of folds, period doublings, symmetry breakings and torus points in two parameters
// (branches/floquet_condition.hpp through BoundaryCurve): the test function's exact derivative
// against central differences; each curve through the point that one-parameter continuation in
// the other parameter locates (the paper runs in u_r at fixed omega), and a multiplier +1, -1 or a
// pair on the unit circle in the exact simulator's period map along the curve.
#include "stickslip/branches/floquet_condition.hpp"

#include <algorithm>
#include <complex>
#include <filesystem>

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include "stickslip/branches/boundary_curve.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/io/run.hpp"
#include "stickslip/orbits/margins.hpp"
#include "stickslip/orbits/stability.hpp"
#include "support/period_map.hpp"
#include "support/problem_at.hpp"
#include "support/section6_symmetry_breaking.hpp"
#include "support/solved_presets.hpp"

namespace stickslip {
namespace {

namespace fs = std::filesystem;
namespace ov = orbit_variables;

OrbitContinuationSetup RunFileSetup(const std::string& run) {
  const fs::path root(STICKSLIP_SOURCE_DIR);
  return MakeSetup(ReadRunFile(root / "continuation-scripts" / (run + ".toml")), root / "results");
}

// The orbit at the first located special point of `type` on the run's branch.
CurveStart Located(const std::string& run, const std::string& type) {
  const OrbitContinuationSetup setup = RunFileSetup(run);
  const OrbitBranch branch = ContinueOrbit(setup);
  for (const SpecialPoint& s : branch.branch.special_points) {
    if (s.type == type && s.located) return {branch.orbits[s.point], type, setup.parameter, setup.unknowns};
  }
  throw std::runtime_error(type + " not located on " + run + ": " + branch.branch.end_message);
}

// The condition of `type` made at `orbit`.
std::shared_ptr<const OrbitCondition> FloquetAt(std::string_view type, const Orbit& orbit, double max_singularity = 1e-4) {
  return FloquetCondition(type, ProblemAt(orbit), ov::Pack(orbit), max_singularity);
}

double Residual(const OrbitCondition& c, const Orbit& o) {
  Eigen::VectorXd r;
  c.Evaluate(ProblemAt(o), ov::Pack(o), Eigen::VectorXd(), &r, nullptr, nullptr);
  return r(0);
}

void ExpectCentralDifferences(const OrbitCondition& c, const Orbit& o) {
  Eigen::VectorXd r;
  Eigen::MatrixXd d;
  Eigen::MatrixXd d_extra;
  c.Evaluate(ProblemAt(o), ov::Pack(o), Eigen::VectorXd(), &r, &d, &d_extra);
  const Eigen::VectorXd v = ov::Pack(o);
  ASSERT_EQ(d.cols(), v.size());
  EXPECT_EQ(d_extra.cols(), 0);
  for (int k = 0; k < v.size(); ++k) {
    const double h = 1e-6 * (1.0 + std::abs(v(k)));
    Eigen::VectorXd plus = v, minus = v;
    plus(k) += h;
    minus(k) -= h;
    const double fd = (Residual(c, ov::Unpack(o.signature, plus)) - Residual(c, ov::Unpack(o.signature, minus))) / (2 * h);
    EXPECT_NEAR(d(0, k), fd, 1e-6 * (1.0 + std::abs(fd))) << c.Name() << " d/d" << ov::Name(o.signature.size(), k);
  }
}

TEST(FloquetCondition, DerivativeIsTheCentralDifferenceOfTheTestFunction) {
  for (const char* type : {"LP", "PD"}) ExpectCentralDifferences(*FloquetAt(type, SolvedPreset("paper-5.1"), 1.0), SolvedPreset("paper-5.1"));
  for (const char* type : {"LP", "SB"}) ExpectCentralDifferences(*FloquetAt(type, SolvedPreset("paper-6"), 1.0), SolvedPreset("paper-6"));
  const CurveStart tr = Located("paper-5.1-omega-up", "TR");
  ExpectCentralDifferences(*FloquetAt("TR", tr.orbit), tr.orbit);
}

TEST(FloquetCondition, RefusesPointsAndTypesWithoutACurve) {
  const Orbit section5 = SolvedPreset("paper-5.1");
  const Orbit section6 = SolvedPreset("paper-6");
  EXPECT_THROW(FloquetAt("LP", section5), InvalidInput);  // no multiplier near +1 there
  EXPECT_THROW(FloquetAt("SB", section5, 1.0), InvalidInput);  // not antisymmetric
  EXPECT_THROW(FloquetAt("PD", section6, 1.0), InvalidInput);  // antisymmetric: SB instead
  EXPECT_THROW(FloquetAt("GR", section5, 1.0), InvalidInput);
  const CurveStart lp = Located("paper-5.1-omega-up", "LP");
  const OrbitContinuationSetup setup = RunFileSetup("paper-5.1-omega-up");
  EXPECT_THROW(BoundaryCurve(lp, setup, "omega"), InvalidInput);  // the continued one
  EXPECT_THROW(BoundaryCurve(lp, setup, "d1"), InvalidInput);
  EXPECT_THROW(BoundaryCurve(lp, setup, "nonsense"), InvalidInput);
}

// The curve through `start` in (omega, u_r), stopped on the line omega = `omega` (a user value).
Orbit CurveAtOmega(const CurveStart& start, double omega) {
  OrbitContinuationSetup setup = BoundaryCurve(start, RunFileSetup("paper-5.1-omega-up"), "u_r");
  const int omega_index = static_cast<int>(FreeIndices(setup.start.signature, setup.unknowns).size());
  setup.options.user_values = {{omega_index, omega, "omega"}};
  setup.options.direction = omega < start.orbit.parameters.omega ? -1 : 1;
  setup.options.step.ds = 0.002;
  setup.options.step.ds_max = 0.01;
  setup.options.max_points = 200;
  const OrbitBranch curve = ContinueOrbit(setup);
  for (const SpecialPoint& s : curve.branch.special_points) {
    if (s.type == "UZ" && s.located) return curve.orbits[s.point];
  }
  throw std::runtime_error("the curve does not reach omega = " + std::to_string(omega) + ": " + curve.branch.end_message);
}

struct CurveCase {
  const char* omega_run;  // locates the start
  const char* u_r_run;    // at fixed omega, locates the same kind of point
  const char* type;
};

class FloquetCurve : public ::testing::TestWithParam<CurveCase> {};

TEST_P(FloquetCurve, PassesThroughThePointTheUrBranchLocates) {
  const CurveCase& c = GetParam();
  const CurveStart start = Located(c.omega_run, c.type);
  const CurveStart target = Located(c.u_r_run, c.type);
  const Orbit on_curve = CurveAtOmega(start, target.orbit.parameters.omega);
  EXPECT_NEAR(on_curve.parameters.omega, target.orbit.parameters.omega, 1e-12);
  EXPECT_NEAR(on_curve.parameters.u_r, target.orbit.parameters.u_r, 1e-9) << "from " << start.orbit.parameters.u_r;
  EXPECT_GT(std::abs(on_curve.parameters.u_r - start.orbit.parameters.u_r), 1e-3);  // it moved
}

TEST_P(FloquetCurve, HasTheMultiplierOfItsTypeInTheSimulatorsPeriodMap) {
  const CurveCase& c = GetParam();
  const CurveStart start = Located(c.omega_run, c.type);
  const CurveStart target = Located(c.u_r_run, c.type);
  // Half-way between the two located points, the orbit on the curve.
  const Orbit o = CurveAtOmega(start, 0.5 * (start.orbit.parameters.omega + target.orbit.parameters.omega));
  const Eigen::EigenSolver<Eigen::Matrix4d> eigen(PeriodMapJacobian(o), false);
  double nearest = INFINITY;
  for (int i = 0; i < 4; ++i) {
    const std::complex<double> mu = eigen.eigenvalues()(i);
    if (std::string(c.type) == "LP") nearest = std::min(nearest, std::abs(mu - 1.0));
    if (std::string(c.type) == "TR" && mu.imag() != 0.0) nearest = std::min(nearest, std::abs(std::abs(mu) - 1.0));
  }
  EXPECT_LT(nearest, 1e-6) << c.type << " at omega = " << o.parameters.omega << ", u_r = " << o.parameters.u_r;
  EXPECT_LT(nearest, 1e-6);
}

INSTANTIATE_TEST_SUITE_P(PaperRuns, FloquetCurve,
                         ::testing::Values(CurveCase{"paper-5.1-omega-up", "paper-5.1-u_r-up", "LP"},
                                           CurveCase{"paper-5.1-omega-up", "paper-5.1-u_r-up", "TR"},
                                           CurveCase{"paper-6-omega-up", "paper-6-u_r-up", "LP"},
                                           CurveCase{"paper-6-omega-up", "paper-6-u_r-up", "TR"}),
                         [](const auto& test) {
                           return std::string(test.param.omega_run).substr(6, 1) + "_" + test.param.type;
                         });


// The first located special point of `type` on the branch of `setup`.
CurveStart LocatedOn(const OrbitContinuationSetup& setup, const std::string& type) {
  const OrbitBranch branch = ContinueOrbit(setup);
  for (const SpecialPoint& s : branch.branch.special_points) {
    if (s.type == type && s.located) return {branch.orbits[s.point], type, setup.parameter, setup.unknowns};
  }
  throw std::runtime_error(type + " not located: " + branch.branch.end_message);
}

// From a PD (section 5.2) and an SB (section 6), the curve in (omega, u_r): at a few of its points,
// continuation in omega at that u_r, from 0.0005 above, locates the same kind of point at the
// curve's omega; and, for the PD (a motion), the exact simulator's period map has the multiplier
// -1 there. (The SB's orbits are past their type changes, no motions: the simulator leaves them.
// SymmetryTest.* checks det(H + I) against the simulator on motions.)
TEST(FloquetCurve, PeriodDoublingAndSymmetryBreakingCurvesAreWhereOmegaBranchesLocateThem) {
  struct Case {
    OrbitContinuationSetup branch;
    const char* type;
    double multiplier;  // of the simulator's period map: -1 at a PD
    bool continue_past_type_changes;  // the SB's orbits are no motions: the simulator cannot show them
  };
  OrbitContinuationSetup pd_branch = RunFileSetup("paper-5.2-omega-to-pd");
  for (const Case& c : {Case{pd_branch, "PD", -1.0, false}, Case{Section6AboveItsSymmetryBreaking(), "SB", 1.0, true}}) {
    const CurveStart start = LocatedOn(c.branch, c.type);
    OrbitContinuationSetup setup = BoundaryCurve(start, c.branch, "u_r");
    setup.options.step.ds = 0.002;
    setup.options.step.ds_max = 0.004;
    setup.options.max_points = 6;
    setup.options.continue_past_terminal = c.continue_past_type_changes;
    const OrbitBranch curve = ContinueOrbit(setup);
    ASSERT_GE(curve.orbits.size(), 6u) << c.type << ": " << curve.branch.end_message;
    for (std::size_t k = 2; k < curve.orbits.size(); k += 3) {
      const Orbit& o = curve.orbits[k];
      EXPECT_GT(std::abs(o.parameters.u_r - start.orbit.parameters.u_r), 1e-4) << c.type;
      OrbitContinuationSetup again = c.branch;
      again.start = o;
      again.start.parameters.omega += 0.0005;
      again.options.direction = -1;
      again.options.max_points = 300;
      again.options.lambda_min = o.parameters.omega - 0.01;
      again.options.lambda_max = o.parameters.omega + 0.01;
      const CurveStart found = LocatedOn(again, c.type);
      EXPECT_NEAR(found.orbit.parameters.omega, o.parameters.omega, 1e-9) << c.type << " at u_r = " << o.parameters.u_r;
      EXPECT_EQ(found.orbit.parameters.u_r, o.parameters.u_r);
      if (c.continue_past_type_changes) continue;
      const Eigen::EigenSolver<Eigen::Matrix4d> eigen(PeriodMapJacobian(o), false);
      double nearest = INFINITY;
      for (int i = 0; i < 4; ++i) nearest = std::min(nearest, std::abs(eigen.eigenvalues()(i) - c.multiplier));
      EXPECT_LT(nearest, 1e-6) << c.type << " at omega = " << o.parameters.omega << ", u_r = " << o.parameters.u_r;
    }
  }
}

// The §5.2 PD curve meets a fold curve at a fold-flip (LPPD: multipliers +1 and -1): located on
// the PD curve as det(M - I) changing sign, and on the fold curve, approached from a point of its
// own, as det(M + I) changing sign: the same point from each side (1e-9), where the exact
// simulator's period map has both multipliers (1e-6).
TEST(FloquetCurve, FoldFlipIsFoundFromThePeriodDoublingAndTheFoldCurve) {
  const OrbitContinuationSetup branch = RunFileSetup("paper-5.2-omega-to-pd");
  OrbitContinuationSetup pd = BoundaryCurve(LocatedOn(branch, "PD"), branch, "u_r");
  pd.options.direction = -1;
  pd.options.step.ds = 0.002;
  pd.options.step.ds_max = 0.01;
  pd.options.max_points = 150;
  const CurveStart on_pd = LocatedOn(pd, "LPPD");
  // The fold curve through it, followed away and back.
  OrbitContinuationSetup fold = BoundaryCurve({on_pd.orbit, "LP", "omega", branch.unknowns}, branch, "u_r");
  fold.options.step.ds = 0.002;
  fold.options.step.ds_max = 0.004;
  fold.options.max_points = 5;
  const OrbitBranch away = ContinueOrbit(fold);
  ASSERT_EQ(away.orbits.size(), 5u) << away.branch.end_message;
  OrbitContinuationSetup back = BoundaryCurve({away.orbits.back(), "LP", "omega", branch.unknowns}, branch, "u_r");
  back.options = fold.options;
  back.options.direction = -fold.options.direction;
  back.options.max_points = 20;
  const CurveStart on_fold = LocatedOn(back, "LPPD");
  EXPECT_NEAR(on_fold.orbit.parameters.omega, on_pd.orbit.parameters.omega, 1e-9);
  EXPECT_NEAR(on_fold.orbit.parameters.u_r, on_pd.orbit.parameters.u_r, 1e-9);
  const Stability s = StabilityOf(on_pd.orbit);
  EXPECT_NEAR(s.fold_test, 0.0, 1e-9);
  EXPECT_NEAR(s.flip_test, 0.0, 1e-9);
  const Eigen::EigenSolver<Eigen::Matrix4d> eigen(PeriodMapJacobian(on_pd.orbit), false);
  double near_plus = INFINITY, near_minus = INFINITY;
  for (int i = 0; i < 4; ++i) {
    near_plus = std::min(near_plus, std::abs(eigen.eigenvalues()(i) - 1.0));
    near_minus = std::min(near_minus, std::abs(eigen.eigenvalues()(i) + 1.0));
  }
  EXPECT_LT(near_plus, 1e-6);
  EXPECT_LT(near_minus, 1e-6);
}

// Below omega = 0.555 the section 5.1 fold curve ends where the stick's exit turns tangential
// (exit-slope:3 = 0). There the exit's saltation matrix divides by the slope, one multiplier runs
// through infinity (about 0.72/exit-slope:3), and det(M + I) and p'(1) change sign through that
// pole: no fold-flip and no 1:1 resonance, as the exact simulator's period map shows at the last
// point before the end (no multiplier near -1, one near +1). Only the genuine R1 is reported.
TEST(FloquetCurve, EndsAtTheTangentialStickExitWithoutAFoldFlipOrResonanceThere) {
  const OrbitContinuationSetup branch = RunFileSetup("paper-5.1-omega-up");
  OrbitContinuationSetup fold = BoundaryCurve(Located("paper-5.1-omega-up", "LP"), branch, "u_r");
  fold.options.direction = -1;
  fold.options.lambda_min = 0.5;
  fold.options.step.ds = 0.002;
  fold.options.step.ds_max = 0.002;
  fold.options.max_points = 3000;
  const OrbitBranch curve = ContinueOrbit(fold);
  ASSERT_EQ(curve.branch.end, BranchEnd::kTerminalEvent) << curve.branch.end_message;
  int resonances = 0;
  for (const SpecialPoint& s : curve.branch.special_points) {
    EXPECT_NE(s.type, "LPPD") << "at omega = " << s.lambda;
    if (s.type != "R1") continue;
    ++resonances;
    EXPECT_TRUE(s.located);
    EXPECT_NEAR(s.lambda, 0.5620757769, 1e-9);  // paper-5.1-fold-curve's R1
  }
  EXPECT_EQ(resonances, 1);
  // The last point before the end that is a motion with exit-slope:3 >= 5e-3: nearer the pole the
  // period map's central differences (steps 1e-6) would reach across the tangential exit.
  const Orbit* last = nullptr;
  double slope = 0.0;
  for (const Orbit& o : curve.orbits) {
    const std::vector<Margin> margins = AdmissibilityMargins(o);
    for (const Margin& m : margins) {
      if (m.Name() == "exit-slope:3" && m.value >= 5e-3 && SmallestMargin(margins).value > 0.0) {
        last = &o;
        slope = m.value;
      }
    }
  }
  ASSERT_NE(last, nullptr);
  EXPECT_LT(slope, 1e-2);  // near the end
  const Eigen::EigenSolver<Eigen::Matrix4d> eigen(PeriodMapJacobian(*last), false);
  double largest = 0.0, near_minus = INFINITY;
  int near_plus = 0;
  for (int i = 0; i < 4; ++i) {
    const std::complex<double> mu = eigen.eigenvalues()(i);
    largest = std::max(largest, std::abs(mu));
    near_minus = std::min(near_minus, std::abs(mu + 1.0));
    if (std::abs(mu - 1.0) < 1e-3) ++near_plus;
  }
  EXPECT_GT(largest, 50.0);     // the pole is near
  EXPECT_GT(near_minus, 0.5);   // no multiplier -1 (LPPD)
  EXPECT_EQ(near_plus, 1) << "exit-slope:3 = " << slope << ", multipliers " << eigen.eigenvalues().transpose();  // the fold's +1 only, no double +1 (R1)
}

// The family ends where the sliding friction vanishes (eq. 4: 0 < u_s): the §5.1 fold curve in
// (omega, u_s), downwards, ends at a located u_s = 0, the sliding-friction margin's zero.
TEST(FloquetCurve, InTheSlidingFrictionEndsWhereItVanishes) {
  const OrbitContinuationSetup branch = RunFileSetup("paper-5.1-omega-up");
  OrbitContinuationSetup fold = BoundaryCurve(Located("paper-5.1-omega-up", "LP"), branch, "u_s");
  fold.options.direction = -1;
  fold.options.lambda_min = 0.3;
  fold.options.max_points = 3000;
  const OrbitBranch curve = ContinueOrbit(fold);
  ASSERT_EQ(curve.branch.end, BranchEnd::kTerminalEvent) << curve.branch.end_message;
  const auto end = std::find_if(curve.branch.special_points.begin(), curve.branch.special_points.end(),
                                [](const SpecialPoint& s) { return s.test_function == "margin:sliding-friction"; });
  ASSERT_NE(end, curve.branch.special_points.end());
  EXPECT_TRUE(end->located);
  EXPECT_NEAR(curve.orbits[end->point].parameters.u_s, 0.0, 1e-9);
  EXPECT_EQ(end->point + 1, static_cast<int>(curve.orbits.size()));  // the last point
  EXPECT_GT(curve.orbits.front().parameters.u_s, 0.01);             // from the paper's 0.0138
}

}  // namespace
}  // namespace stickslip
