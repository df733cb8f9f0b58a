// The margin = 0 condition of a type boundary: its exact derivatives against central differences
// of its own residuals (in the orbit variables and in the extremum time tau), its residuals at the
// interior minimum against the margins' root finder, and the conditions it refuses.
#include "stickslip/branches/margin_condition.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <variant>

#include <Eigen/SVD>
#include <gtest/gtest.h>

#include "stickslip/branches/orbit_continuation.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/io/run.hpp"
#include "stickslip/orbits/margin_gradients.hpp"
#include "support/problem_at.hpp"
#include "support/random_orbits.hpp"
#include "support/restart_in_omega.hpp"
#include "support/solved_presets.hpp"

namespace stickslip {
namespace {

namespace ov = orbit_variables;

struct Residual {
  Eigen::VectorXd value;
  Eigen::MatrixXd d_variables;
  Eigen::MatrixXd d_extra;
};
Residual Evaluate(const MarginCondition& c, const Orbit& orbit, const Eigen::VectorXd& extra) {
  Residual r;
  c.Evaluate(ProblemAt(orbit), ov::Pack(orbit), extra, &r.value, &r.d_variables, &r.d_extra);
  return r;
}

// The condition on `margin` made at `orbit`.
MarginCondition ConditionAt(const Orbit& orbit, std::string_view margin) {
  return MarginCondition(ProblemAt(orbit), ov::Pack(orbit), margin);
}

// Checks the condition's derivatives at (orbit, extra) against central differences of its
// residuals, in every orbit variable and every extra unknown.
void ExpectDerivativesMatchDifferences(const MarginCondition& c, const Orbit& orbit, const Eigen::VectorXd& extra) {
  const Residual r = Evaluate(c, orbit, extra);
  const Eigen::VectorXd v = ov::Pack(orbit);
  ASSERT_EQ(r.d_variables.rows(), c.EquationCount());
  ASSERT_EQ(r.d_variables.cols(), v.size());
  ASSERT_EQ(r.d_extra.cols(), c.ExtraUnknownCount());
  auto expect_near = [&](const Eigen::VectorXd& exact, const Eigen::VectorXd& fd, const std::string& what) {
    for (int k = 0; k < exact.size(); ++k) {
      EXPECT_NEAR(exact(k), fd(k), 1e-6 * std::max(1.0, std::abs(fd(k))))
          << c.Name() << " residual " << k << " d/d" << what << " on " << orbit.signature.ToString();
    }
  };
  for (int index = 0; index < v.size(); ++index) {
    const double h = 1e-6 * std::max(1.0, std::abs(v(index)));
    Eigen::VectorXd plus = v, minus = v;
    plus(index) += h;
    minus(index) -= h;
    const Eigen::VectorXd fd = (Evaluate(c, ov::Unpack(orbit.signature, plus), extra).value -
                                Evaluate(c, ov::Unpack(orbit.signature, minus), extra).value) / (2 * h);
    expect_near(r.d_variables.col(index), fd, ov::Name(orbit.signature.size(), index));
  }
  for (int k = 0; k < extra.size(); ++k) {
    const double h = 1e-6 * std::max(1.0, std::abs(extra(k)));
    Eigen::VectorXd plus = extra, minus = extra;
    plus(k) += h;
    minus(k) -= h;
    const Eigen::VectorXd fd = (Evaluate(c, orbit, plus).value - Evaluate(c, orbit, minus).value) / (2 * h);
    expect_near(r.d_extra.col(k), fd, "tau");
  }
}

// Every margin of `orbit` the condition accepts, checked; returns what was checked ("reversal",
// "velocity (interior)", ...).
std::set<std::string> ExpectEveryConditionMatchesDifferences(const Orbit& orbit) {
  std::set<std::string> checked;
  for (const Margin& m : AdmissibilityMargins(orbit)) {
    if (!std::isfinite(m.value)) continue;
    const bool slip_duration = m.kind == MarginKind::kDuration && orbit.signature.segments()[m.segment] != Mode::kStick;
    if (slip_duration || m.kind == MarginKind::kFrictionLevel) continue;  // refused (below)
    // A random orbit's stick constraint need not be zero at the exit; with exit-slope <= 0 the
    // condition refuses its interior minimum as if it were (below).
    std::optional<MarginCondition> made;
    try {
      made.emplace(ProblemAt(orbit), ov::Pack(orbit), m.Name());
    } catch (const InvalidInput& e) {
      if (std::string(e.what()).find("no maximum separates it from the exit") != std::string::npos) continue;
      throw;
    }
    const MarginCondition& c = *made;
    SCOPED_TRACE(c.Name());
    const Eigen::VectorXd tau_star = c.ExtraUnknowns(ProblemAt(orbit), ov::Pack(orbit));
    if (c.Interior()) {
      // At the root finder's minimum the residuals are the margin and a zero slope ...
      const Residual at_minimum = Evaluate(c, orbit, tau_star);
      EXPECT_NEAR(at_minimum.value(0), m.value, 1e-12 * std::max(1.0, std::abs(m.value)));
      EXPECT_NEAR(at_minimum.value(1), 0.0, 1e-8);
      EXPECT_GT(at_minimum.d_extra(1, 0), 0.0);  // f_tau_tau > 0 at a minimum
      // ... and the derivatives hold at any time, not only there.
      ExpectDerivativesMatchDifferences(c, orbit, tau_star);
      ExpectDerivativesMatchDifferences(c, orbit, tau_star * 0.8);
    } else {
      EXPECT_NEAR(Evaluate(c, orbit, tau_star).value(0), m.value, 1e-12 * std::max(1.0, std::abs(m.value)));
      ExpectDerivativesMatchDifferences(c, orbit, tau_star);
    }
    checked.insert(std::string(m.base) + (c.Interior() ? " (interior)" : ""));
  }
  return checked;
}

TEST(MarginCondition, DerivativesMatchCentralDifferencesOfItsResiduals) {
  std::set<std::string> checked;
  for (const char* name : {"paper-4.1", "paper-5.1", "paper-5.2", "paper-6"}) {
    SCOPED_TRACE(name);
    checked.merge(ExpectEveryConditionMatchesDifferences(SolvedPreset(name)));
  }
  // Random orbits (the residuals need no periodicity) with every end kind and interior minima.
  for (const RandomOrbit& r : RandomOrbitsOfEveryEndKind(4)) {
    SCOPED_TRACE(r.label);
    checked.merge(ExpectEveryConditionMatchesDifferences(r.orbit));
  }
  for (const char* kind : {"velocity (interior)", "G (interior)", "G1 (interior)", "reversal", "stick-entry",
                           "abnormal-stop", "stop-slope", "exit-slope", "duration", "G", "G1"}) {
    EXPECT_TRUE(checked.count(kind)) << kind;
  }
}

// The message of the InvalidInput `make` throws, or "" if it throws none.
template <typename Make>
std::string Refusal(Make&& make) {
  try {
    make();
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.field(), "condition");
    return e.what();
  }
  return "";
}

TEST(MarginCondition, RefusesMarginsWhoseZeroIsNoRegularCurve) {
  const Orbit nonsticking = SolvedPreset("paper-4.1");  // slip- / antisymmetric
  // A slip's duration: pointed to the margin of the end before it (the mirror's reversal).
  EXPECT_EQ(Refusal([&] { ConditionAt(nonsticking, "duration:1"); }),
            "condition = margin:duration:1 is invalid: valid range a margin whose zero is a regular curve: not a "
            "slip's duration (at zero length its end condition x2' = 0 holds identically); a slip shrinks to nothing "
            "only where the acceleration at its start does, at the zero of the margin of the end before it: use "
            "margin:reversal:1");
  EXPECT_NE(Refusal([&] { ConditionAt(nonsticking, "sliding-friction"); }).find("u_s = 0 ends the physical family"),
            std::string::npos);
  EXPECT_NE(Refusal([&] { ConditionAt(nonsticking, "G:1"); })
                .find("valid range a margin of slip- / antisymmetric: margin:duration:1, margin:velocity:1"),
            std::string::npos);
  // The §4.1 slip has no interior minimum of its velocity at the paper's data.
  ASSERT_TRUE(std::isinf(AdmissibilityMargins(nonsticking)[1].value));
  EXPECT_NE(Refusal([&] { ConditionAt(nonsticking, "velocity:1"); }).find("no interior minimum"),
            std::string::npos);
  // §5.1 (slip- slip+ stick slip+): the slip after the stick is pointed to the stick's exit slope.
  EXPECT_NE(Refusal([&] { ConditionAt(SolvedPreset("paper-5.1"), "duration:4"); }).find("use margin:exit-slope:3"),
            std::string::npos);
  // A stick's duration is a boundary (T0).
  EXPECT_EQ(Refusal([&] { ConditionAt(SolvedPreset("paper-5.1"), "duration:3"); }), "");
}

// The setup a run file restarting at branch:label of results/<trace> in omega makes.
OrbitContinuationSetup TraceRestart(const char* trace, const char* branch, const char* label) {
  return MakeSetup(RestartInOmega(branch, label), std::filesystem::path(STICKSLIP_SOURCE_DIR) / "results" / trace);
}

// Assembled here from the periodicity equations (omega and u_r free) and the margin's value and
// slope at its interior minimum tau (MarginGradientAt), not through MarginCondition: the
// Jacobian of the system that would continue `margin` = 0 as an interior minimum from the trace's
// point, in (unknowns, tau). Returns its smallest singular value over its largest.
double RelativeSmallestSingularValue(const char* trace, const char* branch, const char* label, const char* margin) {
  OrbitContinuationSetup setup = TraceRestart(trace, branch, label);
  setup.unknowns.release.emplace_back("u_r");
  setup.unknowns.condition_equations = 1;  // f(tau) = 0 and f_tau(tau) = 0 in one unknown more, tau
  const OrbitContinuationProblem problem = MakeOrbitContinuation(setup);
  const Orbit& orbit = setup.start;
  Margin m;
  for (const Margin& candidate : AdmissibilityMargins(orbit)) {
    if (candidate.Name() == margin) m = candidate;
  }
  EXPECT_EQ(m.Name(), margin);
  double t0 = 0.0;
  for (int k = 0; k < m.segment; ++k) t0 += orbit.durations[k];
  const MarginGradient g = MarginGradientAt(orbit, m, m.t - t0);
  Eigen::VectorXd f;
  JacobianMatrix j;
  problem.system->Evaluate(problem.start, &f, &j);
  const Eigen::MatrixXd& periodicity = std::get<Eigen::MatrixXd>(j);
  Eigen::MatrixXd rows(2, g.d_value.size());
  rows << g.d_value, g.d_slope;
  Eigen::MatrixXd augmented = Eigen::MatrixXd::Zero(periodicity.rows() + 2, periodicity.cols() + 1);
  augmented.topLeftCorner(periodicity.rows(), periodicity.cols()) = periodicity;
  augmented.bottomLeftCorner(2, periodicity.cols()) = problem.system->ToUnknowns(rows);
  augmented.bottomRightCorner(2, 1) << g.slope, g.curvature;
  const Eigen::VectorXd s = Eigen::JacobiSVD<Eigen::MatrixXd>(augmented).singularValues();
  std::printf("%s at %s/%s:%s: tau = %.10g of d = %.10g, singular values %.3e .. %.3e (%.1e)\n", margin, trace, branch,
              label, m.t - t0, orbit.durations[m.segment], s(s.size() - 1), s(0), s(s.size() - 1) / s(0));
  return s(s.size() - 1) / s(0);
}

TEST(MarginCondition, RefusesAnInteriorMinimumOfTheExitConstraintThatIsTheStickExit) {
  // The §5.1 trace passes the tangential exit of its stick (exit-slope:3 = 0: branch-2:GR2,
  // branch-5:GR4) and, on the branch after it, locates G:3 = 0 at the same point (branch-3:GR2,
  // branch-6:GR2): the interior minimum of G born at the exit, 9e-7 and 3e-7 before it, with
  // exit-slope:3 = -1.3e-6 and -4.6e-8. The system continuing G:3 as an interior minimum there has
  // a Jacobian of deficient rank (the row of G(tau) is the end condition's at tau = d3: smallest
  // singular value ~ |G''| |d3 - tau|), independent of MarginCondition's verdict ...
  for (const char* branch : {"branch-3", "branch-6"}) {
    SCOPED_TRACE(branch);
    EXPECT_LT(RelativeSmallestSingularValue("paper-5.1-omega-trace", branch, "GR2", "G:3"), 1e-7);
    // ... and refused, pointed to the regular condition of the same boundary.
    const OrbitContinuationSetup at = TraceRestart("paper-5.1-omega-trace", branch, "GR2");
    const std::string refusal = Refusal([&] { ConditionAt(at.start, "G:3"); });
    EXPECT_NE(refusal.find("no maximum separates it from the exit"), std::string::npos) << refusal;
    EXPECT_NE(refusal.find("use margin:exit-slope:3"), std::string::npos) << refusal;
  }
  // A grazing of G inside the §6 stick, apart from its exit (exit-slope:2 = 10.8 there): regular,
  // and accepted.
  EXPECT_GT(RelativeSmallestSingularValue("paper-6-omega-trace", "branch-2", "GR4", "G:2"), 1e-4);
  EXPECT_EQ(Refusal([&] { ConditionAt(TraceRestart("paper-6-omega-trace", "branch-2", "GR4").start, "G:2"); }), "");
}

}  // namespace
}  // namespace stickslip
