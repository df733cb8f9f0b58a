// The monodromy matrix's exact derivatives (forward-mode AD through the walk) against central
// differences of StabilityOf's monodromy, on paper orbits with and without sticks.
#include "stickslip/orbits/floquet_gradients.hpp"

#include <algorithm>
#include <span>

#include <gtest/gtest.h>

#include "stickslip/orbits/stability.hpp"
#include "support/five_mass_chain.hpp"
#include "support/perturbed_orbit.hpp"
#include "support/solved_presets.hpp"

namespace stickslip {
namespace {

namespace ov = orbit_variables;

class MonodromyGradients : public ::testing::TestWithParam<const char*> {};

Eigen::Matrix4d ListedMonodromy(const Orbit& o) {
  return Monodromy<double>(o.signature, o.InitialState(), o.phi, o.durations, o.parameters).listed;
}
template <typename Model>
Eigen::MatrixXd ListedMonodromy(const Model& model, const BasicOrbit<Model>& o) {
  return Monodromy<double>(model, o.signature, o.start, o.phi, std::span<const double>(o.durations), o.parameters).listed;
}

TEST_P(MonodromyGradients, ValueIsTheStabilityMonodromy) {
  const Orbit o = SolvedPreset(GetParam());
  const MonodromyGradient g = stickslip::MonodromyGradients(o);
  const Eigen::Matrix4d m = StabilityOf(o).monodromy;
  EXPECT_LE((g.period - m).cwiseAbs().maxCoeff(), 1e-13 * (1.0 + m.cwiseAbs().maxCoeff()));
  EXPECT_LE((g.listed - ListedMonodromy(o)).cwiseAbs().maxCoeff(), 1e-13 * (1.0 + m.cwiseAbs().maxCoeff()));
}

TEST_P(MonodromyGradients, AreCentralDifferencesOfTheMonodromy) {
  const Orbit o = SolvedPreset(GetParam());
  const MonodromyGradient g = stickslip::MonodromyGradients(o);
  const Eigen::VectorXd v = ov::Pack(o);
  ASSERT_EQ(static_cast<int>(g.d_period.size()), v.size());
  const double scale = 1.0 + g.period.cwiseAbs().maxCoeff();
  for (int k = 0; k < v.size(); ++k) {
    const double h = 1e-6 * (1.0 + std::abs(v(k)));
    Eigen::VectorXd plus = v, minus = v;
    plus(k) += h;
    minus(k) -= h;
    const Orbit op = ov::Unpack(o.signature, plus), om = ov::Unpack(o.signature, minus);
    const Eigen::Matrix4d period = (StabilityOf(op).monodromy - StabilityOf(om).monodromy) / (2 * h);
    const Eigen::Matrix4d listed = (ListedMonodromy(op) - ListedMonodromy(om)) / (2 * h);
    EXPECT_LE((g.d_period[k] - period).cwiseAbs().maxCoeff(), 1e-6 * scale) << ov::Name(o.signature.size(), k);
    EXPECT_LE((g.d_listed[k] - listed).cwiseAbs().maxCoeff(), 1e-6 * scale) << ov::Name(o.signature.size(), k);
    // The transition matrices depend on chi and eta (eq. 55, 58); u_r enters no saltation matrix.
    const int chi = ov::Parameter(o.signature.size(), ParameterId::kChi);
    if (k == chi || k == chi + 1) {
      EXPECT_GT(g.d_period[k].cwiseAbs().maxCoeff(), 0.0);
    }
  }
}

// §4.1 without sticks (antisymmetric), §5.1 and §6 with (§6 antisymmetric).
INSTANTIATE_TEST_SUITE_P(PaperOrbits, MonodromyGradients, ::testing::Values("paper-4.1", "paper-5.1", "paper-6"),
                         [](const auto& test) { return std::string(test.param).substr(6, 1) + "_" + std::to_string(test.index); });

// A model sized at run time: the damped five-mass chain's stick-slip orbit (its motion settled at
// omega = 0.6), every variable but the belt's speed, over the period and over the listed half
// (the orbit is antisymmetric); the value is StabilityOf's monodromy.
TEST(MonodromyGradientsAtARunTimeSize, AreCentralDifferencesOfTheMonodromy) {
  const DynamicLinearOscillator model = FiveMassChain();
  const BasicOrbit<DynamicLinearOscillator> o = SettledOrbit(model, {0.6, 0.3, 0.4, 0.0}, 300);
  const BasicMonodromyGradient<Eigen::Dynamic> g = stickslip::MonodromyGradients(model, o);
  const Eigen::MatrixXd m = StabilityOf(model, o).monodromy;
  const double scale = 1.0 + m.cwiseAbs().maxCoeff();
  EXPECT_LE((g.period - m).cwiseAbs().maxCoeff(), 1e-13 * scale);
  EXPECT_LE((g.listed - ListedMonodromy(model, o)).cwiseAbs().maxCoeff(), 1e-13 * scale);
  const int count = model.StateSize() + o.signature.size() + DynamicLinearOscillator::kParameterCount - 1;
  double largest = 0.0;
  ASSERT_EQ(static_cast<int>(g.d_period.size()), count + 1);
  for (int k = 0; k < count; ++k) {
    const double h = 1e-6;
    const BasicOrbit<DynamicLinearOscillator> plus = PerturbedOrbit(model, o, k, h), minus = PerturbedOrbit(model, o, k, -h);
    const Eigen::MatrixXd period = (StabilityOf(model, plus).monodromy - StabilityOf(model, minus).monodromy) / (2 * h);
    const Eigen::MatrixXd listed = (ListedMonodromy(model, plus) - ListedMonodromy(model, minus)) / (2 * h);
    const std::size_t j = static_cast<std::size_t>(k);
    EXPECT_LE((g.d_period[j] - period).cwiseAbs().maxCoeff(), 1e-6 * scale) << "variable " << k;
    EXPECT_LE((g.d_listed[j] - listed).cwiseAbs().maxCoeff(), 1e-6 * scale) << "variable " << k;
    largest = std::max(largest, g.d_period[j].cwiseAbs().maxCoeff());
  }
  EXPECT_GT(largest, 1e-3 * scale) << "the monodromy depends on the orbit's variables";
}

}  // namespace
}  // namespace stickslip
