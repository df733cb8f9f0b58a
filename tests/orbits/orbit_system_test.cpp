// An orbit system of a model other than the paper's, continued by the engine: Den Hartog's
// non-sticking orbit (tests/support) followed in the friction ratio, against his closed form.
#include "stickslip/orbits/orbit_system.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "stickslip/continuation/continuation.hpp"
#include "support/den_hartog_orbit.hpp"
#include "support/den_hartog_oscillator.hpp"

namespace stickslip {
namespace {

using Equations = BasicPeriodicityEquations<DenHartogOscillator>;

TEST(OrbitSystem, ContinuesDenHartogsOrbitInTheFrictionRatioAlongHisClosedForm) {
  for (const double r : {0.6, 1.5}) {
    const Equations equations(DenHartogModel(), Signature::Parse("slip- / antisymmetric"), Shooting::kSingle);
    // x0, phi, d1 and beta, the static level tied to it.
    const std::vector<int> free = {0, equations.Phi(), equations.Duration(0), equations.Parameter(1)};
    const BasicOrbitSystem<DenHartogOscillator> system(equations, DenHartogVariables(DenHartogOrbit(r, 0.02), equations),
                                                       free, true);
    ContinuationOptions options;
    options.parameter_index = 3;
    options.lambda_max = 0.15;
    const Eigen::VectorXd start = system.Unknowns(DenHartogVariables(DenHartogOrbit(r, 0.02), equations));
    const Branch branch = Continuation(system, nullptr, options, start).Run();
    ASSERT_EQ(branch.end, BranchEnd::kParameterBound) << branch.end_message;
    ASSERT_GT(branch.points.size(), 5u);
    EXPECT_NEAR(branch.points.back().lambda, 0.15, 1e-10);
    for (const BranchPoint& point : branch.points) {
      const Eigen::VectorXd v = system.Variables(point.u);
      const DenHartogOrbit orbit(r, v(equations.Parameter(1)));
      EXPECT_NEAR(v(0), orbit.amplitude, 1e-9) << "r = " << r << ", beta = " << orbit.beta;
      EXPECT_NEAR(std::remainder(v(equations.Phi()) - orbit.phi, 2 * std::numbers::pi), 0.0, 1e-9);
      EXPECT_NEAR(v(equations.Duration(0)), std::numbers::pi / r, 1e-9);
      EXPECT_EQ(v(equations.Parameter(2)), v(equations.Parameter(1)));  // the static level tied
    }
  }
}

}  // namespace
}  // namespace stickslip
