// Independent verification of computed orbits: it passes on the paper's orbits and reports, never
// crashes on, an orbit that is no motion of the system.
#include "stickslip/orbits/verification.hpp"

#include <gtest/gtest.h>

#include "stickslip/model/exact_simulator.hpp"
#include "stickslip/model/odeint_simulation.hpp"
#include "stickslip/orbits/margins.hpp"
#include "stickslip/orbits/orbit_solver.hpp"
#include "stickslip/orbits/paper_presets.hpp"
#include "support/den_hartog_orbit.hpp"
#include "support/den_hartog_oscillator.hpp"
#include "support/solved_presets.hpp"

namespace stickslip {
namespace {

TEST(VerifyOrbit, PassesOnThePaperOrbits) {
  for (const char* name : {"paper-4.1", "paper-5.1", "paper-6"}) {
    const Verification v = VerifyOrbit(SolvedPreset(name));
    EXPECT_TRUE(v.Passed()) << name << "\n" << v.Report();
  }
}

// Section 4.2's orbits have abnormal stops (u_r = u_s): the contact's velocity touches zero with
// zero slope, so its minimum is zero only to the integrator's error, and Odeint's search for a dip
// inside a step must not take that for a stick (slip, stick, slip would not match the orbit's
// sequence). Solved at forcing frequencies from 3 % below the paper's to 3 % above, every orbit
// that is a motion (all margins positive) passes both simulators.
TEST(VerifyOrbit, PassesAlongSection42sOrbitsWithAbnormalStops) {
  const PaperPreset& preset = *FindPaperPreset("paper-4.2");
  Orbit guess = SolvedPreset("paper-4.2");
  const double omega = guess.parameters.omega;
  int verified = 0;
  for (const double factor : {1.0, 0.985, 0.97, 1.015, 1.03}) {
    guess.parameters.omega = omega * factor;
    const OrbitSolution s =
        SolveOrbit(guess, FreeIndices(guess.signature, preset.unknowns), preset.unknowns.tie_static_friction);
    ASSERT_TRUE(s.summary.Converged()) << "omega = " << guess.parameters.omega << ": " << s.summary.message;
    if (SmallestMargin(AdmissibilityMargins(s.orbit)).value <= 0.0) continue;
    const Verification v = VerifyOrbit(s.orbit);
    EXPECT_TRUE(v.Passed()) << "omega = " << s.orbit.parameters.omega << "\n" << v.Report();
    ++verified;
  }
  EXPECT_GE(verified, 3);
}

// Newton may converge past a family's end, where u_s <= 0 (paper-4.2 at omega = 0.63 did, and
// the verification then read an empty simulation: SIGSEGV).
TEST(VerifyOrbit, ReportsAnOrbitWithNonPhysicalFrictionInsteadOfSimulatingIt) {
  Orbit o = SolvedPreset("paper-4.2");
  o.parameters.u_s = -0.001;
  o.parameters.u_r = -0.001;
  const Verification v = VerifyOrbit(o);
  EXPECT_FALSE(v.Passed());
  EXPECT_NE(v.not_simulated.find("u_s = -0.001 is invalid"), std::string::npos) << v.not_simulated;
  EXPECT_NE(v.Report().find("not simulated"), std::string::npos);
}

// The test model through the interface, by its own simulators: Den Hartog's orbit is a motion
// (both follow it over a period) while r^2 X > beta_static, and is not once the static level
// holds its turning points (Shaw; FRICTION-LITERATURE.md): there the simulated mass sticks.
TEST(VerifyOrbit, PassesDenHartogsOrbitOfTheTestModelAndFailsItWhereStaticFrictionHoldsItsTurningPoints) {
  auto exact = [](const DenHartogOscillator& m, const DenHartogOscillator::Parameters& p,
                  const DenHartogOscillator::State& x0, double phi,
                  const BasicSimulationOptions<DenHartogOscillator::State>& options) {
    return SimulateExact(m, p, x0, phi, options);
  };
  auto integrated = [](const DenHartogOscillator& m, const DenHartogOscillator::Parameters& p,
                       const DenHartogOscillator::State& x0, double phi,
                       const BasicSimulationOptions<DenHartogOscillator::State>& options) {
    return SimulateOdeint(m, p, x0, phi, options);
  };
  for (const auto& [r, beta] : kDenHartogNonStickingCases) {
    SCOPED_TRACE(testing::Message() << "r = " << r << ", beta = " << beta);
    const DenHartogOrbit o(r, beta);
    for (const char* signature : {"slip- / antisymmetric", "slip- slip+"}) {
      const Verification v = VerifyOrbit(DenHartogModel(), DenHartogOnSignature(o, signature, beta), exact, integrated);
      EXPECT_TRUE(v.Passed()) << signature << "\n" << v.Report();
    }
    const double holding = r * r * o.amplitude;
    const Verification held =
        VerifyOrbit(DenHartogModel(), DenHartogOnSignature(o, "slip- slip+", 1.05 * holding), exact, integrated);
    EXPECT_FALSE(held.exact.sequence_matches) << held.Report();
    EXPECT_FALSE(held.odeint.sequence_matches) << held.Report();
    EXPECT_FALSE(held.Passed());
  }
}

}  // namespace
}  // namespace stickslip
