// Traces of models other than the paper's through TraceOrbits (branches/model_trace.hpp), the
// paper's model's path: its type switches (each confirmed by the model's exact simulator), least
// periods and bifurcation branches, with nothing of the paper's model in between.
//   - Den Hartog's one mass (support/den_hartog_oscillator.hpp), traced in the friction level from
//     his non-sticking orbit: the first branch ends where the turning points start to stick, at his
//     closed-form level beta* (FRICTION-LITERATURE.md), and the chain goes on as a sticking orbit
//     that both simulators, the exact and the Odeint one, follow over a period.
//   - One mass on a moving belt, no forcing (autonomous), traced in the belt's speed: undamped,
//     every orbit is the closed-form stick-slip cycle; damped, the trace ends at the fold where the
//     slip grazes the belt, with the stick still finite.
//   - The paper's two masses in physical units as the general linear oscillator
//     (support/pascal_in_physical_units.hpp), traced over the forcing frequency from section 4.1's
//     orbit: the same chain as the paper's model's (signatures, how each branch began and ended, the
//     margin switched at) with its ends at the same scaled frequencies. The two closed forms are
//     independent (the paper's eqs. 2-11 in scaled variables; a first-order modal basis in SI units).
//     The same at a size read with the data (DynamicLinearOscillator, a model from a file).
//   - Five masses in a chain, damped, sized at run time (support/five_mass_chain.hpp), traced over
//     the forcing frequency from the orbit its simulated motion settles on: orbits along every link
//     are motions that both simulators follow.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "stickslip/analysis/model_orbit_finder.hpp"
#include "stickslip/branches/model_trace.hpp"
#include "stickslip/model/exact_simulator.hpp"
#include "stickslip/model/odeint_simulation.hpp"
#include "stickslip/orbits/verification.hpp"
#include "support/belt_cycle.hpp"
#include "support/den_hartog_orbit.hpp"
#include "support/den_hartog_oscillator.hpp"
#include "support/five_mass_chain.hpp"
#include "support/general_models.hpp"
#include "support/omega_setup.hpp"
#include "support/pascal_in_physical_units.hpp"
#include "support/solved_presets.hpp"
#include "support/test_names.hpp"

