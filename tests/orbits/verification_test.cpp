// Independent verification of computed orbits: it passes on the paper's orbits and reports, never
// crashes on, an orbit that is no motion of the system.
#include "stickslip/orbits/verification.hpp"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace stickslip
