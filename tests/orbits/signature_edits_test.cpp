// Signature edits: round trips, explicit renaming of durations, and orbits that stay the same
// motion under an edited type (compared by sampling the closed-form flows over a period).
#include "stickslip/orbits/signature_edits.hpp"

#include <gtest/gtest.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/orbits/periodicity.hpp"
#include "support/solved_presets.hpp"

namespace stickslip {
namespace {

Signature Parsed(const char* text) { return Signature::Parse(text); }

// The largest difference between the two orbits' states at 401 times over one period.
double SampledDistance(const Orbit& a, const Orbit& b) {
  const std::vector<State> x = a.Sample(401);
  const std::vector<State> y = b.Sample(401);
  double distance = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k) distance = std::max(distance, (x[k] - y[k]).lpNorm<Eigen::Infinity>());
  return distance;
}

TEST(SignatureEdits, InsertThenRemoveGivesTheSignatureBack) {
  const Signature s = Parsed("slip- slip+ stick slip+");
  for (int position = 0; position <= s.size(); ++position) {
    const SignatureEdit inserted = InsertSegment(s, position, Mode::kSlipNegative);
    EXPECT_EQ(inserted.signature.size(), s.size() + 1);
    EXPECT_EQ(inserted.signature.segments()[position], Mode::kSlipNegative);
    EXPECT_EQ(RemoveSegment(inserted.signature, position, /*join_equal_neighbours=*/false).signature, s);
  }
}

TEST(SignatureEdits, SplitThenRemoveWithJoinGivesTheSignatureBack) {
  const Signature s = Parsed("slip- slip+ stick slip+");
  const SignatureEdit split = SplitSegment(s, 1, Mode::kStick);  // a stick inside slip+
  EXPECT_EQ(split.signature, Parsed("slip- slip+ stick slip+ stick slip+"));
  EXPECT_EQ(RemoveSegment(split.signature, 2, /*join_equal_neighbours=*/true).signature, s);
  // Without the join the two slips meet at an abnormal stop.
  EXPECT_EQ(RemoveSegment(split.signature, 2, false).signature, Parsed("slip- slip+ slip+ stick slip+"));
}

TEST(SignatureEdits, RenameDurationsExplicitlyAndRefuseOnesThatChangedMeaning) {
  const Signature s = Parsed("slip- slip+ stick slip+");
  const SignatureEdit inserted = InsertSegment(s, 1, Mode::kStick);
  EXPECT_EQ(inserted.Renamed("d1"), "d1");
  EXPECT_EQ(inserted.Renamed("d2"), "d3");
  EXPECT_EQ(inserted.Renamed("d4"), "d5");
  EXPECT_EQ(inserted.Renamed("omega"), "omega");
  EXPECT_EQ(inserted.Renamed("phi"), "phi");
  const SignatureEdit split = SplitSegment(s, 1, Mode::kStick);
  EXPECT_THROW(split.Renamed("d2"), InvalidInput);  // now only the part before the stick
  EXPECT_EQ(split.Renamed("d3"), "d5");
  const SignatureEdit removed = RemoveSegment(s, 2, /*join_equal_neighbours=*/true);
  EXPECT_EQ(removed.signature, Parsed("slip- slip+"));
  EXPECT_THROW(removed.Renamed("d2"), InvalidInput);  // joined with d4
  EXPECT_THROW(removed.Renamed("d3"), InvalidInput);  // removed
  EXPECT_EQ(removed.Renamed("d1"), "d1");
}

TEST(SignatureEdits, RefuseInvalidResultsWithTheFieldNamed) {
  const Signature s = Parsed("slip- stick slip+");
  EXPECT_THROW(InsertSegment(s, 1, Mode::kStick), InvalidInput);  // a stick beside a stick
  EXPECT_THROW(InsertSegment(s, 4, Mode::kStick), InvalidInput);
  EXPECT_THROW(RemoveSegment(s, -1, false), InvalidInput);
  EXPECT_THROW(RemoveSegment(Parsed("slip-"), 0, false), InvalidInput);
  // Joining slip+ ... slip+ around a vanished first segment would span the time origin.
  EXPECT_THROW(RemoveSegment(Parsed("stick slip+ slip- slip+"), 0, true), InvalidInput);
  EXPECT_THROW(RemoveSegment(Parsed("slip+ stick"), 1, true), InvalidInput);
  // Before the first listed segment of an antisymmetric orbit comes the mirror of the last one:
  // slip+ (the mirror of slip-) and slip+ would join across the origin.
  EXPECT_THROW(RemoveSegment(Parsed("stick slip+ slip- / antisymmetric"), 0, true), InvalidInput);
  EXPECT_EQ(RemoveSegment(Parsed("stick slip+ slip- / antisymmetric"), 0, false).signature,
            Parsed("slip+ slip- / antisymmetric"));
  try {
    InsertSegment(s, 9, Mode::kSlipNegative);
    FAIL();
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.field(), "position");
    EXPECT_EQ(std::string(e.what()), "position = 9 is invalid: valid range 0 <= position <= 3");
  }
}

