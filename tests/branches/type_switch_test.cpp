// Switching to the adjacent orbit type at the located type changes of the paper's branches
// (continuation-scripts/). Where a switch is confirmed: the start on the new type is the located
// orbit (state, phase, period and the whole motion to 1e-10), the orbit past the boundary goes
// through the new signature in the exact and the Odeint simulators with the new segment short,
// the located parameter does not depend on the step size, and the new branch goes on. Where none
// is: the exact simulator, nudged past the boundary, shows why (the new segment is long). Where the
// margin has no adjacent type: the branch folds there.
#include "stickslip/branches/type_switch.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <map>

#include "stickslip/invalid_input.hpp"
#include "stickslip/io/run.hpp"
#include "stickslip/model/simulation.hpp"
#include "stickslip/orbits/orbit_solver.hpp"
#include "stickslip/orbits/verification.hpp"

namespace stickslip {
namespace {

namespace fs = std::filesystem;

struct Located {
  OrbitContinuationSetup setup;
  OrbitBranch branch;
  SpecialPoint special;
  LocatedTypeChange change;
};

// The branch of `setup`, and its special point where `margin` changed sign.
Located Locate(const OrbitContinuationSetup& setup, const std::string& margin) {
  OrbitBranch branch = ContinueOrbit(setup);
  for (const SpecialPoint& s : branch.branch.special_points) {
    if (s.test_function == "margin:" + margin) {
      LocatedTypeChange change = TypeChangeAt(branch, s, setup);
      return {setup, std::move(branch), s, std::move(change)};
    }
  }
  throw std::runtime_error(margin + " is not located on the branch of " + setup.start.signature.ToString() + ": " +
                           branch.branch.end_message);
}

// The run file's branch, and its special point where `margin` changed sign.
Located Locate(const std::string& run, const std::string& margin, double ds_scale = 1.0) {
  const fs::path root(STICKSLIP_SOURCE_DIR);
  OrbitContinuationSetup setup =
      MakeSetup(ReadRunFile(root / "continuation-scripts" / (run + ".toml")), root / "results");
  setup.options.step.ds *= ds_scale;
  setup.options.step.ds_max *= ds_scale;
  return Locate(setup, margin);
}

Margin Named(const Orbit& o, const std::string& name) {
  for (const Margin& m : AdmissibilityMargins(o)) {
    if (m.Name() == name) return m;
  }
  throw std::runtime_error(name);
}

OrbitBranch ContinueNewType(const Located& at, const TypeSwitch& sw, int direction, int points,
                            bool from_past = false) {
  OrbitContinuationSetup setup = at.setup;
  setup.start = from_past ? *sw.past : *sw.start;
  setup.unknowns = sw.unknowns;
  setup.options.direction = direction;
  setup.options.max_points = points;
  return ContinueOrbit(setup);
}

struct ConfirmedCase {
  const char* run;
  const char* margin;
  double lambda;  // as results/ has it (10 digits)
  const char* adjacent;
};

class ConfirmedSwitch : public ::testing::TestWithParam<ConfirmedCase> {};

TEST_P(ConfirmedSwitch, TheNewTypeStartsOnTheLocatedOrbitAndTheSimulatorFollowsItPastTheBoundary) {
  const ConfirmedCase& c = GetParam();
  const Located at = Locate(c.run, c.margin);
  EXPECT_NEAR(at.special.lambda, c.lambda, 1e-10);
  const TypeSwitch sw = SwitchAt(at.change);
  ASSERT_EQ(sw.status, TypeSwitchStatus::kConfirmed) << sw.reason;
  EXPECT_EQ(sw.adjacent->edit.signature.ToString(), c.adjacent);
  EXPECT_STREQ(sw.adjacent->bifurcation, "crossing-sliding");
  EXPECT_TRUE(sw.persists) << "the stick grows on the far side of the boundary";
  EXPECT_EQ(sw.direction, at.change.past);

  // Continuous across the switch: the same state, phase and period, and the same motion over a period.
  const Orbit& located = at.change.orbit;
  const Orbit& start = *sw.start;
  EXPECT_LE(std::abs(start.x10 - located.x10), 1e-10);
  EXPECT_LE(std::abs(start.x20 - located.x20), 1e-10);
  EXPECT_LE(std::abs(start.v10 - located.v10), 1e-10);
  EXPECT_LE(std::abs(start.phi - located.phi), 1e-10);
  EXPECT_LE(std::abs(start.Period() - located.Period()), 1e-10);
  EXPECT_LE(std::abs(start.durations[sw.adjacent->new_segment]), 1e-10);
  const std::vector<State> a = start.Sample(101);
  const std::vector<State> b = located.Sample(101);
  for (std::size_t k = 0; k < a.size(); ++k) EXPECT_LE((a[k] - b[k]).lpNorm<Eigen::Infinity>(), 1e-10) << k;

  // Past the boundary: both simulators go through the new signature, the new stick is short.
  const Orbit& past = *sw.past;
  const ParameterId id = *ParameterFromString(at.change.parameter);
  EXPECT_GT((past.parameters[id] - c.lambda) * at.change.past, 0.0);
  const double d = past.durations[sw.adjacent->new_segment];
  EXPECT_GT(d, 0.0);
  EXPECT_LT(d, 1e-3 * past.Period());
  const Verification v = VerifyOrbit(past);
  EXPECT_TRUE(v.exact.sequence_matches && v.exact.periodicity_mismatch <= 1e-9) << v.Report();
  EXPECT_TRUE(v.Passed()) << v.Report();

  // The located parameter and the start do not depend on the step size.
  const Located finer = Locate(c.run, c.margin, 0.37);
  EXPECT_NEAR(finer.special.lambda, at.special.lambda, 1e-9);
  const TypeSwitch again = SwitchAt(finer.change);
  ASSERT_EQ(again.status, TypeSwitchStatus::kConfirmed) << again.reason;
  EXPECT_LE((orbit_variables::Pack(*again.start) - orbit_variables::Pack(start)).lpNorm<Eigen::Infinity>(), 1e-9);

  // The new branch goes on: admissible, the stick growing away from the boundary.
  const OrbitBranch next = ContinueNewType(at, sw, sw.direction, 8);
  ASSERT_EQ(next.orbits.size(), 8u) << next.branch.end_message;
  for (std::size_t k = 1; k < next.orbits.size(); ++k) {
    const Orbit& o = next.orbits[k];
    EXPECT_GT((o.parameters[id] - c.lambda) * sw.direction, 0.0);
    EXPECT_GT(o.durations[sw.adjacent->new_segment], next.orbits[k - 1].durations[sw.adjacent->new_segment]);
    EXPECT_GT(SmallestMargin(AdmissibilityMargins(o)).value, 0.0) << k;
  }
  const Verification later = VerifyOrbit(next.orbits.back());
  EXPECT_TRUE(later.Passed()) << later.Report();
}

INSTANTIATE_TEST_SUITE_P(
    PaperBranches, ConfirmedSwitch,
    ::testing::Values(
        // The case: section 4.1 downwards, the stops turn into sticks.
        ConfirmedCase{"paper-4.1-omega-down", "reversal:1", 0.5999775071, "slip- stick / antisymmetric"},
        ConfirmedCase{"paper-4.1-u_r-up", "reversal:1", 0.2996721467, "slip- stick / antisymmetric"},
        ConfirmedCase{"paper-4.2-omega-down", "reversal:2", 0.56996423, "slip- slip- stick / antisymmetric"},
        ConfirmedCase{"paper-4.2-u_s-up", "reversal:2", 0.1745455071, "slip- slip- stick / antisymmetric"},
        ConfirmedCase{"paper-5.2-omega-down", "reversal:1", 0.6039832496, "slip- stick slip+ stick"}),
    [](const auto& test) {
      std::string name = std::string(test.param.run) + "_" + test.param.margin;
      for (char& ch : name) ch = std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
      return name;
    });

// The inverse: the section 4.1 sticking branch, followed back up, loses its stick where it was born
// (T0 at the same omega), and the switch there returns to the nonsticking type and its orbit.
TEST(TypeSwitch, TheStickingBranchOfSection41ClosesBackOntoTheNonstickingOrbit) {
  const Located at = Locate("paper-4.1-omega-down", "reversal:1");
  const TypeSwitch sw = SwitchAt(at.change);
  ASSERT_EQ(sw.status, TypeSwitchStatus::kConfirmed) << sw.reason;
  const OrbitBranch down = ContinueNewType(at, sw, -1, 12);
  ASSERT_EQ(down.orbits.size(), 12u);
  OrbitContinuationSetup back = at.setup;
  back.start = down.orbits.back();
  back.unknowns = sw.unknowns;
  back.options.direction = +1;
  back.options.max_points = 100;
  const OrbitBranch up = ContinueOrbit(back);
  ASSERT_EQ(up.branch.end, BranchEnd::kTerminalEvent) << up.branch.end_message;
  // The type changes the branch ended at (an EP follows them): the stick's duration, the force at
  // its entry and G at its start reach zero together. The first two switch back; G's adding-sliding
  // candidate is ruled out (its new slip+ cannot stop soon).
  std::map<std::string, TypeSwitchStatus> statuses;
  for (const SpecialPoint& end : up.branch.special_points) {
    if (end.test_function.rfind("margin:", 0) != 0) continue;
    EXPECT_NEAR(end.lambda, at.special.lambda, 1e-9);
    const LocatedTypeChange change = TypeChangeAt(up, end, back);
    EXPECT_EQ(change.past, +1);
    const TypeSwitch inverse = SwitchAt(change);
    statuses[change.margin] = inverse.status;
    if (inverse.status != TypeSwitchStatus::kConfirmed) continue;
    EXPECT_EQ(inverse.adjacent->edit.signature.ToString(), "slip- / antisymmetric");
    EXPECT_TRUE(inverse.persists);
    EXPECT_LE(
        (orbit_variables::Pack(*inverse.start) - orbit_variables::Pack(at.change.orbit)).lpNorm<Eigen::Infinity>(),
        1e-9);
    EXPECT_TRUE(VerifyOrbit(*inverse.past).Passed());
  }
  EXPECT_EQ(statuses, (std::map<std::string, TypeSwitchStatus>{{"G:2", TypeSwitchStatus::kNotConfirmed},
                                                               {"duration:2", TypeSwitchStatus::kConfirmed},
                                                               {"stick-entry:1", TypeSwitchStatus::kConfirmed}}));
}

struct UnconfirmedCase {
  const char* run;
  const char* margin;
  const char* blocking;  // the margin of the start that rules the candidate out
};

class UnconfirmedSwitch : public ::testing::TestWithParam<UnconfirmedCase> {};

// With u_r > u_s these changes of type have no adjacent orbit nearby: the new segment is long. The
// exact simulator, started on the located orbit with the parameter nudged past the boundary, shows
// it: the segment of the new mode that begins at the event lasts more than 1% of the period.
// The exact simulator, started on the located type's orbit just past the boundary (not a motion:
// its margin is negative there), makes the new segment of the first candidate long: more than 1%
// of the period.
void ExpectTheNewSegmentIsLongPastTheBoundary(const Located& at, const std::string& margin) {
  const Orbit& o = at.change.orbit;
  const Margin located = Named(o, margin);
  const AdjacentType candidate =
      AdjacentTypes(margin.substr(0, margin.find(':')), located.segment, o.signature, false).front();
  const Mode new_mode = candidate.edit.signature.segments()[candidate.new_segment];
  Orbit guess = o;
  const ParameterId id = *ParameterFromString(at.change.parameter);
  guess.parameters[id] += at.change.past * 1e-6 * (1 + std::abs(guess.parameters[id]));
  const OrbitSolution beyond =
      SolveOrbit(guess, FreeIndices(o.signature, at.setup.unknowns), at.setup.unknowns.tie_static_friction);
  ASSERT_TRUE(beyond.summary.Converged());
  ASSERT_LT(Named(beyond.orbit, margin).value, 0.0) << "past the boundary";
  SimulationOptions options;
  options.duration = o.Period();
  const SimulationResult r =
      SimulateExact(beyond.orbit.parameters, beyond.orbit.InitialState(), beyond.orbit.phi, options);
  const Segment* next = nullptr;
  for (const Segment& s : r.segments) {
    // Past a grazing the constraint is violated on an interval ~ sqrt(nudge) wide: section 6's
    // slip+ begins 0.012 before the grazing time.
    if (s.mode == new_mode && std::abs(s.t_start - located.t) < 0.05) next = &s;
  }
  std::string modes;
  for (const Segment& s : r.segments) modes += fmt::format(" {}@{:.6f}", ToString(s.mode), s.t_start);
  ASSERT_NE(next, nullptr) << "no " << ToString(new_mode) << " begins at t = " << located.t << ":" << modes;
  EXPECT_GT(next->t_end - next->t_start, 1e-2 * o.Period()) << modes;
}

// With u_r > u_s these changes of type have no adjacent orbit nearby: the new segment is long.
TEST_P(UnconfirmedSwitch, TheSimulatorPastTheBoundaryShowsTheNewSegmentIsNotShort) {
  const UnconfirmedCase& c = GetParam();
  const Located at = Locate(c.run, c.margin);
  const TypeSwitch sw = SwitchAt(at.change);
  ASSERT_EQ(sw.status, TypeSwitchStatus::kNotConfirmed) << sw.reason;
  EXPECT_NE(sw.reason.find(std::string("margin ") + c.blocking), std::string::npos) << sw.reason;
  EXPECT_FALSE(sw.start.has_value());
  ExpectTheNewSegmentIsLongPastTheBoundary(at, c.margin);
}

INSTANTIATE_TEST_SUITE_P(
    PaperBranches, UnconfirmedSwitch,
    ::testing::Values(
        // The new stick at the first stop: the force moves into the band (exit-slope < 0), the mass stays.
        UnconfirmedCase{"paper-5.1-omega-down", "reversal:1", "exit-slope:2"},
        UnconfirmedCase{"paper-5.1-u_r-down", "reversal:1", "exit-slope:2"},
        // The new slip+ from the stick starts at the static level and accelerates: it cannot stop soon.
        UnconfirmedCase{"paper-5.2-omega-down", "G:3", "stop-slope:4"},
        UnconfirmedCase{"paper-5.2-u_r-up", "G:3", "stop-slope:4"},
        UnconfirmedCase{"paper-6-omega-up", "G:2", "stop-slope:3"}),
    [](const auto& test) {
      std::string name = std::string(test.param.run) + "_" + test.param.margin;
      for (char& ch : name) ch = std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
      return name;
    });

// Section 4.1's data continued in chi: the stops turn into sticks at chi = 0.30032 (confirmed), and
// on the sticking branch the force at the entry into the stick reaches the static level at
// chi = 0.32637 (where G also grazes zero at the stick's start). The stick still lasts 0.014 there, so
// no candidate is confirmed: the reversed slip+ is long.
TEST(TypeSwitch, AStickEntryAtTheStaticLevelOnTheSection41StickingBranchHasNoNearbyOrbit) {
  const fs::path root(STICKSLIP_SOURCE_DIR);
  OrbitContinuationSetup setup =
      MakeSetup(ReadRunFile(root / "continuation-scripts" / "paper-4.1-omega-up.toml"), root / "results");
  setup.parameter = "chi";
  setup.options.user_values.clear();
  setup.options.lambda_max = 0.5;
  const Located stops = Locate(setup, "reversal:1");
  EXPECT_NEAR(stops.special.lambda, 0.3003229572, 1e-10);
  const TypeSwitch first = SwitchAt(stops.change);
  ASSERT_EQ(first.status, TypeSwitchStatus::kConfirmed) << first.reason;

  OrbitContinuationSetup sticking = setup;
  sticking.start = *first.start;
  sticking.unknowns = first.unknowns;
  sticking.options.direction = first.direction;
  const Located at = Locate(sticking, "stick-entry:1");
  EXPECT_NEAR(at.special.lambda, 0.3263659421, 1e-9);
  EXPECT_EQ(at.change.past, 1);
  const TypeSwitch sw = SwitchAt(at.change);
  ASSERT_EQ(sw.status, TypeSwitchStatus::kNotConfirmed) << sw.reason;
  EXPECT_NE(sw.reason.find("margin stop-slope:2"), std::string::npos) << sw.reason;
  EXPECT_NE(sw.reason.find("segment 2 has not vanished"), std::string::npos) << sw.reason;
  ExpectTheNewSegmentIsLongPastTheBoundary(at, "stick-entry:1");
}

// Section 4.2 (u_r = u_s, a Filippov system): the stick born at the second stop (SK, omega =
// 0.56996) grows down to omega = 0.32111, where s grazes +eta u_r inside it. There the stick splits
// around a short slip- (adding-sliding): the new slip starts with x2'' = 0 and lasts a root of the
// parameter step, so it is found with its length given; both simulators confirm it, and the new
// branch goes on.
TEST(TypeSwitch, AtEqualFrictionLevelsAGrazingInsideTheStickAddsAShortSlip) {
  for (const double ds_scale : {1.0, 0.37}) {
    const Located stops = Locate("paper-4.2-omega-down", "reversal:2", ds_scale);
    const TypeSwitch first = SwitchAt(stops.change);
    ASSERT_EQ(first.status, TypeSwitchStatus::kConfirmed) << first.reason;
    OrbitContinuationSetup sticking = stops.setup;
    sticking.start = *first.start;
    sticking.unknowns = first.unknowns;
    sticking.options.direction = first.direction;
    const Located at = Locate(sticking, "G1:3");
    EXPECT_NEAR(at.special.lambda, 0.3211122863, 1e-9) << "ds x " << ds_scale;

    const TypeSwitch sw = SwitchAt(at.change);
    ASSERT_EQ(sw.status, TypeSwitchStatus::kConfirmed) << sw.reason;
    EXPECT_EQ(sw.adjacent->edit.signature.ToString(), "slip- slip- stick slip- stick / antisymmetric");
    EXPECT_STREQ(sw.adjacent->bifurcation, "adding-sliding");
    EXPECT_TRUE(sw.persists);
    EXPECT_EQ(sw.direction, -1);
    const Orbit& located = at.change.orbit;
    EXPECT_LE(OrbitDistance(*sw.start, located), 1e-10);
    const std::vector<State> a = sw.start->Sample(101);
    const std::vector<State> b = located.Sample(101);
    for (std::size_t k = 0; k < a.size(); ++k) EXPECT_LE((a[k] - b[k]).lpNorm<Eigen::Infinity>(), 1e-10) << k;
    const Margin g1 = Named(located, "G1:3");
    EXPECT_NEAR(sw.start->SegmentTimes()[3], g1.t, 1e-12) << "the new slip sits at the grazing time";

    const Orbit& past = *sw.past;
    EXPECT_LT(past.parameters.omega, at.special.lambda);
    EXPECT_GT(past.durations[3], 0.0);
    EXPECT_LT(past.durations[3], 1e-2 * past.Period());
    // Odeint, which sees only sign changes of x2' at its tolerances, merges the short slip into the
    // sticks around it: the exact simulator alone resolves it.
    const Verification v = VerifyOrbit(past);
    EXPECT_TRUE(v.exact.sequence_matches && v.exact.periodicity_mismatch <= 1e-9 &&
                v.exact.max_event_time_difference <= 1e-9)
        << v.Report();
    if (ds_scale != 1.0) continue;

    // At the grazing the new type's Jacobian is singular (the slip's length is a root of the step):
    // its branch starts from the orbit past the boundary.
    const OrbitBranch next = ContinueNewType(at, sw, sw.direction, 6, true);
    ASSERT_EQ(next.orbits.size(), 6u) << next.branch.end_message;
    for (std::size_t k = 1; k < next.orbits.size(); ++k) {
      EXPECT_LT(next.orbits[k].parameters.omega, at.special.lambda);
      EXPECT_GT(SmallestMargin(AdmissibilityMargins(next.orbits[k])).value, 0.0) << k;
    }
    const Verification later = VerifyOrbit(next.orbits.back());
    EXPECT_TRUE(later.Passed()) << later.Report();
  }
}

TEST(TypeSwitch, InvalidOptionsAndAMarginTheOrbitDoesNotHaveAreRefused) {
  const Located at = Locate("paper-4.1-omega-down", "reversal:1");
  TypeSwitchOptions options;
  options.nudge = 0.0;
  EXPECT_THROW(SwitchAt(at.change, options), InvalidInput);
  options = {};
  options.new_durations = {0.5};  // longer than max_new_duration
  EXPECT_THROW(SwitchAt(at.change, options), InvalidInput);
  LocatedTypeChange wrong = at.change;
  wrong.margin = "G:1";
  EXPECT_THROW(SwitchAt(wrong), InvalidInput);
  wrong = at.change;
  wrong.parameter = "x10";
  EXPECT_THROW(SwitchAt(wrong), InvalidInput);
}

// A tangential stop is a fold of the same type (LP at the same point); the family's end has nothing.
TEST(TypeSwitch, ATangentialEndOrTheFamilysEndHasNoAdjacentType) {
  const Located ns = Locate("paper-5.2-omega-up", "stop-slope:2");
  EXPECT_EQ(SwitchAt(ns.change).status, TypeSwitchStatus::kNoAdjacentType);
  bool fold = false;
  for (const SpecialPoint& s : ns.branch.branch.special_points) {
    fold = fold || (s.type == "LP" && std::abs(s.lambda - ns.special.lambda) < 1e-9);
  }
  EXPECT_TRUE(fold) << "the branch folds where the stop becomes tangential";
  EXPECT_EQ(SwitchAt(Locate("paper-6-omega-down", "exit-slope:2").change).status, TypeSwitchStatus::kNoAdjacentType);
  EXPECT_EQ(SwitchAt(Locate("paper-4.2-omega-up", "sliding-friction").change).status,
            TypeSwitchStatus::kNoAdjacentType);
}

}  // namespace
}  // namespace stickslip
