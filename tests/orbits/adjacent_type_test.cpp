// The adjacent types of every margin kind (lib/README.md's switching table), and their start orbits:
// the same motion as the located orbit, sampled over a whole period, with the new segment of zero
// length where the margin says.
#include "stickslip/orbits/adjacent_type.hpp"

#include <gtest/gtest.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/orbits/segment_walk.hpp"
#include "support/den_hartog_orbit.hpp"
#include "support/solved_presets.hpp"

namespace stickslip {
namespace {

std::vector<std::string> Signatures(std::string_view base, int segment, const char* signature,
                                    bool equal_friction = false) {
  std::vector<std::string> out;
  for (const AdjacentType& a : AdjacentTypes(base, segment, Signature::Parse(signature), equal_friction)) {
    out.push_back(a.edit.signature.ToString());
  }
  return out;
}

using Names = std::vector<std::string>;

TEST(AdjacentTypes, AReversalWhoseForceReachesTheStaticLevelGetsAStickAtItsStop) {
  EXPECT_EQ(Signatures("reversal", 0, "slip- / antisymmetric"), Names{"slip- stick / antisymmetric"});
  EXPECT_EQ(Signatures("reversal", 0, "slip- slip+ stick slip+"), Names{"slip- stick slip+ stick slip+"});
  EXPECT_EQ(Signatures("reversal", 1, "slip- slip- / antisymmetric", true), Names{"slip- slip- stick / antisymmetric"});
  const AdjacentType a = AdjacentTypes("reversal", 0, Signature::Parse("slip- slip+"), false).front();
  EXPECT_EQ(a.new_segment, 1);
  EXPECT_STREQ(a.bifurcation, "crossing-sliding");
}

TEST(AdjacentTypes, AStickEntryAtTheStaticLevelReversesFirstOrLosesAVanishedStick) {
  // slip+ stops into the stick of segment 3: the mass reverses (a slip- between), or, where the
  // stick has zero length, the slips on both sides of it are one.
  EXPECT_EQ(Signatures("stick-entry", 1, "slip- slip+ stick slip+"),
            (Names{"slip- slip+ slip- stick slip+", "slip- slip+"}));
  EXPECT_EQ(Signatures("stick-entry", 0, "slip- stick slip+ stick"),
            (Names{"slip- slip+ stick slip+ stick", "slip- slip+ stick"}));
}

TEST(AdjacentTypes, AnAbnormalStopWhoseJerkVanishesGetsAStick) {
  EXPECT_EQ(Signatures("abnormal-stop", 0, "slip- slip- / antisymmetric", true),
            Names{"slip- stick slip- / antisymmetric"});
}

TEST(AdjacentTypes, AGrazingOfTheVelocitySplitsTheSlipAroundAStickOrAnAbnormalStop) {
  EXPECT_EQ(Signatures("velocity", 0, "slip- slip+"), Names{"slip- stick slip- slip+"});
  EXPECT_EQ(Signatures("velocity", 0, "slip- slip+", true), (Names{"slip- stick slip- slip+", "slip- slip- slip+"}));
}

TEST(AdjacentTypes, AGrazingOfGOrG1SplitsTheStickAroundASlipOfThatSign) {
  EXPECT_EQ(Signatures("G", 2, "slip- slip+ stick"), Names{"slip- slip+ stick slip+ stick"});
  EXPECT_EQ(Signatures("G1", 1, "slip- stick / antisymmetric"), Names{"slip- stick slip- stick / antisymmetric"});
  EXPECT_STREQ(AdjacentTypes("G", 2, Signature::Parse("slip- slip+ stick"), false).front().bifurcation,
               "adding-sliding");
}

TEST(AdjacentTypes, AVanishedSegmentIsRemovedAndEqualNeighboursJoined) {
  EXPECT_EQ(Signatures("duration", 1, "slip- stick / antisymmetric"), Names{"slip- / antisymmetric"});
  EXPECT_EQ(Signatures("duration", 2, "slip- slip+ stick slip+"), Names{"slip- slip+"});  // slip+ joined
  EXPECT_EQ(Signatures("duration", 2, "slip- slip+ stick slip+", true), (Names{"slip- slip+", "slip- slip+ slip+"}));
  EXPECT_EQ(Signatures("duration", 1, "slip- slip+ stick slip+"), Names{"slip- stick slip+"});
  // The join would span the orbit's origin, and a lone segment cannot go.
  EXPECT_EQ(Signatures("duration", 0, "stick slip- stick slip-"), Names{});
  EXPECT_EQ(Signatures("duration", 0, "stick slip- stick slip+"), Names{"slip- stick slip+"});
  EXPECT_EQ(Signatures("duration", 0, "slip- / antisymmetric"), Names{});
}

TEST(AdjacentTypes, TangentialEndsAndTheFamilysEndHaveNone) {
  EXPECT_EQ(Signatures("stop-slope", 1, "slip- slip+ stick"), Names{});
  EXPECT_EQ(Signatures("exit-slope", 2, "slip- slip+ stick"), Names{});
  EXPECT_EQ(Signatures("sliding-friction", 0, "slip- slip+ stick"), Names{});
  EXPECT_NE(NoAdjacentTypeReason("stop-slope"), "");
  EXPECT_NE(NoAdjacentTypeReason("exit-slope"), "");
  EXPECT_EQ(NoAdjacentTypeReason("reversal"), "");
}

TEST(AdjacentTypes, AMarginThatIsNotTheSegmentsIsRefused) {
  const Signature s = Signature::Parse("slip- slip+ stick");
  EXPECT_THROW(AdjacentTypes("G", 0, s, false), InvalidInput);         // a slip has no G
  EXPECT_THROW(AdjacentTypes("reversal", 1, s, false), InvalidInput);  // slip+ ends into the stick
  EXPECT_THROW(AdjacentTypes("velocity", 2, s, false), InvalidInput);  // a stick has no velocity
  EXPECT_THROW(AdjacentTypes("slope", 0, s, false), InvalidInput);     // no such margin
  EXPECT_THROW(AdjacentTypes("duration", 3, s, false), InvalidInput);  // no such segment
}

// The start orbit is the same motion: sampled over a period it equals the located orbit.
void ExpectSameMotion(const Orbit& a, const Orbit& b) {
  ASSERT_DOUBLE_EQ(a.Period(), b.Period());
  const std::vector<State> sa = a.Sample(97);
  const std::vector<State> sb = b.Sample(97);
  for (std::size_t k = 0; k < sa.size(); ++k) EXPECT_LT((sa[k] - sb[k]).lpNorm<Eigen::Infinity>(), 1e-12) << k;
}

Margin Named(const Orbit& o, const std::string& name) {
  for (const Margin& m : AdmissibilityMargins(o)) {
    if (m.Name() == name) return m;
  }
  throw std::runtime_error(name);
}

TEST(AdjacentStart, AnInsertedSegmentHasZeroLengthAtTheStop) {
  const Orbit o = SolvedPreset("paper-4.1");
  const AdjacentType a = AdjacentTypes("reversal", 0, o.signature, false).front();
  const Orbit start = AdjacentStart(o, Named(o, "reversal:1"), a);
  EXPECT_EQ(start.durations, (std::vector<double>{o.durations[0], 0.0}));
  ExpectSameMotion(start, o);
}

TEST(AdjacentStart, ASplitStickIsCutAtTheTimeOfTheMargin) {
  const Orbit o = SolvedPreset("paper-6");
  Margin g = Named(o, "G:2");
  g.t = o.SegmentTimes()[1] + 0.3 * o.durations[1];  // an interior minimum's time, as a grazing has it
  const AdjacentType a = AdjacentTypes("G", 1, o.signature, false).front();
  const Orbit start = AdjacentStart(o, g, a);
  ASSERT_EQ(start.signature.ToString(), "slip- stick slip+ stick slip- / antisymmetric");
  const double tau = g.t - o.SegmentTimes()[1];
  EXPECT_GT(tau, 0.0);
  EXPECT_LT(tau, o.durations[1]);
  EXPECT_DOUBLE_EQ(start.durations[1], tau);
  EXPECT_EQ(start.durations[2], 0.0);
  EXPECT_NEAR(start.durations[1] + start.durations[3], o.durations[1], 1e-15);
  ExpectSameMotion(start, o);
}

TEST(AdjacentStart, ASlipSplitAtAnAbnormalStopKeepsItsMotion) {
  const Orbit o = SolvedPreset("paper-5.1");
  Margin m = Named(o, "velocity:1");
  m.t = 0.4 * o.durations[0];  // any interior time: the split itself does not move the motion
  const std::vector<AdjacentType> candidates = AdjacentTypes("velocity", 0, o.signature, true);
  ASSERT_EQ(candidates.size(), 2u);
  const Orbit start = AdjacentStart(o, m, candidates[1]);
  ASSERT_EQ(start.signature.ToString(), "slip- slip- slip+ stick slip+");
  EXPECT_NEAR(start.durations[0] + start.durations[1], o.durations[0], 1e-15);
  ExpectSameMotion(start, o);
}

// The seam: the edit knows an orbit of any model only by its signature and durations. A stick of
// zero length inserted at a stop of Den Hartog's orbit of the test model leaves its motion as it was.
TEST(AdjacentStart, AStopOfTheTestModelGetsAZeroLengthStickAndKeepsItsMotion) {
  using TestOrbit = BasicOrbit<DenHartogOscillator>;
  const TestOrbit orbit = DenHartogOnSignature(DenHartogOrbit(0.8, 0.2), "slip- slip+", 1.0);
  const AdjacentType a = AdjacentTypes("reversal", 0, orbit.signature, false).front();
  const TestOrbit start = AdjacentStart(orbit, Margin{}, a);
  EXPECT_EQ(start.signature.ToString(), "slip- stick slip+");
  EXPECT_EQ(start.durations, (std::vector<double>{orbit.durations[0], 0.0, orbit.durations[1]}));
  auto end_of_period = [](const TestOrbit& o) {
    DenHartogOscillator::State end;
    WalkSegments(DenHartogModel(), o, Extent::kListed, PhaseRule::kAccumulated,
                 [&](const SegmentVisit<double, DenHartogOscillator>& s) { end = s.end; });
    return end;
  };
  EXPECT_LT((end_of_period(start) - end_of_period(orbit)).lpNorm<Eigen::Infinity>(), 1e-14);
}

}  // namespace
}  // namespace stickslip
