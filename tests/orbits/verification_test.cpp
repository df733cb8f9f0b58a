// Independent verification of computed orbits: it passes on the paper's orbits and reports, never
// crashes on, an orbit that is no motion of the system.
#include "stickslip/orbits/verification.hpp"

#include <gtest/gtest.h>

#include "stickslip/model/exact_simulator.hpp"
#include "stickslip/model/odeint_simulation.hpp"
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