namespace stickslip {
namespace {

template <OscillatorModel Model>
std::string Describe(const BasicTraceResult<Model>& trace) {
  std::string text;
  for (const BasicTraceDirection<Model>* chain : {&trace.down, &trace.up}) {
    text += fmt::format("{}: {} ({})\n", chain->direction > 0 ? "up" : "down", ToString(chain->end), chain->message);
    for (const BasicTraceLink<Model>& link : chain->links) {
      text += fmt::format("  '{}' from {} at '{}': {} points, {:.10g} to {:.10g}: {} ({})\n", link.signature,
                          ToString(link.start), link.margin, link.branch.orbits.size(),
                          link.branch.branch.points.front().lambda, link.branch.branch.points.back().lambda,
                          ToString(link.end), link.message);
    }
  }
  return text;
}

// Den Hartog's level beta* = |V| / sqrt(U^2 + 1/r^4), where r^2 X = beta: the turning points of his
// non-sticking orbit start to stick.
double StickingLevel(double r) {
  const DenHartogOrbit o(r, 0.0);
  return std::abs(o.v) / std::sqrt(o.u * o.u + 1.0 / std::pow(r, 4));
}

TEST(TraceOfDenHartogsOscillator, SwitchesToASimulatedStickingOrbitAtTheClosedFormStickingLevel) {
  const double r = 1.5, beta = 0.05;
  const DenHartogOrbit o(r, beta);
  BasicOrbitContinuationSetup<DenHartogOscillator> setup{
      {Signature::Parse("slip- / antisymmetric"), {r, beta, beta, 0.0}, {o.amplitude, 0.0}, o.phi, {o.Period() / 2}},
      {}, "F_k", ShootingChoice::kAuto, LinearSolverType::kKlu, {}, {}, {}, {}, kDefaultMaxAmplitude,
      kDefaultResonanceApproach, DenHartogModel()};
  setup.unknowns.tie_static_friction = true;
  setup.options.lambda_min = 0.01;
  setup.options.lambda_max = 0.9;
  setup.options.max_points = 400;
  TraceOptions options;
  options.max_branches = 4;
  const BasicTraceResult<DenHartogOscillator> trace = TraceOrbits(setup, options);
  SCOPED_TRACE(Describe(trace));
  EXPECT_EQ(trace.down.end, TraceEnd::kParameterBound);
  ASSERT_GE(trace.up.links.size(), 2u);
  const BasicTraceLink<DenHartogOscillator>& slipping = trace.up.links[0];
  const BasicTraceLink<DenHartogOscillator>& sticking = trace.up.links[1];
  EXPECT_EQ(slipping.end, TraceEnd::kSwitched);
  EXPECT_NEAR(slipping.branch.orbits.back().parameters.F_k, StickingLevel(r), 1e-8);
  EXPECT_EQ(sticking.start, LinkStart::kSwitch);
  ASSERT_TRUE(sticking.type_switch.has_value());
  EXPECT_EQ(sticking.type_switch->status, TypeSwitchStatus::kConfirmed);
  EXPECT_NE(sticking.signature.find("stick"), std::string::npos) << sticking.signature;
  EXPECT_EQ(sticking.direction, 1) << "friction growing, the stick grows";
  RecordProperty("sticking_level_difference",
                 fmt::format("{:.3g}", slipping.branch.orbits.back().parameters.F_k - StickingLevel(r)));
  // Every few points of the sticking branch, as both simulators follow it.
  const auto& orbits = sticking.branch.orbits;
  ASSERT_GE(orbits.size(), 3u);
  for (std::size_t k = 1; k < orbits.size(); k += std::max<std::size_t>(1, orbits.size() / 5)) {
    const Verification v = VerifyByBothSimulators(DenHartogModel(), orbits[k]);
    EXPECT_TRUE(v.Passed()) << "point " << k << " at F_k = " << orbits[k].parameters.F_k << "\n" << v.Report();
  }
}

// At both sizes: fixed at compile time (LinearOscillator<2>) and read with the data
// (DynamicLinearOscillator, a model from a file).
template <typename Model>
class TraceOfTheGeneralModel : public testing::Test {};
using GeneralModelSizes = testing::Types<LinearOscillator<2>, DynamicLinearOscillator>;
TYPED_TEST_SUITE(TraceOfTheGeneralModel, GeneralModelSizes, ModelSizeName);

TYPED_TEST(TraceOfTheGeneralModel, FollowsThePaperModelsSection41ChainAtTheSameScaledFrequencies) {
  using Model = TypeParam;
  const Orbit paper = SolvedPreset("paper-4.1");
  const PhysicalTwoMasses physical;
  const double scale = physical.Omega(paper.parameters);
  TraceOptions options;
  options.max_branches = 6;
  const TraceResult scaled = TraceOrbits(OmegaSetup<Pascal2014>(paper, {}, 0.3, 0.69, 1.0, 3000), options);
  const BasicTraceResult<Model> general = TraceOrbits(
      OmegaSetup<Model>(InPhysicalUnits<Model>(paper, physical), Model(physical.Data(paper.parameters)), 0.3, 0.69,
                        scale, 3000),
      options);
  SCOPED_TRACE("the paper's model:\n" + Describe(scaled) + "the general model:\n" + Describe(general));
  double worst = 0.0;
  int links = 0;
  for (const auto& [a, b] : {std::pair{&scaled.down, &general.down}, std::pair{&scaled.up, &general.up}}) {
    EXPECT_EQ(a->end, b->end);
    ASSERT_EQ(a->links.size(), b->links.size());
    for (std::size_t k = 0; k < a->links.size(); ++k) {
      const TraceLink& p = a->links[k];
      const BasicTraceLink<Model>& q = b->links[k];
      EXPECT_EQ(p.signature, q.signature) << "link " << k;
      EXPECT_EQ(p.start, q.start) << "link " << k;
      EXPECT_EQ(p.margin, q.margin) << "link " << k;
      EXPECT_EQ(p.end, q.end) << "link " << k;
      const double end = p.branch.branch.points.back().lambda;
      const double general_end = q.branch.branch.points.back().lambda / scale;
      EXPECT_NEAR(general_end, end, 1e-8 * end) << "link " << k;
      worst = std::max(worst, std::abs(general_end - end) / end);
      ++links;
    }
  }
  EXPECT_GE(links, 3);
  this->RecordProperty("links", links);
  this->RecordProperty("worst_relative_end_difference", fmt::format("{:.3g}", worst));
}

// One mass on a belt, no forcing (autonomous: the period is the durations' sum): m = k = 1,
// F_s = 1.5, F_k = 1, from its stick-slip orbit at v_b = 0.2, traced in the belt's speed.
BasicOrbitContinuationSetup<LinearOscillator<1>> BeltTrace(double damping, double low, double high) {
  const BeltCycle belt;
  BasicOrbitContinuationSetup<LinearOscillator<1>> setup =
      OmegaSetup<LinearOscillator<1>>(belt.Orbit(), LinearOscillator<1>(belt.Data(damping)), low, high, 1.0, 1000);
  setup.parameter = "v_b";
  return setup;
}

// Undamped, every orbit of the trace is the closed form (FRICTION-LITERATURE.md: T_stick =
// 2 (F_s - F_k)/(k v_b), T_slip = (pi + 2 atan(v_b/(omega_n d)))/omega_n), and the trace ends at the
// range's bounds both ways, one branch each.
TEST(TraceOfAMassOnABelt, UndampedFollowsTheClosedFormStickSlipCycleToTheBounds) {
  const BasicTraceResult<LinearOscillator<1>> trace = TraceOrbits(BeltTrace(0.0, 0.1, 1.0));
  SCOPED_TRACE(Describe(trace));
  EXPECT_EQ(trace.down.end, TraceEnd::kParameterBound);
  EXPECT_EQ(trace.up.end, TraceEnd::kParameterBound);
  double worst = 0.0;
  int orbits = 0;
  for (const BasicTraceDirection<LinearOscillator<1>>* chain : {&trace.down, &trace.up}) {
    ASSERT_EQ(chain->links.size(), 1u);
    for (const BasicOrbit<LinearOscillator<1>>& o : chain->links[0].branch.orbits) {
      BeltCycle belt;
      belt.v_b = o.parameters.v_b;
      worst = std::max({worst, std::abs(o.durations[0] - belt.Stick()), std::abs(o.durations[1] - belt.Slip())});
      ++orbits;
    }
  }
  EXPECT_LE(worst, 1e-9);
  EXPECT_GT(orbits, 10);
  RecordProperty("worst_duration_difference", fmt::format("{:.3g}", worst));
}

// Damped (c = 0.1), the stick does not vanish as the belt speeds up: the slip grazes the belt
// (the stop becomes tangential) and the family folds there with its stick still finite, near
// v_b = 0.549 with a stick of 0.91 (the general-oscillator issue's figures): the trace ends there,
// no type past it; every orbit on the way is a motion both simulators follow.
TEST(TraceOfAMassOnABelt, DampedEndsAtTheFoldWhereTheSlipGrazesTheBelt) {
  const BasicTraceResult<LinearOscillator<1>> trace = TraceOrbits(BeltTrace(0.1, 0.1, 2.0));
  SCOPED_TRACE(Describe(trace));
  ASSERT_EQ(trace.up.links.size(), 1u);
  const BasicTraceLink<LinearOscillator<1>>& up = trace.up.links[0];
  EXPECT_EQ(trace.up.end, TraceEnd::kNoAdjacentType);
  EXPECT_TRUE(up.message.starts_with("stop-slope:2")) << up.message;
  const BasicOrbit<LinearOscillator<1>>& fold = up.branch.orbits.back();
  EXPECT_NEAR(fold.parameters.v_b, 0.549, 0.005);
  EXPECT_NEAR(fold.durations[0], 0.91, 0.01);
  const LinearOscillator<1> model = BeltTrace(0.1, 0.1, 2.0).model;
  for (std::size_t k = 0; k + 1 < up.branch.orbits.size(); k += 10) {
    const Verification v = VerifyByBothSimulators(model, up.branch.orbits[k]);
    EXPECT_TRUE(v.Passed()) << "v_b = " << up.branch.orbits[k].parameters.v_b << "\n" << v.Report();
  }
  RecordProperty("fold_belt_speed", fmt::format("{:.10g}", fold.parameters.v_b));
}

// A trace switches types by nudging the continued variable as a parameter of the model: a held
// start variable or duration is refused by name before anything is traced (it used to be refused
// at the first change of type, every branch traced so far lost).
TEST(TraceOfAMassOnABelt, RefusesAContinuedVariableThatIsNoParameter) {
  BasicOrbitContinuationSetup<LinearOscillator<1>> setup = BeltTrace(0.0, 0.1, 1.0);
  setup.parameter = "x10";
  setup.unknowns.fix = {"x10"};
  setup.unknowns.release = {"v_b"};
  try {
    TraceOrbits(setup);
    ADD_FAILURE() << "traced in x10";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.field(), "parameter") << e.what();
  }
}

// The trace of the five-mass chain over the forcing frequency from the orbit its motion settles on
// at omega = 0.6: orbits along every link are motions that both simulators follow over a period
// (the Odeint one integrates M q'' + C q' + K q = g cos + F, sharing no flow or event code with the
// closed forms; a link's ends, where a segment vanishes or a stop grazes, are left out: there the
// sequence a simulator sees is decided by rounding); the trace leaves its start both ways and,
// damped, crosses the chain's natural frequency 0.83 with a bounded amplitude to the range's top.
TEST(TraceOfAFiveMassChain, FollowsOrbitsBothSimulatorsConfirmAcrossTypeChanges) {
  const DynamicLinearOscillator model = FiveMassChain();
  ASSERT_EQ(model.StateSize(), 10);
  const BasicOrbit<DynamicLinearOscillator> guess = SettledOrbit(model, {0.6, 0.3, 0.4, 0.0}, 300);
  TraceOptions options;
  options.max_branches = 4;
  const BasicTraceResult<DynamicLinearOscillator> trace =
      TraceOrbits(OmegaSetup<DynamicLinearOscillator>(guess, model, 0.4, 1.2, 1.0, 2000), options);
  SCOPED_TRACE("from '" + guess.signature.ToString() + "':\n" + Describe(trace));
  int verified = 0;
  for (const BasicTraceDirection<DynamicLinearOscillator>* chain : {&trace.down, &trace.up}) {
    ASSERT_FALSE(chain->links.empty());
    EXPECT_GT(chain->links.front().branch.orbits.size(), 2u);
    for (const BasicTraceLink<DynamicLinearOscillator>& link : chain->links) {
      const std::vector<BasicOrbit<DynamicLinearOscillator>>& orbits = link.branch.orbits;
      EXPECT_GE(orbits.size(), 3u) << "'" << link.signature << "': too short to check inside";
      const std::size_t step = std::max<std::size_t>(1, orbits.size() / 6);
      for (std::size_t k = 1; k + 1 < orbits.size(); k += step) {
        const Verification v = VerifyByBothSimulators(model, orbits[k]);
        EXPECT_TRUE(v.Passed()) << "'" << link.signature << "' at omega = " << orbits[k].parameters.omega << "\n"
                                << v.Report();
        ++verified;
      }
    }
  }
  EXPECT_GE(trace.up.links.size(), 2u) << "no change of type";
  EXPECT_EQ(trace.up.end, TraceEnd::kParameterBound);
  EXPECT_GE(verified, 12);
  RecordProperty("verified_orbits", verified);
}

}  // namespace
}  // namespace stickslip
