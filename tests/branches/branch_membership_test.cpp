// "Is this orbit on a branch already" (branches/branch_membership.hpp), against a trace of §4.1's
// data over omega in [0.56, 0.66] (the nonsticking orbit 'slip- / antisymmetric' both ways from the
// paper's omega = 0.6, the sticking orbit below its crossing-sliding at 0.59998): the orbits of the
// branches' points lie on their own branch; the orbit the exact simulator settles on between two
// points (FindOrbit: its own choice of origin, found by simulation, not by the branch) lies on the
// branch between those points; the same state at a shifted omega, a state moved off the branch and
// the same state under another type do not; a point's orbit from another origin (a stick exit, the
// mirrored half) is on its branch.
#include "stickslip/branches/branch_membership.hpp"

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "stickslip/analysis/orbit_finder.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/io/run.hpp"
#include "stickslip/orbits/orbit_origin.hpp"
#include "stickslip/orbits/signature_edits.hpp"

namespace stickslip {
namespace {

const TraceResult& Section41Trace() {
  static const TraceResult trace = [] {
    const std::filesystem::path root(STICKSLIP_SOURCE_DIR);
    OrbitContinuationSetup setup =
        MakeSetup(ReadRunFile(root / "continuation-scripts" / "paper-4.1-omega-trace.toml"), root / "results");
    setup.options.lambda_min = 0.56;
    setup.options.lambda_max = 0.66;
    return TraceOrbits(setup);
  }();
  return trace;
}

// The index among BranchesOf(trace) of the first branch of type `signature` reaching above `omega`.
int BranchOfTypeAbove(const std::string& signature, double omega) {
  const std::vector<const OrbitBranch*> branches = BranchesOf(Section41Trace());
  for (int b = 0; b < static_cast<int>(branches.size()); ++b) {
    const Orbit& last = branches[b]->orbits.back();
    if (last.signature.ToString() == signature && last.parameters.omega > omega) return b;
  }
  return -1;
}

TEST(BranchMembership, OrbitsAtABranchesPointsLieOnThatBranch) {
  const std::vector<const OrbitBranch*> branches = BranchesOf(Section41Trace());
  int tried = 0;
  for (int b = 0; b < static_cast<int>(branches.size()); ++b) {
    const int n = static_cast<int>(branches[b]->orbits.size());
    if (n < 3) continue;  // the stretch from 0.6 down to the crossing-sliding has no inner point
    for (const int i : {1, n / 2, n - 2}) {
      const BranchMembership m = FindOnBranches(branches[b]->orbits[i], branches);
      ++tried;
      ASSERT_TRUE(m.on_branch) << "branch " << b << " point " << i << ": " << m.message;
      EXPECT_EQ(m.branch, b) << m.message;
      EXPECT_TRUE(m.point == i || m.point == i - 1) << m.message;  // either interval ending at i
      EXPECT_LT(m.distance, 1e-9);
    }
  }
  EXPECT_GE(tried, 6);  // both types were tried
}

// The orbit the exact simulator settles on at omega halfway between points i and i + 1 of the
// nonsticking branch above 0.6, started from point i's state.
FindOrbitResult FoundBetween(const OrbitBranch& branch, int i) {
  const Orbit& near = branch.orbits[i];
  Parameters p = near.parameters;
  p.omega = 0.5 * (near.parameters.omega + branch.orbits[i + 1].parameters.omega);
  return FindOrbit(p, near.InitialState(), near.phi);
}

// The sticking orbit's points from another origin (a stick exit, and the mirrored half): the same
// motion, so on the same branch.
TEST(BranchMembership, AnOrbitFromAnotherOriginLiesOnTheSameBranch) {
  const std::vector<const OrbitBranch*> branches = BranchesOf(Section41Trace());
  int b = 0;
  while (b < static_cast<int>(branches.size()) &&
         branches[b]->orbits.front().signature.ToString() != "slip- stick / antisymmetric") {
    ++b;
  }
  ASSERT_LT(b, static_cast<int>(branches.size()));
  const Orbit& point = branches[b]->orbits[branches[b]->orbits.size() / 2];
  for (int j = 1; j < OriginCount(point.signature); ++j) {
    const Orbit rotated = WithOriginAt(point, j);
    const BranchMembership m = FindOnBranches(rotated, branches);
    EXPECT_TRUE(m.on_branch) << rotated.signature.ToString() << ": " << m.message;
    EXPECT_EQ(m.branch, b);
  }
}

TEST(BranchMembership, TheOrbitSimulationFindsBetweenTwoPointsLiesOnTheBranchThere) {
  const int b = BranchOfTypeAbove("slip- / antisymmetric", 0.62);
  ASSERT_GE(b, 0);
  const OrbitBranch& branch = *BranchesOf(Section41Trace())[b];
  for (const int i : {1, static_cast<int>(branch.orbits.size()) / 2}) {
    const FindOrbitResult found = FoundBetween(branch, i);
    ASSERT_TRUE(found.Found()) << found.message;
    const BranchMembership m = FindOnBranches(found.solution->orbit, BranchesOf(Section41Trace()));
    ASSERT_TRUE(m.on_branch) << m.message;
    EXPECT_EQ(m.branch, b);
    EXPECT_EQ(m.point, i);
    EXPECT_LT(m.distance, 1e-8);
  }
}

TEST(BranchMembership, NotAtAShiftedParameterNorOffTheBranchNorUnderAnotherType) {
  const int b = BranchOfTypeAbove("slip- / antisymmetric", 0.62);
  ASSERT_GE(b, 0);
  const OrbitBranch& branch = *BranchesOf(Section41Trace())[b];
  const FindOrbitResult found = FoundBetween(branch, static_cast<int>(branch.orbits.size()) / 2);
  ASSERT_TRUE(found.Found()) << found.message;
  const std::vector<const OrbitBranch*> branches = BranchesOf(Section41Trace());

  Orbit shifted = found.solution->orbit;
  shifted.parameters.omega += 2e-3;
  const BranchMembership at_shifted = FindOnBranches(shifted, branches);
  EXPECT_FALSE(at_shifted.on_branch) << at_shifted.message;
  EXPECT_GT(at_shifted.distance, 1e-5);

  Orbit moved = found.solution->orbit;
  moved.x10 += 1e-4;
  EXPECT_FALSE(FindOnBranches(moved, branches).on_branch);

  // The same state as the sticking type, which exists only below 0.59998: no branch of it here.
  const Orbit sticking = InsertSegment(found.solution->orbit, 1, Mode::kStick);
  ASSERT_EQ(sticking.signature.ToString(), "slip- stick / antisymmetric");
  const BranchMembership other_type = FindOnBranches(sticking, branches);
  EXPECT_FALSE(other_type.on_branch) << other_type.message;
}

TEST(BranchMembership, RefusesAToleranceOutOfRangeAndAnUnknownParameter) {
  const Orbit& orbit = BranchesOf(Section41Trace()).front()->orbits.front();
  BranchMembershipOptions options;
  options.tolerance = 0.0;
  EXPECT_THROW(FindOnBranches(orbit, {}, options), InvalidInput);
  options = {};
  options.parameter = "omgea";
  EXPECT_THROW(FindOnBranches(orbit, {}, options), InvalidInput);
}

}  // namespace
}  // namespace stickslip