// A zero-length segment inserted anywhere, or a split around one, leaves the motion as it was.
TEST(OrbitEdits, ZeroLengthSegmentGivesTheSameOrbit) {
  for (const char* name : {"paper-4.1", "paper-5.1", "paper-6"}) {
    SCOPED_TRACE(name);
    const Orbit o = SolvedPreset(name);
    for (int position = 0; position <= o.signature.size(); ++position) {
      const Mode mode = position < o.signature.size() && o.signature.segments()[position] == Mode::kStick
                            ? Mode::kSlipPositive
                            : Mode::kStick;
      if (position > 0 && o.signature.segments()[position - 1] == Mode::kStick && mode == Mode::kStick) continue;
      const Orbit edited = InsertSegment(o, position, mode);
      EXPECT_EQ(edited.Period(), o.Period());
      EXPECT_EQ(edited.InitialState(), o.InitialState());
      EXPECT_EQ(edited.phi, o.phi);
      EXPECT_LT(SampledDistance(edited, o), 1e-12);
    }
    for (int i = 0; i < o.signature.size(); ++i) {
      if (o.signature.segments()[i] == Mode::kStick) continue;
      const Orbit split = SplitSegment(o, i, 0.4 * o.durations[i], Mode::kStick);
      EXPECT_LT(SampledDistance(split, o), 1e-12);
      const Orbit back = RemoveSegment(split, i + 1, /*join_equal_neighbours=*/true);
      EXPECT_EQ(back.signature, o.signature);
      ASSERT_EQ(back.durations.size(), o.durations.size());
      for (std::size_t k = 0; k < o.durations.size(); ++k) {
        EXPECT_NEAR(back.durations[k], o.durations[k], 1e-15 * o.durations[k] + 1e-15);
      }
    }
  }
}

// At a located stop-force boundary (a reversal whose force reaches the static level) a
// zero-length stick inserted at the stop solves the periodicity equations of the new type: the
// edit is how a branch of the adjacent type starts.
TEST(OrbitEdits, ZeroLengthStickSolvesTheAdjacentTypeWhereTheReversalForceIsAtItsLevel) {
  Orbit o = SolvedPreset("paper-4.1");  // a reversal at the end of segment 1
  // Move u_r onto the reversal's force threshold: s - eta u_r = 0 there (the stop-force margin).
  const State end = o.SegmentStates()[1];
  const double phase = o.phi + o.parameters.omega * o.durations[0];
  o.parameters.u_r = std::abs(StickForce(end, phase, o.parameters)) / o.parameters.eta;
  const Orbit edited = InsertSegment(o, 1, Mode::kStick);
  const PeriodicityEquations adjacent(edited.signature, Shooting::kSingle);
  Eigen::VectorXd residual;
  adjacent.Evaluate(adjacent.Variables(edited), &residual, nullptr);
  EXPECT_LT(residual.lpNorm<Eigen::Infinity>(), 1e-12) << residual.transpose();
}

TEST(Unfolded, ListsTheWholePeriodAsOftenAsAsked) {
  EXPECT_EQ(Unfolded(Parsed("slip- stick slip- / antisymmetric"), 1), Parsed("slip- stick slip- slip+ stick slip+"));
  EXPECT_EQ(Unfolded(Parsed("slip- slip+ stick"), 2), Parsed("slip- slip+ stick slip- slip+ stick / period 2"));
  EXPECT_EQ(Unfolded(Parsed("slip- / antisymmetric"), 2).ToString(), "slip- slip+ slip- slip+ / period 2");
  EXPECT_THROW(Unfolded(Parsed("slip- slip+"), 0), InvalidInput);
}

TEST(Unfolded, IsTheSameMotion) {
  for (const char* preset : {"paper-6", "paper-5.1", "paper-4.1"}) {
    SCOPED_TRACE(preset);
    const Orbit o = SolvedPreset(preset);
    EXPECT_LT(SampledDistance(Unfolded(o, 1), o), 1e-12);
    // Over two periods: the same states at the same times, twice.
    const std::vector<State> once = o.Sample(401), twice = Unfolded(o, 2).Sample(801);
    for (int k = 0; k < 801; ++k) {
      EXPECT_LT((twice[k] - once[k % 400]).lpNorm<Eigen::Infinity>(), 1e-11) << k;
    }
  }
}

}  // namespace
}  // namespace stickslip
