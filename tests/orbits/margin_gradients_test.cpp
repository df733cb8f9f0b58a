// Margin gradients against central differences of the margins themselves (which find interior
// minima by root finding, independently of the envelope theorem the gradients use), on every
// paper orbit and on random orbits that cover every end kind.
#include "stickslip/orbits/margin_gradients.hpp"

#include <cmath>
#include <set>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "support/den_hartog_orbit.hpp"
#include "support/den_hartog_oscillator.hpp"
#include "support/five_mass_chain.hpp"
#include "support/perturbed_orbit.hpp"
#include "support/random_orbits.hpp"
#include "support/solved_presets.hpp"

namespace stickslip {
namespace {

namespace ov = orbit_variables;

// Central difference of every margin's value and time along variable `index`.
struct Differences {
  std::vector<double> value;
  std::vector<double> t;
};
Differences CentralDifferences(const Orbit& orbit, int index) {
  const Eigen::VectorXd v = ov::Pack(orbit);
  const double h = 1e-6 * std::max(1.0, std::abs(v(index)));
  Eigen::VectorXd plus = v, minus = v;
  plus(index) += h;
  minus(index) -= h;
  const std::vector<Margin> up = AdmissibilityMargins(ov::Unpack(orbit.signature, plus));
  const std::vector<Margin> down = AdmissibilityMargins(ov::Unpack(orbit.signature, minus));
  Differences d;
  for (std::size_t k = 0; k < up.size(); ++k) {
    d.value.push_back((up[k].value - down[k].value) / (2 * h));
    d.t.push_back((up[k].t - down[k].t) / (2 * h));
  }
  return d;
}

// Checks every finite margin's gradient and time gradient; returns the kinds it checked.
std::set<std::string> ExpectGradientsMatchDifferences(const Orbit& orbit) {
  const std::vector<Margin> margins = AdmissibilityMargins(orbit);
  const std::vector<MarginGradient> gradients = MarginGradients(orbit);
  EXPECT_EQ(gradients.size(), margins.size());
  std::set<std::string> checked;
  const int count = ov::Count(orbit.signature.size());
  for (int index = 0; index < count; ++index) {
    const Differences fd = CentralDifferences(orbit, index);
    for (std::size_t k = 0; k < margins.size(); ++k) {
      if (!std::isfinite(margins[k].value)) continue;
      const MarginGradient& g = gradients[k];
      EXPECT_NEAR(g.value, margins[k].value, 1e-12 * std::max(1.0, std::abs(margins[k].value)));
      EXPECT_NEAR(g.d_value(index), fd.value[k], 1e-6 * std::max(1.0, std::abs(fd.value[k])))
          << margins[k].Name() << " d/d" << ov::Name(orbit.signature.size(), index) << " on "
          << orbit.signature.ToString();
      EXPECT_NEAR(g.d_t(index), fd.t[k], 1e-5 * std::max(1.0, std::abs(fd.t[k])))
          << "time of " << margins[k].Name() << " d/d" << ov::Name(orbit.signature.size(), index);
      checked.insert(std::string(ToString(margins[k].kind)) + (g.interior ? " (interior)" : ""));
    }
  }
  for (const MarginGradient& g : gradients) {
    if (!g.interior) continue;
    EXPECT_NEAR(g.slope, 0.0, 1e-8);  // the time derivative vanishes at an interior minimum
    EXPECT_GT(g.curvature, 0.0);
  }
  return checked;
}

TEST(MarginGradients, MatchCentralDifferencesOnEveryPaperOrbit) {
  std::set<std::string> kinds;
  for (const char* name : {"paper-4.1", "paper-4.2", "paper-5.1", "paper-5.2", "paper-6"}) {
    SCOPED_TRACE(name);
    kinds.merge(ExpectGradientsMatchDifferences(SolvedPreset(name)));
  }
  // The paper's orbits have stops of every kind and sticks ending both ways.
  for (const char* kind : {"duration", "stop-slope", "stop-force", "stick-constraint", "exit-slope", "friction-level"}) {
    EXPECT_TRUE(kinds.count(kind)) << kind;
  }
}

// Orbits need not be periodic for their margins to be defined: random variables on signatures
// that hold every end kind (abnormal stop, reversal, stick entry, exits into slip+ and slip-)
// give interior minima of x2' and of G, G1 too.
TEST(MarginGradients, MatchCentralDifferencesOnRandomOrbitsOfEveryEndKind) {
  std::set<std::string> kinds;
  for (const RandomOrbit& r : RandomOrbitsOfEveryEndKind(6)) {
    SCOPED_TRACE(r.label);
    kinds.merge(ExpectGradientsMatchDifferences(r.orbit));
  }
  for (const char* kind : {"slip-velocity (interior)", "stick-constraint (interior)", "stick-constraint", "stop-force",
                           "stop-slope", "exit-slope"}) {
    EXPECT_TRUE(kinds.count(kind)) << kind;
  }
}

template <typename Model>
std::set<std::string> ExpectModelGradientsMatchDifferences(const Model& model, const BasicOrbit<Model>& orbit) {
  const std::vector<Margin> margins = AdmissibilityMargins(model, orbit);
  const std::vector<MarginGradient> gradients = MarginGradients(model, orbit);
  EXPECT_EQ(gradients.size(), margins.size());
  std::set<std::string> checked;
  // The belt's speed (the rest velocity) is left out: the contact's start velocity follows it.
  const int count = model.StateSize() + orbit.signature.size() + Model::kParameterCount - 1;
  for (int index = 0; index < count; ++index) {
    const double h = 1e-6;
    const std::vector<Margin> up = AdmissibilityMargins(model, PerturbedOrbit(model, orbit, index, h));
    const std::vector<Margin> down = AdmissibilityMargins(model, PerturbedOrbit(model, orbit, index, -h));
    for (std::size_t k = 0; k < margins.size(); ++k) {
      if (!std::isfinite(margins[k].value)) continue;
      const double fd = (up[k].value - down[k].value) / (2 * h);
      EXPECT_NEAR(gradients[k].value, margins[k].value, 1e-12 * std::max(1.0, std::abs(margins[k].value)));
      EXPECT_NEAR(gradients[k].d_value(index), fd, 1e-6 * std::max(1.0, std::abs(fd)))
          << margins[k].Name() << " along variable " << index << " on " << orbit.signature.ToString();
      EXPECT_NEAR(gradients[k].d_t(index), (up[k].t - down[k].t) / (2 * h), 1e-5 * std::max(1.0, std::abs(fd)))
          << "time of " << margins[k].Name() << " along variable " << index;
      checked.insert(std::string(ToString(margins[k].kind)) + (gradients[k].interior ? " (interior)" : ""));
    }
  }
  return checked;
}

// Den Hartog's orbits with interior minima of the slip velocity (margins_test.cpp), and an orbit
// with sticks ending both ways (not periodic: its margins are defined all the same).
TEST(MarginGradients, MatchCentralDifferencesForTheTestModel) {
  std::set<std::string> kinds;
  for (const auto& [r, beta] : {std::pair{0.3, 0.05}, std::pair{0.38, 0.1}}) {
    kinds.merge(ExpectModelGradientsMatchDifferences(
        DenHartogModel(), DenHartogOnSignature(DenHartogOrbit(r, beta), "slip- slip+", beta)));
  }
  const BasicOrbit<DenHartogOscillator> sticking{
      Signature::Parse("slip- stick slip+ stick"), {0.7, 0.2, 0.3}, {1.0, 0.0}, 0.3, {2.0, 0.5, 2.5, 0.7}};
  kinds.merge(ExpectModelGradientsMatchDifferences(DenHartogModel(), sticking));
  for (const char* kind : {"duration", "slip-velocity (interior)", "stop-slope", "stop-force", "stick-constraint",
                           "exit-slope", "friction-level"}) {
    EXPECT_TRUE(kinds.count(kind)) << kind;
  }
}

// A model sized at run time: the damped five-mass chain (support/five_mass_chain.hpp) on the
// stick-slip orbit its motion settles on at omega = 0.6, and the same orbit's point (not
// periodic, its margins defined all the same) with the stick twice as long.
TEST(MarginGradients, MatchCentralDifferencesAtARunTimeSize) {
  const DynamicLinearOscillator model = FiveMassChain();
  BasicOrbit<DynamicLinearOscillator> orbit = SettledOrbit(model, {0.6, 0.3, 0.4, 0.0}, 300);
  std::set<std::string> kinds = ExpectModelGradientsMatchDifferences(model, orbit);
  orbit.durations[0] *= 2.0;
  kinds.merge(ExpectModelGradientsMatchDifferences(model, orbit));
  for (const char* kind : {"duration", "stop-slope", "stick-constraint", "exit-slope"}) {
    EXPECT_TRUE(kinds.count(kind)) << kind;
  }
}

}  // namespace
}  // namespace stickslip
