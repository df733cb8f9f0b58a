// Branches of the general linear oscillator through ContinueOrbit, the paper's model's path.
// The paper's branches in omega are continued twice: through the paper's model and through the
// general linear oscillator in physical units (support/pascal_in_physical_units.hpp). The two closed
// forms are independent (the paper's eqs. 2-11 in its scaled variables; the general model's
// first-order modal basis of M, K and the forcing in SI units), so the same special points at the
// same scaled frequency, with the same orbits there, check both and the model-free branch layer
// between them. A damped mass on a belt (autonomous) is continued in the belt's speed to the fold
// where its slip grazes the belt.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "stickslip/analysis/model_orbit_finder.hpp"
#include "stickslip/branches/model_boundary_curve.hpp"
#include "stickslip/branches/model_orbit_continuation.hpp"
#include "stickslip/orbits/signature_edits.hpp"
#include "support/belt_cycle.hpp"
#include "support/five_mass_chain.hpp"
#include "support/general_models.hpp"
#include "support/omega_setup.hpp"
#include "support/pascal_in_physical_units.hpp"
#include "support/solved_presets.hpp"
#include "support/test_names.hpp"

namespace stickslip {
namespace {

// A branch in omega from `start`, down or up, to 0.2 or 0.68 (short of omega1 = 0.70 of section
// 4.1, where a branch creeps on towards the resonance); `scale` the model's unit of frequency.
template <OscillatorModel Model>
BasicOrbitContinuationSetup<Model> OmegaBranch(OrbitOfModel<Model> start, Model model, int direction, double scale) {
  BasicOrbitContinuationSetup<Model> setup = OmegaSetup<Model>(std::move(start), std::move(model), 0.2, 0.68, scale, 1000);
  setup.options.direction = direction;
  return setup;
}

class PaperBranchThroughTheGeneralModel : public testing::TestWithParam<const char*> {};

TEST_P(PaperBranchThroughTheGeneralModel, HasTheSameSpecialPointsAtTheSameScaledFrequencies) {
  const Orbit paper = SolvedPreset(GetParam());
  const PhysicalTwoMasses physical;
  const double omega_scale = physical.Omega(paper.parameters), length = physical.Length(paper.parameters);
  double worst = 0.0;
  std::size_t compared = 0;
  for (int direction : {-1, 1}) {
    const OrbitContinuationSetup scaled = OmegaBranch<Pascal2014>(paper, {}, direction, 1.0);
    const BasicOrbitContinuationSetup<LinearOscillator<2>> general = OmegaBranch<LinearOscillator<2>>(
        InPhysicalUnits(paper, physical), LinearOscillator<2>(physical.Data(paper.parameters)), direction, omega_scale);
    const OrbitBranch a = ContinueOrbit(scaled);
    const BasicOrbitBranch<LinearOscillator<2>> b = ContinueOrbit(general);
    ASSERT_EQ(a.branch.end, b.branch.end) << a.branch.end_message << " | " << b.branch.end_message;
    ASSERT_EQ(a.branch.special_points.size(), b.branch.special_points.size()) << "direction " << direction;
    ASSERT_GE(a.branch.special_points.size(), 1u);
    for (std::size_t k = 0; k < a.branch.special_points.size(); ++k) {
      const SpecialPoint& p = a.branch.special_points[k];
      const SpecialPoint& q = b.branch.special_points[k];
      EXPECT_EQ(p.type, q.type) << "special point " << k;
      EXPECT_EQ(p.test_function, q.test_function) << "special point " << k;
      EXPECT_NEAR(q.lambda / omega_scale, p.lambda, 1e-8 * p.lambda) << p.type << ", direction " << direction;
      worst = std::max(worst, std::abs(q.lambda / omega_scale - p.lambda) / p.lambda);
      ++compared;
      const Orbit& o = a.orbits[p.point];
      const BasicOrbit<LinearOscillator<2>>& g = b.orbits[q.point];
      EXPECT_NEAR(g.start(0) / length, o.x10, 1e-7) << p.type;
      EXPECT_NEAR(g.start(1) / length, o.x20, 1e-7) << p.type;
      EXPECT_NEAR(g.durations.front() * omega_scale, o.durations.front(), 1e-7) << p.type;
    }
    RecordProperty(direction < 0 ? "down" : "up",
                   a.branch.special_points.back().type + " at " + std::to_string(a.branch.special_points.back().lambda));
  }
  RecordProperty("special_points", static_cast<int>(compared));
  RecordProperty("worst_relative_omega_difference", fmt::format("{:.3g}", worst));
}

INSTANTIATE_TEST_SUITE_P(PaperPresets, PaperBranchThroughTheGeneralModel,
                         testing::Values("paper-4.1", "paper-5.1", "paper-6"), PresetTestName);

// A curve in two parameters from the first special point of `type` on a branch in omega, with
// `second` released and user values at the scaled frequencies `omegas` (times `scale`).
template <OscillatorModel Model>
BasicOrbitBranch<Model> CurveFrom(const BasicOrbitContinuationSetup<Model>& setup, const char* type, const char* second,
                                  const std::vector<double>& omegas, double scale) {
  const BasicOrbitBranch<Model> branch = ContinueOrbit(setup);
  const auto special = std::find_if(branch.branch.special_points.begin(), branch.branch.special_points.end(),
                                    [&](const SpecialPoint& s) { return s.type == type && s.located; });
  if (special == branch.branch.special_points.end()) throw std::runtime_error(std::string("no ") + type);
  const std::string condition = CurveCondition(type, special->test_function);
  const BasicCurveStart<Model> start{branch.orbits[special->point], condition, "omega", setup.unknowns};
  BasicOrbitContinuationSetup<Model> curve = BoundaryCurve(start, setup, second);
  const OrbitVariableSet variables = VariableSetOf(curve.model, AsBasicOrbit(start.orbit).signature);
  const int omega = static_cast<int>(FreeIndices(variables, curve.unknowns).size());
  curve.options.direction = omegas.front() * scale < special->lambda ? -1 : 1;
  curve.options.max_points = 2000;
  curve.options.step.ds = 0.002 * scale;
  curve.options.step.ds_max = 0.01 * scale;
  for (double w : omegas) curve.options.user_values.push_back({omega, w * scale, fmt::format("omega={}", w)});
  // From the start to a little past the last user value.
  curve.options.lambda_min = std::min(special->lambda, omegas.back() * scale * 0.999);
  curve.options.lambda_max = std::max(special->lambda, omegas.back() * scale * 1.001);
  return ContinueOrbit(curve);
}

// The same two-parameter curves through the paper's model and the general one in physical units:
// the section 4.1 boundary where the nonsticking orbit's stops start to stick (its reversal margin
// = 0, in (omega, u_r) and (omega, F_s)) and the section 5.1 fold curve (a multiplier +1). At the
// same scaled frequencies (user values) the static levels and orbits agree after the paper's
// scaling: the margin and Floquet conditions of both closed forms, through the model-free curve
// layer.
TEST(PaperCurvesThroughTheGeneralModel, AgreeAtTheSameScaledFrequencies) {
  struct Case {
    const char* preset;
    int direction;
    const char* type;
    std::vector<double> omegas;
  };
  double worst = 0.0;
  for (const Case& c : {Case{"paper-4.1", -1, "SK", {0.58, 0.55, 0.5}}, Case{"paper-5.1", 1, "LP", {0.58, 0.575, 0.57}}}) {
    SCOPED_TRACE(c.preset);
    const Orbit paper = SolvedPreset(c.preset);
    const PhysicalTwoMasses physical;
    const double scale = physical.Omega(paper.parameters), length = physical.Length(paper.parameters);
    const double force = paper.parameters.eta * physical.f0;
    const OrbitBranch a = CurveFrom(OmegaBranch<Pascal2014>(paper, {}, c.direction, 1.0), c.type, "u_r", c.omegas, 1.0);
    const BasicOrbitBranch<LinearOscillator<2>> b = CurveFrom(
        OmegaBranch<LinearOscillator<2>>(InPhysicalUnits(paper, physical), LinearOscillator<2>(physical.Data(paper.parameters)),
                                         c.direction, scale),
        c.type, "F_s", c.omegas, scale);
    std::vector<const SpecialPoint*> uz_a, uz_b;
    for (const SpecialPoint& s : a.branch.special_points) if (s.type == "UZ") uz_a.push_back(&s);
    for (const SpecialPoint& s : b.branch.special_points) if (s.type == "UZ") uz_b.push_back(&s);
    ASSERT_EQ(uz_a.size(), c.omegas.size()) << a.branch.end_message;
    ASSERT_EQ(uz_b.size(), c.omegas.size()) << b.branch.end_message;
    for (std::size_t k = 0; k < uz_a.size(); ++k) {
      const Orbit& o = a.orbits[uz_a[k]->point];
      const BasicOrbit<LinearOscillator<2>>& g = b.orbits[uz_b[k]->point];
      EXPECT_NEAR(g.parameters.omega / scale, o.parameters.omega, 1e-12);
      EXPECT_NEAR(g.parameters.F_s / force, o.parameters.u_r, 1e-11) << "omega = " << o.parameters.omega;
      EXPECT_NEAR(g.start(0) / length, o.x10, 1e-7);
      EXPECT_NEAR(g.durations.front() * scale, o.durations.front(), 1e-7);
      worst = std::max(worst, std::abs(g.parameters.F_s / force - o.parameters.u_r));
    }
  }
  RecordProperty("worst_static_level_difference", fmt::format("{:.3g}", worst));
}

// A mass on a belt with viscous damping (m = k = 1, c = 0.1, no forcing: autonomous, the period
// the durations' sum) and F_s = 1.5 > F_k = 1: its stick-slip cycle, continued in the belt's speed
// from the undamped closed form's guess at v_b = 0.2 (tests/orbits/belt_orbit_test.cpp), does not
// lose its stick as the belt speeds up. Its slip arc becomes tangent to s = 0 at the re-stick (the
// stop's slope margin, NS) exactly where the family folds (LP, the engine's tangent test): near
// v_b = 0.549 with the stick still 0.91 long (../shared/FRICTION-LITERATURE.md, issue 23).
TEST(BeltStickSlipBranch, DampedFamilyEndsWhereItsSlipGrazesTheBeltInAFold) {
  const BeltCycle belt;  // m = k = 1, F_s = 1.5, F_k = 1, v_b = 0.2
  BasicOrbitContinuationSetup<LinearOscillator<1>> setup =
      OmegaBranch<LinearOscillator<1>>(belt.Orbit(), LinearOscillator<1>(belt.Data(0.1)), 1, 1.0);
  setup.parameter = "v_b";
  setup.options.lambda_min = 0.01;
  setup.options.lambda_max = 2.0;
  const BasicOrbitBranch<LinearOscillator<1>> result = ContinueOrbit(setup);
  const Branch& branch = result.branch;
  ASSERT_EQ(branch.end, BranchEnd::kTerminalEvent) << branch.end_message;
  auto find = [&](const char* type) {
    const auto s = std::find_if(branch.special_points.begin(), branch.special_points.end(),
                                [&](const SpecialPoint& p) { return p.type == type; });
    EXPECT_NE(s, branch.special_points.end()) << type;
    return s == branch.special_points.end() ? SpecialPoint{} : *s;
  };
  const SpecialPoint graze = find("NS"), fold = find("LP");
  EXPECT_EQ(graze.test_function, "margin:stop-slope:2");
  EXPECT_NEAR(graze.lambda, 0.549, 0.005);
  EXPECT_NEAR(result.orbits[graze.point].durations[0], 0.91, 0.01);
  EXPECT_NEAR(fold.lambda, graze.lambda, 1e-8);
  RecordProperty("grazing_belt_speed", fmt::format("{:.10g}", graze.lambda));
  RecordProperty("fold_belt_speed", fmt::format("{:.10g}", fold.lambda));
  RecordProperty("stick", fmt::format("{:.10g}", result.orbits[graze.point].durations[0]));
}

// An antisymmetric orbit (its second half the mirror -X of its first) is a motion only on a fixed
// surface: the five-mass chain's 'stick slip+ / antisymmetric' at v_b = 0 is refused as a start in
// the belt's speed; written over its whole period it is continued, and at v_b = 0.05 its orbit,
// no longer symmetric (its two sticks differ), is a motion both simulators follow.
TEST(BeltSpeedBranch, TakesAnAntisymmetricStartOnlyWrittenOverItsWholePeriod) {
  using Model = DynamicLinearOscillator;
  const Model model = FiveMassChain();
  const BasicOrbit<Model> settled = SettledOrbit(model, {0.6, 0.3, 0.4, 0.0}, 300);
  ASSERT_TRUE(settled.signature.antisymmetric()) << settled.signature.ToString();
  BasicOrbitContinuationSetup<Model> setup = OmegaSetup<Model>(settled, model, -1.0, 1.0, 1.0, 200);
  setup.parameter = "v_b";
  try {
    ContinueOrbit(setup);
    ADD_FAILURE() << "an antisymmetric start was continued in v_b";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.field(), "parameter") << e.what();
  }
  setup.start = Unfolded(settled, 1);
  setup.options.lambda_min = 0.0;
  setup.options.lambda_max = 0.05;
  const BasicOrbitBranch<Model> branch = ContinueOrbit(setup);
  ASSERT_EQ(branch.branch.end, BranchEnd::kParameterBound) << branch.branch.end_message;
  const BasicOrbit<Model>& moving = branch.orbits.back();
  EXPECT_EQ(moving.signature.ToString(), "stick slip+ stick slip-");
  EXPECT_GT(std::abs(moving.durations[0] - moving.durations[2]), 0.01) << "the sticks of a moving surface differ";
  const Verification v = VerifyByBothSimulators(model, moving);
  EXPECT_TRUE(v.Passed()) << v.Report();
}

}  // namespace
}  // namespace stickslip

