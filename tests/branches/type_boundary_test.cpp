// The crossing-sliding boundary of the §4.1 nonsticking orbit in the (omega, u_r) plane: every
// point of the curve is where one-parameter continuation in omega at that u_r locates its SK, and
// the orbit there, its zero-length stick removed, has its reversal margin zero.
#include "stickslip/branches/type_boundary.hpp"

#include <filesystem>

#include <gtest/gtest.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/io/run.hpp"
#include "stickslip/orbits/signature_edits.hpp"

namespace stickslip {
namespace {

namespace fs = std::filesystem;

// The run file's setup, with `set` added (the start's data).
OrbitContinuationSetup RunFileSetup(const std::string& run, const NamedValues& set = {}) {
  const fs::path root(STICKSLIP_SOURCE_DIR);
  RunFile file = ReadRunFile(root / "continuation-scripts" / (run + ".toml"));
  file.set.insert(file.set.end(), set.begin(), set.end());
  return MakeSetup(file, root / "results");
}

// The branch of `setup` and its located change of `margin`.
LocatedTypeChange Located(const OrbitContinuationSetup& setup, const std::string& margin) {
  const OrbitBranch branch = ContinueOrbit(setup);
  for (const SpecialPoint& s : branch.branch.special_points) {
    if (s.test_function == "margin:" + margin) return TypeChangeAt(branch, s, setup);
  }
  throw std::runtime_error(margin + " not located: " + branch.branch.end_message);
}

double MarginOf(const Orbit& orbit, const std::string& name) {
  for (const Margin& m : AdmissibilityMargins(orbit)) {
    if (m.Name() == name) return m.value;
  }
  throw std::runtime_error("no margin " + name);
}

TEST(TypeBoundary, CrossingSlidingCurveIsWhereEachOmegaBranchLocatesItsSK) {
  const OrbitContinuationSetup down = RunFileSetup("paper-4.1-omega-down");
  const LocatedTypeChange sk = Located(down, "reversal:1");
  const TypeBoundarySetup boundary = TypeBoundary(sk, down, "u_r");
  EXPECT_EQ(boundary.setup.start.signature.ToString(), "slip- stick / antisymmetric");
  EXPECT_EQ(boundary.held, "d2");
  for (const int direction : {1, -1}) {
    OrbitContinuationSetup follow = boundary.setup;
    follow.options.direction = direction;
    follow.options.max_points = 12;
    follow.options.step.ds = 0.01;
    follow.options.step.ds_max = 0.02;
    const OrbitBranch curve = ContinueOrbit(follow);
    ASSERT_GE(curve.orbits.size(), 8u) << curve.branch.end_message;
    for (const Orbit& o : curve.orbits) {
      EXPECT_EQ(o.durations[boundary.stick], 0.0);
      const Orbit nonsticking = RemoveSegment(o, boundary.stick, false);
      EXPECT_NEAR(MarginOf(nonsticking, "reversal:1"), 0.0, 1e-9);
    }
    // The curve moves in both parameters.
    const Orbit& last = curve.orbits.back();
    EXPECT_GT(std::abs(last.parameters.u_r - sk.orbit.parameters.u_r), 1e-3);
    EXPECT_GT(std::abs(last.parameters.omega - sk.orbit.parameters.omega), 1e-4);
    // At the last point's u_r, the omega branch of the nonsticking type, from just above the
    // curve downwards, locates its SK at the curve's omega.
    const LocatedTypeChange again = Located(
        RunFileSetup("paper-4.1-omega-down", {{"u_r", last.parameters.u_r}, {"omega", last.parameters.omega + 0.003}}),
        "reversal:1");
    EXPECT_NEAR(again.orbit.parameters.omega, last.parameters.omega, 1e-8) << "u_r = " << last.parameters.u_r;
  }
}

TEST(TypeBoundary, RefusesMarginsItGivesNoBoundaryOfAndBadSecondParameters) {
  const OrbitContinuationSetup down = RunFileSetup("paper-4.1-omega-down");
  LocatedTypeChange sk = Located(down, "reversal:1");
  EXPECT_THROW(TypeBoundary(sk, down, "omega"), InvalidInput);  // the continued one
  EXPECT_THROW(TypeBoundary(sk, down, "x10"), InvalidInput);
  EXPECT_THROW(TypeBoundary(sk, down, "nonsense"), InvalidInput);
  sk.margin = "velocity:1";
  EXPECT_THROW(TypeBoundary(sk, down, "u_r"), InvalidInput);
}

}  // namespace
}  // namespace stickslip
