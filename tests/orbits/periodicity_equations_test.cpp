// The periodicity equations through the model interface, on a model other than the paper's: Den
// Hartog's one-mass oscillator (tests/support), whose non-sticking orbit is known in closed form.
#include "stickslip/orbits/periodicity_equations.hpp"

#include <cmath>
#include <numbers>
#include <numeric>

#include <gtest/gtest.h>

#include "stickslip/orbits/orbit_system.hpp"
#include "support/central_differences.hpp"
#include "support/den_hartog_orbit.hpp"
#include "support/den_hartog_oscillator.hpp"

namespace stickslip {
namespace {

using Equations = BasicPeriodicityEquations<DenHartogOscillator>;

struct Case {
  const char* signature;
  Shooting shooting;
};

class DenHartogPeriodicity : public testing::TestWithParam<Case> {};

TEST_P(DenHartogPeriodicity, VanishOnDenHartogsOrbit) {
  const Equations equations(DenHartogModel(), Signature::Parse(GetParam().signature), GetParam().shooting);
  for (const auto& [r, beta] : {std::pair{0.6, 0.1}, std::pair{1.5, 0.25}, std::pair{2.5, 0.25}}) {
    Eigen::VectorXd residual;
    equations.Evaluate(DenHartogVariables(DenHartogOrbit(r, beta), equations), &residual, nullptr);
    EXPECT_LT(residual.lpNorm<Eigen::Infinity>(), 1e-12) << "r = " << r;
  }
}

TEST_P(DenHartogPeriodicity, JacobianIsTheCentralDifferenceOfTheResidual) {
  const Equations equations(DenHartogModel(), Signature::Parse(GetParam().signature), GetParam().shooting);
  Eigen::VectorXd v = DenHartogVariables(DenHartogOrbit(0.8, 0.2), equations);
  v(0) += 0.03;  // off the orbit, where no column vanishes by symmetry
  v(equations.Phi()) -= 0.02;
  Eigen::VectorXd residual;
  Eigen::MatrixXd jacobian;
  equations.Evaluate(v, &residual, &jacobian);
  const Eigen::MatrixXd differences = CentralDifferenceJacobian(equations, v);
  for (int k = 0; k < v.size(); ++k) {
    EXPECT_LT((differences.col(k) - jacobian.col(k)).lpNorm<Eigen::Infinity>(), 1e-7) << "column " << k;
  }
}

TEST_P(DenHartogPeriodicity, NewtonConvergesToDenHartogsOrbitFromAPerturbedGuess) {
  const Equations equations(DenHartogModel(), Signature::Parse(GetParam().signature), GetParam().shooting);
  std::vector<int> free(equations.Parameter(0));  // start, phase and durations; parameters held
  std::iota(free.begin(), free.end(), 0);
  for (const auto& [r, beta] : {std::pair{0.6, 0.1}, std::pair{1.5, 0.25}}) {
    const DenHartogOrbit orbit(r, beta);
    const BasicOrbitSystem<DenHartogOscillator> system(equations, DenHartogVariables(orbit, equations), free, false);
    Eigen::VectorXd guess = system.Unknowns(DenHartogVariables(orbit, equations));
    guess(0) *= 1.1;
    guess(equations.Phi()) += 0.1;
    guess(equations.Duration(0)) *= 1.05;
    const NewtonResult solved = SolveNewton(system, guess);
    ASSERT_TRUE(solved.summary.Converged()) << solved.summary.message;
    const Eigen::VectorXd v = system.Variables(solved.solution);
    EXPECT_NEAR(v(0), orbit.amplitude, 1e-10) << "r = " << r;
    EXPECT_NEAR(std::remainder(v(equations.Phi()) - orbit.phi, 2 * std::numbers::pi), 0.0, 1e-10);
    for (int i = 0; i < equations.signature().size(); ++i) {
      EXPECT_NEAR(v(equations.Duration(i)), std::numbers::pi / r, 1e-10);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Formulations, DenHartogPeriodicity,
                         testing::Values(Case{"slip- / antisymmetric", Shooting::kSingle},
                                         Case{"slip- slip+", Shooting::kSingle},
                                         Case{"slip- slip+", Shooting::kMultiple}),
                         [](const testing::TestParamInfo<Case>& test) {
                           return std::string(test.param.shooting == Shooting::kMultiple ? "Multiple" : "Single") +
                                  (std::string(test.param.signature).find('/') != std::string::npos ? "HalfPeriod"
                                                                                                   : "FullPeriod");
                         });

TEST(DenHartogPeriodicity, NamesItsEquationsInTheModelsWords) {
  const Equations equations(DenHartogModel(), Signature::Parse("slip- slip+"), Shooting::kMultiple);
  const std::vector<std::string> expected = {"end:1", "continuity:2:x", "continuity:2:x'", "end:2", "periodicity:x",
                                             "period"};
  EXPECT_EQ(equations.EquationNames(), expected);
}

}  // namespace
}  // namespace stickslip
