// The branch that leaves a period doubling: the §5.2 orbit type `slip- slip+ stick`, continued in
// omega below its re-entry into admissibility (SK at omega = 0.7395), loses stability through a
// multiplier -1 at omega = 0.7355. The period-2 branch that leaves there is checked against the
// exact simulator: its orbits repeat after two forcing periods and not after one.
#include "stickslip/branches/bifurcation_branches.hpp"

#include <gtest/gtest.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/io/run.hpp"
#include "stickslip/model/simulation.hpp"
#include "stickslip/orbits/stability.hpp"
#include "support/section6_symmetry_breaking.hpp"

namespace stickslip {
namespace {

// Downwards in omega from 0.737, on the admissible stretch of the §5.2 type. The guess (a point
// of that stretch, from a continuation past the type changes) is corrected at its omega.
OrbitContinuationSetup Section52AboveItsPeriodDoubling() {
  RunFile run;
  run.path = "(test)";
  run.output = "test";
  run.preset = "paper-5.2";
  run.set = {{"omega", 0.736975719636081}};
  run.guess = {{"x10", 0.8358908442122435}, {"x20", 1.5258036723705244}, {"v10", -1.0897400526017202},
               {"phi", 3.5580641421981336}, {"d1", 2.8655384579659624}, {"d2", 3.1896629391933726},
               {"d3", 2.470432677030011}};
  run.parameter = "omega";
  run.direction = -1;
  run.range_min = 0.72;
  run.range_max = 0.739;
  run.steps.ds = 5e-4;
  run.steps.ds_max = 2e-3;
  run.steps.max_points = 200;
  return MakeSetup(run, "results");
}

SpecialPoint PeriodDoubling(const OrbitBranch& branch) {
  for (const SpecialPoint& s : branch.branch.special_points) {
    if (s.type == "PD" && s.located) return s;
  }
  throw std::runtime_error("no located PD: " + branch.branch.end_message);
}

// The state of the exact simulation from the orbit's start at time t.
State At(const Orbit& orbit, double t) {
  SimulationOptions options;
  options.duration = t;
  const SimulationResult r = SimulateExact(orbit.parameters, orbit.InitialState(), orbit.phi, options);
  EXPECT_TRUE(r.Completed()) << r.message;
  return StateAt(r, t);
}

// ... after `periods` forcing periods.
State After(const Orbit& orbit, double periods) {
  return At(orbit, periods * 2.0 * 3.14159265358979323846 / orbit.parameters.omega);
}

TEST(BranchFromBifurcation, LeavesAPeriodDoublingOnPeriod2OrbitsConfirmedBySimulation) {
  const OrbitContinuationSetup setup = Section52AboveItsPeriodDoubling();
  const OrbitBranch period1 = ContinueOrbit(setup);
  const SpecialPoint pd = PeriodDoubling(period1);
  ASSERT_GT(pd.lambda, 0.72);
  ASSERT_LT(pd.lambda, 0.739);
  const BifurcationBranchStart start = BranchFromBifurcation(pd, setup);
  EXPECT_LT(start.singularity, 1e-7);
  EXPECT_EQ(start.at.signature.ToString(), "slip- slip+ stick slip- slip+ stick / period 2");
  // At the point the new type's orbit is the period-1 orbit traversed twice: a multiplier -1 there.
  const Stability at = StabilityOf(start.at);
  EXPECT_NEAR(std::abs(at.multipliers[0]), 1.0, 1e-6);

  OrbitContinuationSetup follow = start.setup;
  follow.options.max_points = 15;
  const OrbitBranch period2 = ContinueOrbit(follow);
  ASSERT_EQ(period2.orbits.size(), 15u) << period2.branch.end_message;
  for (const Orbit& orbit : {period2.orbits[5], period2.orbits.back()}) {
    EXPECT_NEAR(std::abs(orbit.parameters.omega - pd.lambda), 0.0, 0.01);
    // Two forcing periods bring the exact simulation back to the start, one does not: a
    // period-2 motion, not the period-1 orbit traversed twice.
    EXPECT_LT((After(orbit, 2.0) - orbit.InitialState()).cwiseAbs().maxCoeff(), 1e-8);
    EXPECT_GT((After(orbit, 1.0) - orbit.InitialState()).cwiseAbs().maxCoeff(), 1e-4);
    // A supercritical doubling: the period-2 orbits lie where the period-1 orbit has lost
    // stability, and are stable themselves.
    EXPECT_GT(orbit.parameters.omega, pd.lambda);
    EXPECT_TRUE(StabilityOf(orbit).stable);
  }
  // Seen from the other side (-1), the same orbits shifted by one period: its first orbit starts
  // where the +1 side's first orbit is at its fourth segment (the stop that starts the second
  // traversal), to second order in their departure from the point.
  OrbitContinuationSetup other = start.setup;
  other.options.start_direction = -start.setup.options.start_direction;
  other.options.max_points = 1;
  const Orbit shifted = ContinueOrbit(other).orbits.front();
  const Orbit& first = period2.orbits.front();
  const double second_traversal = first.durations[0] + first.durations[1] + first.durations[2];
  const double departure = (At(first, second_traversal) - first.InitialState()).cwiseAbs().maxCoeff();
  EXPECT_GT(departure, 1e-4);
  EXPECT_LT((At(first, second_traversal) - shifted.InitialState()).cwiseAbs().maxCoeff(), departure * departure);
}


TEST(BranchFromBifurcation, LeavesASymmetryBreakingOnOrbitsWithoutTheSymmetry) {
  const OrbitContinuationSetup setup = Section6AboveItsSymmetryBreaking();
  const OrbitBranch antisymmetric = ContinueOrbit(setup);
  const SpecialPoint* sb = nullptr;
  for (const SpecialPoint& s : antisymmetric.branch.special_points) {
    if (s.type == "SB" && s.located) sb = &s;
  }
  ASSERT_NE(sb, nullptr) << antisymmetric.branch.end_message;
  const BifurcationBranchStart start = BranchFromBifurcation(*sb, setup);
  EXPECT_LT(start.singularity, 1e-7);
  EXPECT_EQ(start.at.signature.ToString(), "slip- stick slip- slip+ stick slip+");
  std::vector<Orbit> first;  // of each side
  for (const int side : {1, -1}) {
    OrbitContinuationSetup follow = start.setup;
    follow.options.start_direction *= side;
    follow.options.max_points = 12;
    const OrbitBranch broken = ContinueOrbit(follow);
    ASSERT_EQ(broken.orbits.size(), 12u) << broken.branch.end_message;
    double asymmetry = 0.0;
    for (const Orbit& o : broken.orbits) {
      // The closed-form flows (the orbit is no motion: no simulator follows it) close the orbit
      // after a whole period, and its second half is not the mirror image of its first: the
      // asymmetry grows away from the point.
      const std::vector<State> states = o.SegmentStates();
      EXPECT_LT((states.back() - o.InitialState()).cwiseAbs().maxCoeff(), 1e-10);
      const double a = (states[3] + o.InitialState()).cwiseAbs().maxCoeff();
      EXPECT_GT(a, asymmetry);
      asymmetry = a;
    }
    EXPECT_GT(asymmetry, 0.1);
    first.push_back(broken.orbits.front());
  }
  // The two sides are mirror images: one side's first orbit starts where the other's, mirrored,
  // is at its second half's first stop, to second order in their departure from the point (the
  // first points lie on planes through the point, which the mirror maps only to first order).
  const State mirrored = -first[0].SegmentStates()[3];
  const double departure = (first[0].SegmentStates()[3] + first[0].InitialState()).cwiseAbs().maxCoeff();
  EXPECT_LT((mirrored - first[1].InitialState()).cwiseAbs().maxCoeff(), departure * departure);
}

TEST(BranchFromBifurcation, RefusesAPointThatIsNoBranchPointOrPeriodDoubling) {
  const OrbitContinuationSetup setup = Section52AboveItsPeriodDoubling();
  SpecialPoint fold;
  fold.type = "LP";
  EXPECT_THROW(BranchFromBifurcation(fold, setup), InvalidInput);
  SpecialPoint pd;
  pd.type = "PD";
  EXPECT_THROW(BranchFromBifurcation(pd, setup, 0), InvalidInput);
}

}  // namespace
}  // namespace stickslip
