// Least-period reduction: signatures written as copies of a shorter one reduce to it (the
// expected signature is the shorter one, parsed); an orbit written over three of its periods and
// solved by Newton as a period-3 orbit (from a perturbed guess, so that Newton, not the copy,
// makes the durations repeat) reduces to the paper orbit solved from the printed values; copies
// whose durations differ are not reduced, and the mismatch reported is the one put in.
#include "stickslip/orbits/least_period.hpp"

#include <cctype>
#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/model/linear_oscillator.hpp"
#include "stickslip/orbits/orbit_solver.hpp"
#include "support/belt_cycle.hpp"
#include "support/solved_presets.hpp"

namespace stickslip {
namespace {

namespace ov = orbit_variables;

void ExpectReducesTo(const char* text, const char* least, int repeats) {
  const SignatureRepeat r = LeastPeriodSignature(Signature::Parse(text));
  EXPECT_EQ(r.least, Signature::Parse(least)) << text << " gave " << r.least.ToString();
  EXPECT_EQ(r.repeats, repeats) << text;
}

TEST(LeastPeriodSignature, ReducesCopiesOfAShorterSequence) {
  ExpectReducesTo("slip- slip+ slip- slip+ slip- slip+ / period 3", "slip- slip+", 3);
  ExpectReducesTo("slip- stick slip- stick slip- stick slip- stick / period 4", "slip- stick", 4);
  ExpectReducesTo("slip- slip+ stick slip+ slip- slip+ stick slip+ / period 2", "slip- slip+ stick slip+", 2);
}

TEST(LeastPeriodSignature, ReducesOnlyAsFarAsThePeriodMultipleAllows) {
  // Six copies over 4 forcing periods: two copies of period 2 each; three would need 4/3 periods.
  ExpectReducesTo("slip- slip+ slip- slip+ slip- slip+ slip- slip+ slip- slip+ slip- slip+ / period 4",
                  "slip- slip+ slip- slip+ slip- slip+ / period 2", 2);
  // Copies within one forcing period are no forced orbit's repeat.
  ExpectReducesTo("slip- slip+ slip- slip+", "slip- slip+ slip- slip+", 1);
  ExpectReducesTo("slip- slip+ stick / period 5", "slip- slip+ stick / period 5", 1);
}

TEST(LeastPeriodSignature, ReducesAnAntisymmetricHalfThatAlternatesCopyAndMirror) {
  // Three half-periods of section 6's orbit: its half, the mirror image, its half again.
  ExpectReducesTo("slip- stick slip- slip+ stick slip+ slip- stick slip- / antisymmetric period 3",
                  "slip- stick slip- / antisymmetric", 3);
  // Plain copies of the half are another orbit: over 3 T/2 it would not have changed sign.
  ExpectReducesTo("slip- stick slip- slip- stick slip- slip- stick slip- / antisymmetric period 3",
                  "slip- stick slip- slip- stick slip- slip- stick slip- / antisymmetric period 3", 1);
}

// `orbit` written over `times` of its periods: the sequence (alternately mirrored when
// antisymmetric), the durations copied.
Orbit WrittenOver(const Orbit& orbit, int times) {
  std::vector<Mode> segments;
  std::vector<double> durations;
  for (int copy = 0; copy < times; ++copy) {
    for (int i = 0; i < orbit.signature.size(); ++i) {
      const Mode mode = orbit.signature.segments()[i];
      segments.push_back(orbit.signature.antisymmetric() && copy % 2 == 1 ? Mirror(mode) : mode);
      durations.push_back(orbit.durations[i]);
    }
  }
  Orbit written = orbit;
  written.signature = Signature(segments, orbit.signature.antisymmetric(), times * orbit.signature.period_multiple());
  written.durations = durations;
  return written;
}

// Newton on the period-`times` equations (x10, x20, v10, phi and every duration free) from the
// written-over orbit with every duration of the later copies moved by 1e-4.
Orbit SolvedOver(const Orbit& orbit, int times) {
  Orbit guess = WrittenOver(orbit, times);
  for (int i = orbit.signature.size(); i < guess.signature.size(); ++i) guess.durations[i] += 1e-4 * (i % 3 - 1);
  guess.x10 += 1e-5;
  const OrbitSolution solved = SolveOrbit(guess, FreeIndices(guess.signature, {}), false);
  EXPECT_TRUE(solved.summary.Converged()) << solved.summary.BriefReport();
  return solved.orbit;
}

void ExpectSameOrbit(const Orbit& reduced, const Orbit& expected, double tolerance) {
  ASSERT_EQ(reduced.signature, expected.signature) << reduced.signature.ToString();
  const Eigen::VectorXd a = ov::Pack(reduced);
  const Eigen::VectorXd b = ov::Pack(expected);
  for (int i = 0; i < a.size(); ++i) {
    EXPECT_NEAR(a(i), b(i), tolerance * (1.0 + std::abs(b(i)))) << ov::Name(expected.signature.size(), i);
  }
}

class ReducesPaperOrbitWrittenOverThreePeriods : public ::testing::TestWithParam<const char*> {};

TEST_P(ReducesPaperOrbitWrittenOverThreePeriods, ToThePaperOrbit) {
  const Orbit paper = SolvedPreset(GetParam());
  const LeastPeriodOrbit reduced = ReduceToLeastPeriod(SolvedOver(paper, 3));
  ASSERT_EQ(reduced.status, LeastPeriodStatus::kReduced) << reduced.message;
  EXPECT_EQ(reduced.repeats, 3);
  EXPECT_LT(reduced.duration_mismatch, 1e-10);
  EXPECT_LT(reduced.state_mismatch, 1e-10);
  ExpectSameOrbit(reduced.orbit, paper, 1e-9);
}

// Section 4.1 is antisymmetric (a one-segment half), 5.1 plain with a stick.
INSTANTIATE_TEST_SUITE_P(Paper, ReducesPaperOrbitWrittenOverThreePeriods,
                         ::testing::Values("paper-4.1", "paper-5.1"),
                         [](const ::testing::TestParamInfo<const char*>& param_info) {
                           std::string name;
                           for (const char* c = param_info.param; *c != '\0'; ++c) {
                             if (std::isalnum(static_cast<unsigned char>(*c))) name += *c;
                           }
                           return name;  // "paper41"
                         });

TEST(ReduceToLeastPeriod, KeepsCopiesWhoseDurationsDiffer) {
  const Orbit paper = SolvedPreset("paper-5.1");
  Orbit written = WrittenOver(paper, 3);
  // The second copy's first segment 1e-3 longer, the third's 1e-3 shorter: the span is kept.
  const int m = paper.signature.size();
  written.durations[m] += 1e-3;
  written.durations[2 * m] -= 1e-3;
  const LeastPeriodOrbit result = ReduceToLeastPeriod(written);
  EXPECT_EQ(result.status, LeastPeriodStatus::kNotRepeating);
  EXPECT_EQ(result.repeats, 1);
  EXPECT_EQ(result.orbit.signature, written.signature);
  EXPECT_NEAR(result.duration_mismatch, 1e-3 / (2.0 * std::numbers::pi / paper.parameters.omega), 1e-12);
  EXPECT_NE(result.message.find("does not"), std::string::npos) << result.message;
}

TEST(ReduceToLeastPeriod, LeavesAnOrbitOfLeastPeriodAsItIs) {
  const Orbit paper = SolvedPreset("paper-6");
  const LeastPeriodOrbit result = ReduceToLeastPeriod(paper);
  EXPECT_EQ(result.status, LeastPeriodStatus::kLeast);
  ExpectSameOrbit(result.orbit, paper, 0.0);
}

TEST(ReduceToLeastPeriod, RefusesDurationsThatDoNotMatchTheSignature) {
  Orbit orbit = SolvedPreset("paper-5.1");
  orbit.durations.pop_back();
  EXPECT_THROW(ReduceToLeastPeriod(orbit), InvalidInput);
  EXPECT_THROW(ReduceToLeastPeriod(SolvedPreset("paper-5.1"), {0.0}), InvalidInput);
}

// One undamped mass on a belt, no forcing (autonomous), its stick-slip cycle in closed form
// (FRICTION-LITERATURE.md: m = k = 1, F_k = 1, F_s = 1.5, the stick from x = (2 F_k - F_s)/k at the
// belt's speed for 2 (F_s - F_k)/(k v_b), the slip for pi + 2 atan(v_b/d)) written twice within
// "one period": with no forcing there is no period to divide, so it is one cycle twice and reduces
// to it (a forced orbit's sequence repeated within one forcing period does not: the test above).
TEST(ReduceToLeastPeriod, ReducesAnAutonomousCycleWrittenTwice) {
  BeltCycle belt;
  belt.v_b = 0.3;
  const LinearOscillator<1> model(belt.Data());
  BasicOrbit<LinearOscillator<1>> twice = belt.Orbit();
  twice.signature = Signature::Parse("stick slip- stick slip-");
  twice.durations = {belt.Stick(), belt.Slip(), belt.Stick(), belt.Slip()};
  const BasicLeastPeriodOrbit<LinearOscillator<1>> reduced = ReduceToLeastPeriod<LinearOscillator<1>>(model, twice);
  EXPECT_EQ(reduced.status, LeastPeriodStatus::kReduced) << reduced.message;
  EXPECT_EQ(reduced.orbit.signature, Signature::Parse("stick slip-"));
  EXPECT_EQ(reduced.repeats, 2);
  EXPECT_LE(reduced.state_mismatch, 1e-12);
  twice.durations[2] += 0.1;  // the second stick longer: two different cycles, no reduction
  EXPECT_EQ((ReduceToLeastPeriod<LinearOscillator<1>>(model, twice).status), LeastPeriodStatus::kNotRepeating);
}

}  // namespace
}  // namespace stickslip
