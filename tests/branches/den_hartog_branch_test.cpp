// A branch of the general linear oscillator (model/linear_oscillator.hpp) through the
// continuation engine, against Den Hartog's closed forms (Trans. ASME APM 53 (1931) 107;
// ../shared/FRICTION-LITERATURE.md): the non-sticking orbit's amplitude
// X = sqrt(V^2 - beta^2 U^2) along a branch in the friction level, the level
// beta* = |V| / sqrt(U^2 + 1/r^4) where its turning points start to stick (r^2 X = beta), the
// one-term harmonic balance's error, and the degenerate frequencies r = 1/(2n) (Csernak, Stepan &
// Shaw 2007) where the full-period periodicity equations are singular and the half-period ones are not;
// with viscous damping, the energy balance over a period and the viscous response as friction vanishes.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <tuple>
#include <variant>

#include <Eigen/SVD>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gtest/gtest.h>

#include "stickslip/branches/model_boundary_curve.hpp"
#include "stickslip/branches/model_orbit_continuation.hpp"
#include "stickslip/continuation/continuation.hpp"
#include "stickslip/model/exact_simulator.hpp"
#include "stickslip/orbits/margins.hpp"
#include "stickslip/orbits/model_orbit_solver.hpp"
#include "stickslip/orbits/orbit_measures.hpp"
#include "stickslip/orbits/orbit_system.hpp"
#include "support/den_hartog_orbit.hpp"
#include "support/den_hartog_oscillator.hpp"
#include "support/general_models.hpp"

