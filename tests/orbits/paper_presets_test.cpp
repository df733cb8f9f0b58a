// Every paper example solved and compared with every value the paper prints, within the
// consistency of the printed numbers (shared/paper/ERRATA.md); each admissible orbit verified by
// both simulators; the section 5.2 orbit at the printed data shown inadmissible.
#include "stickslip/orbits/paper_presets.hpp"

#include <string>

#include <gtest/gtest.h>

#include "stickslip/model/simulation.hpp"
#include "stickslip/orbits/margins.hpp"
#include "stickslip/orbits/verification.hpp"

namespace stickslip {
namespace {

namespace ov = orbit_variables;

Orbit Solve(const char* name, bool paper_choice) {
  const PaperPreset& preset = *FindPaperPreset(name);
  const UnknownChoice& choice = paper_choice ? preset.paper_choice : preset.unknowns;
  const Orbit guess = preset.Guess();
  const OrbitSolution s = SolveOrbit(guess, FreeIndices(guess.signature, choice), choice.tie_static_friction);
  EXPECT_TRUE(s.summary.Converged()) << name << ": " << s.summary.BriefReport();
  return s.orbit;
}


void ExpectPrintedValues(const char* name, const Orbit& o, double tolerance,
                         std::string_view except = "") {
  for (const PrintedValue& v : FindPaperPreset(name)->printed) {
    if (v.paper_name == except) continue;
    EXPECT_NEAR(PrintedQuantity(o, v.variable), std::stod(std::string(v.text)), tolerance)
        << name << " " << v.paper_name;
  }
}

// Printed to 4-5 digits; the example sits on the sticking threshold but the orbit is exact:
// agreement to 2e-4 (ERRATA), tolerance 3e-4.
TEST(PaperOrbits, Section41MatchesThePrintedValues) {
  ExpectPrintedValues("paper-4.1", Solve("paper-4.1", false), 3e-4);
}

// u_s = u_r solved as the paper says. The printed tau1 = 4 is off: the abnormal stop falls at
// t = 3.883 (ERRATA: "near 3.9"); no other choice reproduces 4 with the other values (results/README.md, errata).
// The other printed values agree to 7e-3; the ERRATA's consistency is about 1e-2.
TEST(PaperOrbits, Section42MatchesThePrintedValuesButTau1) {
  const Orbit o = Solve("paper-4.2", false);
  ExpectPrintedValues("paper-4.2", o, 1e-2, "tau1");
  EXPECT_NEAR(o.durations[0], 3.9, 0.02);
  EXPECT_DOUBLE_EQ(o.parameters.u_r, o.parameters.u_s);
}

// With all printed data held, the round tau1 = 2 and tau2 = 3 come out within 2e-4 and tau
// within 3.8e-4 of its printed 3.2663 (the printed tau + T = 6 exactly, which the exact orbit
// misses by 2.3e-4): the paper's consistency here is 4e-4.
TEST(PaperOrbits, Section51MatchesThePrintedValues) {
  const Orbit o = Solve("paper-5.1", false);
  ExpectPrintedValues("paper-5.1", o, 4e-4);
  EXPECT_NEAR(o.durations[1], 2.0, 2e-4);
  EXPECT_NEAR(o.durations[3], 3.0, 2e-4);
}

// Printed to 2-3 digits for the durations and inconsistent at the 3e-2 level (ERRATA).
TEST(PaperOrbits, Section52MatchesThePrintedValuesEitherWay) {
  ExpectPrintedValues("paper-5.2", Solve("paper-5.2", false), 3.5e-2);
  const Orbit held_phi = Solve("paper-5.2", true);
  ExpectPrintedValues("paper-5.2", held_phi, 3.5e-2);
  EXPECT_NEAR(held_phi.parameters.u_r, 0.478, 1e-3);  // ERRATA: "u_r = 0.478"
}

// phi = 3 looks held fixed (ERRATA): with it held and u_r released every value agrees to 4e-2.
TEST(PaperOrbits, Section6MatchesThePrintedValuesWithPhiHeld) {
  ExpectPrintedValues("paper-6", Solve("paper-6", true), 4e-2);
}

class AdmissiblePaperOrbit : public ::testing::TestWithParam<std::pair<const char*, bool>> {};

TEST_P(AdmissiblePaperOrbit, PassesIndependentVerificationWithItsSignature) {
  const auto [name, paper_choice] = GetParam();
  const Orbit o = Solve(name, paper_choice);
  EXPECT_GT(SmallestMargin(AdmissibilityMargins(o)).value, 0.0) << name;
  const Verification v = VerifyOrbit(o);
  EXPECT_TRUE(v.Passed()) << name << "\n" << v.Report();
  EXPECT_TRUE(v.exact.sequence_matches) << v.Report();
  EXPECT_LE(v.exact.periodicity_mismatch, 1e-9);
  EXPECT_LE(v.odeint.periodicity_mismatch, 1e-6);
  EXPECT_LE(v.exact.max_event_time_difference, 1e-9);
  EXPECT_LE(v.odeint.max_event_time_difference, 1e-6);
}

INSTANTIATE_TEST_SUITE_P(
    PaperOrbits, AdmissiblePaperOrbit,
    ::testing::Values(std::pair{"paper-4.1", false}, std::pair{"paper-4.2", false},
                      std::pair{"paper-5.1", false}, std::pair{"paper-5.1", true},
                      std::pair{"paper-5.2", true}, std::pair{"paper-6", false},
                      std::pair{"paper-6", true}),
    [](const auto& param_info) {
      std::string s = std::string(param_info.param.first).substr(6) +
                      (param_info.param.second ? "PaperChoice" : "PaperData");
      for (char& c : s) {
        if (c == '.') c = '_';
      }
      return s;
    });

// ERRATA: at the printed data the section 5.2 orbit exists but violates G >= 0 inside the stick
// (minimum about -0.007); simulated from its start, the stick ends early, near that minimum,
// with an exit into slip+ (G = 0).
TEST(PaperOrbits, Section52AtThePrintedDataLeavesItsStickWhereGIsNegative) {
  const Orbit o = Solve("paper-5.2", false);
  const std::vector<Margin> margins = AdmissibilityMargins(o);
  const Margin smallest = SmallestMargin(margins);
  EXPECT_EQ(smallest.Name(), "G:3");
  EXPECT_NEAR(smallest.value, -0.007, 1e-3);
  const Verification v = VerifyOrbit(o);
  EXPECT_FALSE(v.Passed());
  EXPECT_FALSE(v.exact.sequence_matches);

  SimulationOptions options;
  options.duration = o.Period();
  const SimulationResult r = SimulateExact(o.parameters, o.InitialState(), o.phi, options);
  ASSERT_GE(r.segments.size(), 4u);
  const Segment& stick = r.segments[2];
  ASSERT_EQ(stick.mode, Mode::kStick);
  EXPECT_EQ(stick.end_reason, SegmentEnd::kStickExit);
  EXPECT_EQ(r.segments[3].mode, Mode::kSlipPositive);
  const double stick_start = o.durations[0] + o.durations[1];
  EXPECT_LT(stick.t_end, stick_start + o.durations[2]);  // early
  EXPECT_GT(stick.t_end, stick_start);
  EXPECT_LT(stick.t_end, smallest.t);                     // G crosses zero before its minimum
  EXPECT_NEAR(stick.t_end, smallest.t, 0.5);
}

}  // namespace
}  // namespace stickslip