namespace stickslip {
namespace {

using Equations = BasicPeriodicityEquations<DenHartogOscillator>;
using System = BasicOrbitSystem<DenHartogOscillator>;

double StickingLevel(double r) {
  const DenHartogOrbit o(r, 0.0);
  return std::abs(o.v) / std::sqrt(o.u * o.u + 1.0 / std::pow(r, 4));
}

// Den Hartog's non-sticking orbit as a start of the library's branches.
BasicOrbit<DenHartogOscillator> DenHartogStart(double r, double beta) {
  const DenHartogOrbit o(r, beta);
  return {Signature::Parse("slip- / antisymmetric"), {r, beta, beta, 0.0}, {o.amplitude, 0.0}, o.phi, {o.Period() / 2}};
}

// A branch from it in `parameter`, with the library's defaults.
BasicOrbitContinuationSetup<DenHartogOscillator> DenHartogSetup(double r, double beta, const char* parameter) {
  return {DenHartogStart(r, beta), {}, parameter, ShootingChoice::kAuto, LinearSolverType::kKlu, {}, {}, {}, {},
          kDefaultMaxAmplitude, kDefaultResonanceApproach, DenHartogModel()};
}

// The branch of the general model through the same path as the paper's (ContinueOrbit: the erased
// orbit problem, the orbit monitor, the resonance ends), which proves the seam is the model
// interface: every point's amplitude is Den Hartog's X(r, beta), and the branch ends at the stop
// margin's sign change (SK), where the turning points start to stick, at beta*.
class DenHartogBranchInFriction : public testing::TestWithParam<double> {};

TEST_P(DenHartogBranchInFriction, FollowsTheClosedFormAmplitudeAndEndsWhereTheTurningPointsStick) {
  const double r = GetParam();
  BasicOrbitContinuationSetup<DenHartogOscillator> setup = DenHartogSetup(r, 0.05, "F_k");
  setup.unknowns.tie_static_friction = true;
  setup.options.lambda_max = 2.0;
  setup.options.max_points = 500;
  const BasicOrbitBranch<DenHartogOscillator> result = ContinueOrbit(setup);
  const Branch& branch = result.branch;
  ASSERT_GT(branch.points.size(), 5u);
  ASSERT_EQ(result.orbits.size(), branch.points.size());
  double worst = 0.0;
  for (const BasicOrbit<DenHartogOscillator>& orbit : result.orbits) {
    const double beta = orbit.parameters.F_k;
    EXPECT_EQ(orbit.parameters.F_s, beta) << "tied";
    EXPECT_NEAR(orbit.start(0), DenHartogOrbit(r, beta).amplitude, 1e-9) << "beta = " << beta;
    EXPECT_NEAR(orbit.durations[0], std::numbers::pi / r, 1e-9) << "beta = " << beta;
    worst = std::max(worst, std::abs(orbit.start(0) - DenHartogOrbit(r, beta).amplitude));
  }
  RecordProperty("points", static_cast<int>(branch.points.size()));
  RecordProperty("worst_amplitude_difference", fmt::format("{:.3g}", worst));
  const auto stick = std::find_if(branch.special_points.begin(), branch.special_points.end(),
                                  [](const SpecialPoint& p) { return p.type == "SK"; });
  ASSERT_NE(stick, branch.special_points.end()) << ToString(branch.end) << ": " << branch.end_message;
  EXPECT_TRUE(stick->located);
  EXPECT_NEAR(stick->lambda, StickingLevel(r), 1e-8) << "r = " << r;
  RecordProperty("sticking_level_difference", fmt::format("{:.3g}", stick->lambda - StickingLevel(r)));
}

INSTANTIATE_TEST_SUITE_P(FrequencyRatios, DenHartogBranchInFriction, testing::Values(0.8, 1.5, 2.5));

// The level beta* is largest where d beta*/dr = 0: golden-section search on the closed form.
std::pair<double, double> LargestStickingLevel() {
  const double golden = (std::sqrt(5.0) - 1.0) / 2.0;
  double a = 0.6, b = 1.2;
  for (int k = 0; k < 200 && b - a > 1e-12; ++k) {
    const double c = b - golden * (b - a), d = a + golden * (b - a);
    if (StickingLevel(c) > StickingLevel(d)) {
      b = d;
    } else {
      a = c;
    }
  }
  return {(a + b) / 2, StickingLevel((a + b) / 2)};
}

// The type boundary where the turning points start to stick, continued in two parameters through
// the general model (BoundaryCurve: the located SK's margin = 0 with omega released): every point
// of the curve is Den Hartog's beta*(r), with his amplitude there, and the curve's own fold in F_k
// is the largest beta*, where d beta*/dr = 0.
TEST(DenHartogStickBoundary, IsTheClosedFormLevelOverTheFrequencyRatio) {
  BasicOrbitContinuationSetup<DenHartogOscillator> branch_setup = DenHartogSetup(0.8, 0.05, "F_k");
  branch_setup.unknowns.tie_static_friction = true;
  branch_setup.options.lambda_max = 2.0;
  const BasicOrbitBranch<DenHartogOscillator> branch = ContinueOrbit(branch_setup);
  const auto stick = std::find_if(branch.branch.special_points.begin(), branch.branch.special_points.end(),
                                  [](const SpecialPoint& p) { return p.type == "SK"; });
  ASSERT_NE(stick, branch.branch.special_points.end()) << branch.branch.end_message;
  const BasicCurveStart<DenHartogOscillator> start{branch.orbits[stick->point], stick->test_function, "F_k",
                                                   branch_setup.unknowns};
  BasicOrbitContinuationSetup<DenHartogOscillator> curve_setup = BoundaryCurve(start, branch_setup, "omega");
  curve_setup.options.lambda_min = 0.45;  // r = 0.561, before the degenerate r = 1/2
  curve_setup.options.max_points = 120;
  curve_setup.options.step.ds_max = 0.05;
  for (int direction : {-1, 1}) {
    SCOPED_TRACE(direction);
    curve_setup.options.direction = direction;
    const BasicOrbitBranch<DenHartogOscillator> curve = ContinueOrbit(curve_setup);
    ASSERT_GT(curve.orbits.size(), 20u) << curve.branch.end_message;
    double worst = 0.0, r_min = INFINITY, r_max = 0.0;
    for (const BasicOrbit<DenHartogOscillator>& orbit : curve.orbits) {
      const double r = orbit.parameters.omega, beta = orbit.parameters.F_k;
      EXPECT_NEAR(beta, StickingLevel(r), 1e-12) << "r = " << r;
      EXPECT_NEAR(orbit.start(0), DenHartogOrbit(r, beta).amplitude, 1e-8) << "r = " << r;
      worst = std::max(worst, std::abs(beta - StickingLevel(r)));
      r_min = std::min(r_min, r), r_max = std::max(r_max, r);
    }
    RecordProperty(direction < 0 ? "worst_level_difference_down" : "worst_level_difference_up", fmt::format("{:.3g}", worst));
    if (direction < 0) {
      EXPECT_EQ(curve.branch.end, BranchEnd::kParameterBound) << curve.branch.end_message;
      EXPECT_LT(r_min, 0.57) << "beta* = 0.45 near r = 0.561";
      continue;
    }
    EXPECT_GT(r_max, 1.5) << "the curve passes r = 1 (beta* = pi/4 there) and goes on";
    const auto fold = std::find_if(curve.branch.special_points.begin(), curve.branch.special_points.end(),
                                   [](const SpecialPoint& p) { return p.type == "LP"; });
    ASSERT_NE(fold, curve.branch.special_points.end());
    const auto [r_star, beta_star] = LargestStickingLevel();
    EXPECT_NEAR(fold->lambda, beta_star, 1e-9);
    EXPECT_NEAR(curve.orbits[fold->point].parameters.omega, r_star, 1e-5);
  }
}

// The columns are the model's: its one coordinate's (x) amplitude and peak-to-peak, two multipliers.
// Den Hartog's orbit, undamped and never sticking, has no bounded amplitude at r = 1 (X grows as
// 1/(1 - r^2)): a branch in the forcing frequency ends there as a resonance, at omega_1 = 1.
TEST(DenHartogBranchInFrequency, EndsAtTheResonanceOfTheUndampedSlip) {
  BasicOrbitContinuationSetup<DenHartogOscillator> setup = DenHartogSetup(0.6, 0.1, "omega");
  setup.options.lambda_max = 2.0;
  setup.options.max_points = 2000;
  const BasicOrbitBranch<DenHartogOscillator> result = ContinueOrbit(setup);
  std::vector<std::string> names;
  for (const PointColumn& c : result.columns) names.push_back(c.name);
  for (const char* name : {"amplitude:x", "peak-to-peak:x", "floquet:mu2_re", "friction-work"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name << " not in " << fmt::format("{}", fmt::join(names, " "));
  }
  EXPECT_EQ(std::find(names.begin(), names.end(), "floquet:mu3_re"), names.end());
  EXPECT_EQ(result.branch.end, BranchEnd::kStopped) << result.branch.end_message;
  EXPECT_TRUE(result.branch.end_message.starts_with("resonance: at omega_1 = 1,")) << result.branch.end_message;
  for (const BasicOrbit<DenHartogOscillator>& orbit : result.orbits) {
    const double r = orbit.parameters.omega;
    EXPECT_NEAR(orbit.start(0), DenHartogOrbit(r, 0.1).amplitude, 1e-9 * DenHartogOrbit(r, 0.1).amplitude) << "r = " << r;
  }
  EXPECT_GT(result.orbits.back().parameters.omega, 0.99);
}

// Newton from the one-term harmonic balance's amplitude sqrt(1 - (4 beta/pi)^2) / |1 - r^2| (the
// equivalent viscous damping) converges to Den Hartog's X; the balance's error is within 0.7 beta^2
// relative for beta up to beta*/2 on r in [0.6, 3] (nearer beta* it grows: 1.2 beta^2 at 0.99 beta*).
TEST(DenHartogOrbit, OneTermHarmonicBalanceIsWithinItsBoundAndNewtonCorrectsIt) {
  const DenHartogOscillator model = DenHartogModel();
  const Equations equations(model, Signature::Parse("slip- / antisymmetric"), Shooting::kSingle);
  for (double r : {0.6, 0.8, 1.2, 1.5, 2.0, 2.5, 3.0}) {
    for (double fraction : {0.1, 0.5}) {
      const double beta = fraction * StickingLevel(r);
      const DenHartogOrbit exact(r, beta);
      const double balance = std::sqrt(1.0 - std::pow(4.0 * beta / std::numbers::pi, 2)) / std::abs(1.0 - r * r);
      EXPECT_LE(std::abs(balance - exact.amplitude) / exact.amplitude, 0.7 * beta * beta) << "r = " << r;
      Eigen::VectorXd guess = DenHartogVariables(exact, equations);
      guess(0) = balance;
      guess(equations.Phi()) += 0.05;
      const System system(equations, guess, {0, 1, 2}, true);
      const NewtonResult solved = SolveNewton(system, system.Unknowns(guess));
      ASSERT_TRUE(solved.summary.Converged()) << solved.summary.message;
      EXPECT_NEAR(solved.solution(0), exact.amplitude, 1e-10) << "r = " << r << ", beta = " << beta;
    }
  }
}

// Smallest over largest singular value of the periodicity equations' Jacobian in the start, the
// phase and the durations, at Den Hartog's orbit.
double Conditioning(const char* signature, double r, double beta) {
  const DenHartogOscillator model = DenHartogModel();
  const Equations equations(model, Signature::Parse(signature), Shooting::kSingle);
  const Eigen::VectorXd v = DenHartogVariables(DenHartogOrbit(r, beta), equations);
  std::vector<int> free(equations.Parameter(0));
  std::iota(free.begin(), free.end(), 0);
  const System system(equations, v, free, false);
  Eigen::VectorXd residual;
  JacobianMatrix jacobian;
  system.Evaluate(system.Unknowns(v), &residual, &jacobian);
  EXPECT_LT(residual.lpNorm<Eigen::Infinity>(), 1e-12) << signature << ", r = " << r;
  const Eigen::VectorXd s = Eigen::JacobiSVD<Eigen::MatrixXd>(std::get<Eigen::MatrixXd>(jacobian)).singularValues();
  return s(s.size() - 1) / s(0);
}

// At r = 1/(2n) the free oscillation's period divides the half period: every orbit of the
// continuum that it adds is periodic (a multiplier 1, U = 0: the amplitude does not depend on the
// friction), so the full-period equations are singular there; the antisymmetric half-period ones
// ask for x(T/2) = -x(0), which the free oscillation (returning to +x) does not satisfy: regular.
TEST(DenHartogOrbit, DegenerateFrequencyMakesTheFullPeriodEquationsSingularNotTheHalfPeriods) {
  for (double r : {0.5, 0.25}) {
    EXPECT_LT(Conditioning("slip- slip+", r, 0.05), 1e-12) << "r = " << r;
    EXPECT_GT(Conditioning("slip- / antisymmetric", r, 0.05), 1e-3) << "r = " << r;
  }
  EXPECT_GT(Conditioning("slip- slip+", 0.8, 0.05), 1e-3);  // away from 1/(2n): regular both ways
}

// There the full-period equations have a continuum of solutions (the free oscillation adds to any
// of them), and SolveOrbit says so instead of failing on the singular Jacobian: from two guesses
// of different amplitude (0.5 % below and above Den Hartog's X, the phase off by 0.01) it finds
// two different orbits at the same parameters, each one of a one-dimensional family, admissible
// and a periodic motion of the exact simulator (event-driven: no periodicity equations). (Farther
// along the family the static level holds a turning point: members that are not motions.) Away
// from 1/(2n) the same guesses give Den Hartog's isolated orbit.
TEST(DenHartogOrbit, DegenerateFrequencyGivesAFamilyOfOrbitsNotANewtonFailure) {
  const DenHartogOscillator model = DenHartogModel();
  for (double r : {0.5, 0.25, 0.8}) {
    const DenHartogOrbit exact(r, 0.05);
    const bool degenerate = r != 0.8;
    std::vector<double> amplitudes;
    for (double scale : {0.995, 1.005}) {
      BasicOrbit<DenHartogOscillator> guess = DenHartogOnSignature(exact, "slip- slip+", 0.05);
      guess.start(0) *= scale;
      guess.phi += 0.01;
      const BasicOrbitSolution<DenHartogOscillator> solved = SolveOrbit(model, guess, {0, 1, 2, 3}, false);
      ASSERT_TRUE(solved.summary.Converged()) << "r = " << r << ": " << solved.summary.message;
      EXPECT_EQ(solved.family_dimension, degenerate ? 1 : 0) << "r = " << r;
      EXPECT_EQ(solved.summary.message.starts_with("not isolated: one of a 1-dimensional family"), degenerate);
      const BasicOrbit<DenHartogOscillator>& o = solved.orbit;
      BasicSimulationOptions<DenHartogOscillator::State> options;
      options.duration = o.durations[0] + o.durations[1];
      const BasicSimulationResult<DenHartogOscillator> motion = SimulateExact(model, o.parameters, o.start, o.phi, options);
      ASSERT_TRUE(motion.Completed()) << motion.message;
      ASSERT_GT(SmallestMargin(AdmissibilityMargins(model, o)).value, 0.0) << "r = " << r << ": a motion";
      EXPECT_LT((motion.segments.back().end - o.start).lpNorm<Eigen::Infinity>(), 1e-9) << "r = " << r;
      amplitudes.push_back(o.start(0));
    }
    if (degenerate) {
      EXPECT_GT(amplitudes[1] - amplitudes[0], 0.005 * exact.amplitude) << "r = " << r << ": two members of the family";
    } else {
      EXPECT_NEAR(amplitudes[0], exact.amplitude, 1e-10);
      EXPECT_NEAR(amplitudes[1], exact.amplitude, 1e-10);
    }
  }
}

// Den Hartog's oscillator with viscous damping c (Phil. Mag. 9 (1930) 801: combined viscous and
// Coulomb damping), x'' + c x' + x = cos(omega t + phi) + F, solved by Newton from the undamped
// orbit: the non-sticking orbit with two stops per period, on "slip- / antisymmetric".
BasicOrbit<LinearOscillator<1>> DampedOrbit(const LinearOscillator<1>& model, double r, double beta) {
  const BasicOrbitSolution<LinearOscillator<1>> solved = SolveOrbit(model, DenHartogStart(r, beta), {0, 1, 2}, false);
  EXPECT_TRUE(solved.summary.Converged()) << solved.summary.message;
  return solved.orbit;
}

LinearOscillator<1> DampedDenHartog(double c) {
  LinearOscillatorData data = DenHartogData();
  data.damping = Eigen::MatrixXd::Constant(1, 1, c);
  return LinearOscillator<1>(data);
}

// Over a period of a periodic orbit the forcing's work equals what viscous damping and friction
// dissipate: int cos(psi) x' dt = int c x'^2 dt + F_k int |x'| dt, and on the half period from the
// upper to the lower turning point int |x'| dt = 2X. Integrated by Simpson's rule on the exact flow.
TEST(DampedDenHartogOrbit, BalancesTheForcingsWorkWithViscousAndFrictionLosses) {
  for (const auto& [r, beta, c] : {std::tuple{0.8, 0.2, 0.1}, std::tuple{1.5, 0.25, 0.3}, std::tuple{2.5, 0.1, 0.05}}) {
    const LinearOscillator<1> model = DampedDenHartog(c);
    const BasicOrbit<LinearOscillator<1>> orbit = DampedOrbit(model, r, beta);
    ASSERT_GT(SmallestMargin(AdmissibilityMargins(model, orbit)).value, 0.0) << "r = " << r;
    const double half = orbit.durations[0];
    constexpr int kIntervals = 4000;  // even, for Simpson's rule
    double work = 0.0, viscous = 0.0, travel = 0.0;
    for (int i = 0; i <= kIntervals; ++i) {
      const double t = half * i / kIntervals;
      const double weight = (i == 0 || i == kIntervals ? 1.0 : i % 2 == 1 ? 4.0 : 2.0) * half / (3.0 * kIntervals);
      const auto x = model.Flow(Mode::kSlipNegative, orbit.start, orbit.phi, t, orbit.parameters);
      work += weight * std::cos(orbit.phi + r * t) * x(1);
      viscous += weight * c * x(1) * x(1);
      travel += weight * std::abs(x(1));
    }
    const auto lower = model.Flow(Mode::kSlipNegative, orbit.start, orbit.phi, half, orbit.parameters);
    EXPECT_NEAR(lower(0), -orbit.start(0), 1e-10) << "antisymmetry, r = " << r;
    EXPECT_NEAR(travel, 2.0 * orbit.start(0), 1e-10) << "r = " << r;
    EXPECT_NEAR(work, viscous + beta * travel, 1e-10 * work) << "r = " << r;
    // The measure of friction's work, from the segments' ends, is the balance's remainder.
    EXPECT_NEAR(Measure(model, orbit).friction_work, 2.0 * (work - viscous), 1e-10 * work) << "r = " << r;
  }
}

// As the friction level vanishes the orbit becomes the linear viscous response,
// X = 1/sqrt((1 - r^2)^2 + (c r)^2), up to O(beta).
TEST(DampedDenHartogOrbit, TendsToTheViscousResponseAsFrictionVanishes) {
  for (const auto& [r, c] : {std::pair{0.8, 0.1}, std::pair{1.5, 0.3}, std::pair{2.5, 0.05}}) {
    const BasicOrbit<LinearOscillator<1>> orbit = DampedOrbit(DampedDenHartog(c), r, 1e-7);
    const double viscous = 1.0 / std::sqrt(std::pow(1.0 - r * r, 2) + std::pow(c * r, 2));
    EXPECT_NEAR(orbit.start(0), viscous, 1e-5 * viscous) << "r = " << r;
  }
}

}  // namespace
}  // namespace stickslip
