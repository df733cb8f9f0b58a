// The atlas of an oscillator of the user's (analysis/model_atlas.hpp), checked against what does not
// share its code: the paper's own atlas (closed forms of the 2x2 problem, its own brute force and
// finder) for M. Pascal's two masses written in other physical units; Den Hartog's closed-form
// non-sticking orbit; the closed-form stick-slip cycle of a mass on a belt.
#include "stickslip/analysis/model_atlas.hpp"

#include "stickslip/analysis/atlas.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "stickslip/branches/model_branch_membership.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/orbits/segment_walk.hpp"
#include "stickslip/orbits/signature_edits.hpp"
#include "support/belt_cycle.hpp"
#include "support/den_hartog_orbit.hpp"
#include "support/den_hartogs_mass.hpp"
#include "support/pascal_in_physical_units.hpp"
#include "support/solved_presets.hpp"

namespace stickslip {
namespace {

using Model = DynamicLinearOscillator;

// Every located special point of the branches but their ends, by kind and parameter.
template <typename Branches>
std::vector<std::pair<std::string, double>> SpecialPointsOf(const Branches& branches, double unit) {
  std::vector<std::pair<std::string, double>> points;
  for (const auto* b : branches) {
    for (const SpecialPoint& s : b->branch.special_points) {
      if (s.type != "EP" && s.located) points.emplace_back(s.type, s.lambda / unit);
    }
  }
  return points;
}

// Section 4.1's data over omega in [0.55, 0.65] (the paper atlas test's): its period-3 families, the
// fold, the grazing at 0.5999775 where several margins vanish together.
TEST(ModelAtlas, FindsThePapersBifurcationsInOtherPhysicalUnits) {
  const Parameters paper = SolvedPreset("paper-4.1").parameters;
  AtlasOptions po;
  po.brute_force.first = {ParameterId::kOmega, 0.55, 0.65, 4};
  po.brute_force.transient_periods = 300;
  po.brute_force.scattered_starts = 2;
  const Atlas reference = ComputeAtlas(paper, po);
  // The same masses with m2 = 2 kg, k1 + k2 = 5 N/m, a 3 N force: time and lengths scaled.
  const PhysicalTwoMasses physical;
  const Model model(physical.Data(paper));
  const double unit = physical.Omega(paper);
  ModelAtlasOptions o;
  o.parameter = "omega";
  o.from = 0.55 * unit;
  o.to = 0.65 * unit;
  o.steps = 4;
  // More starts than the paper's atlas takes: which attractors a brute force meets depends on its
  // starts, and these are drawn in other units.
  o.brute_force.scattered_starts = 8;
  o.brute_force.scatter = physical.Length(paper);
  const ModelAtlas atlas = ComputeModelAtlas(model, physical.Of<Model>(paper), o);
  ASSERT_GT(atlas.OnBranches(), 0);
  EXPECT_EQ(atlas.OnBranches(), atlas.PeriodicWithinLimit());
  const auto found = SpecialPointsOf(atlas.Branches(), unit);
  const auto expected = SpecialPointsOf(reference.Branches(), 1.0);
  ASSERT_FALSE(found.empty());
  // Every special point the model's atlas locates, the paper's locates too (in omega / Omega).
  for (const auto& point : found) {
    const bool matched = std::any_of(expected.begin(), expected.end(), [&](const auto& e) {
      return e.first == point.first && std::abs(e.second - point.second) <= 1e-8;
    });
    EXPECT_TRUE(matched) << point.first << " at omega = " << point.second;
  }
  // And the other way: every special point of the paper's atlas (whose mirror-image traces the
  // model's atlas replaces by its scattered starts).
  for (const auto& point : expected) {
    const bool matched = std::any_of(found.begin(), found.end(), [&](const auto& f) {
      return f.first == point.first && std::abs(f.second - point.second) <= 1e-8;
    });
    EXPECT_TRUE(matched) << "the paper's " << point.first << " at omega = " << point.second;
  }
  // The fold of the period-3 family (0.6011956) and the grazing where its stick vanishes (0.5999775).
  for (const char* type : {"LP", "GR"}) {
    EXPECT_TRUE(std::any_of(found.begin(), found.end(), [&](const auto& f) { return f.first == type; })) << type;
  }
}

// Den Hartog's undamped mass above resonance (beta = 0.25): one attractor per grid value, his
// non-sticking orbit, on one branch whose amplitude is his closed form all along.
TEST(ModelAtlas, TracesDenHartogsOrbitWithItsClosedFormAmplitude) {
  const Model model = DenHartogsMass();
  ModelAtlasOptions o;
  o.parameter = "omega";
  o.from = 1.3;
  o.to = 2.5;
  o.steps = 6;
  o.brute_force.threads = 2;
  const ModelAtlas atlas = ComputeModelAtlas(model, {1.5, 0.25, 0.25, 0.0}, o);
  ASSERT_EQ(atlas.attractors.size(), 7u);
  for (const ModelAtlasAttractor& a : atlas.attractors) {
    EXPECT_EQ(a.fate, AttractorFate::kOnBranch) << a.value << ": " << a.reason;
    ASSERT_TRUE(a.found && a.found->measures);
    EXPECT_NEAR(a.found->measures->coordinates[0].Amplitude(), DenHartogOrbit(a.value, 0.25).amplitude, 1e-9);
  }
  ASSERT_EQ(atlas.traces.size(), 1u);
  for (const auto* branch : atlas.Branches()) {
    for (const auto& orbit : branch->orbits) {
      const double r = orbit.parameters.omega;
      const BasicOrbitMeasures m = Measure(model, orbit);
      EXPECT_NEAR(m.coordinates[0].Amplitude(), DenHartogOrbit(r, 0.25).amplitude, 1e-9) << "r = " << r;
    }
  }
}

// A mass on a belt (no forcing) over the belt's speed: the stick-slip cycle at every grid value,
// read on the stick-entry section, on one branch, its stick and slip the closed form's.
TEST(ModelAtlas, TracesTheStickSlipCycleOfAMassOnABelt) {
  BeltCycle belt;
  const Model model(belt.Data());
  ModelAtlasOptions o;
  o.parameter = "v_b";
  o.from = 0.2;
  o.to = 0.8;
  o.steps = 3;
  o.brute_force.scatter = 0.5;
  o.brute_force.transient_periods = 60;
  o.brute_force.time_unit = 2.0 * std::numbers::pi;
  const ModelAtlas atlas = ComputeModelAtlas(model, {1.0, belt.F_k, belt.F_s, 0.5}, o);
  EXPECT_EQ(atlas.OnBranches(), atlas.PeriodicWithinLimit());
  int cycles = 0;
  for (const ModelAtlasAttractor& a : atlas.attractors) {
    if (!a.found || a.found->status != FindOrbitStatus::kFound) continue;
    ++cycles;
    BeltCycle at = belt;
    at.v_b = a.value;
    const BasicOrbit<Model>& orbit = a.found->solution->orbit;
    ASSERT_EQ(orbit.signature.ToString(), "stick slip-");
    EXPECT_NEAR(orbit.durations[0], at.Stick(), 1e-9 * at.Stick());
    EXPECT_NEAR(orbit.durations[1], at.Slip(), 1e-9 * at.Slip());
  }
  EXPECT_EQ(cycles, 4);
  EXPECT_EQ(atlas.traces.size(), 1u);
}

// Section 4.1's masses in physical units over a window with several attractors per grid value,
// traces and switches: everything the atlas holds, for one thread and two.
TEST(ModelAtlas, DoesNotDependOnTheThreadCount) {
  const Parameters paper = SolvedPreset("paper-4.1").parameters;
  const PhysicalTwoMasses physical;
  const Model model(physical.Data(paper));
  ModelAtlasOptions o;
  o.from = 0.55 * physical.Omega(paper);
  o.to = 0.65 * physical.Omega(paper);
  o.steps = 4;
  o.brute_force.scatter = physical.Length(paper);
  o.brute_force.threads = 1;
  const ModelAtlas one = ComputeModelAtlas(model, physical.Of<Model>(paper), o);
  o.brute_force.threads = 2;
  const ModelAtlas two = ComputeModelAtlas(model, physical.Of<Model>(paper), o);
  ASSERT_GT(one.traces.size(), 1u);
  ASSERT_EQ(one.attractors.size(), two.attractors.size());
  for (std::size_t k = 0; k < one.attractors.size(); ++k) {
    const ModelAtlasAttractor &a = one.attractors[k], &b = two.attractors[k];
    EXPECT_EQ(a.fate, b.fate);
    EXPECT_EQ(a.branch, b.branch);
    EXPECT_EQ(a.point, b.point);
    EXPECT_EQ(a.reason, b.reason);
    EXPECT_EQ(a.attractor.starts, b.attractor.starts);
    EXPECT_EQ(a.attractor.section, b.attractor.section);
  }
  const auto a = one.Branches(), b = two.Branches();
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    ASSERT_EQ(a[k]->orbits.size(), b[k]->orbits.size());
    for (std::size_t i = 0; i < a[k]->orbits.size(); ++i) {
      EXPECT_EQ(a[k]->orbits[i].start, b[k]->orbits[i].start);
      EXPECT_EQ(a[k]->orbits[i].durations, b[k]->orbits[i].durations);
    }
  }
}

// Membership judges the motion, not its description: Den Hartog's orbit read from its other stop
// (half a period on) lies on the branch traced from it; the same orbit with its forcing a quarter
// cycle off does not, nor does it at another amplitude.
TEST(ModelAtlas, MembershipTakesAnotherOriginAndRefusesAnotherPhaseOrState) {
  const Model model = DenHartogsMass();
  ModelAtlasOptions o;
  o.from = 1.5;
  o.to = 2.5;
  o.steps = 1;
  const ModelAtlas atlas = ComputeModelAtlas(model, {1.5, 0.25, 0.25, 0.0}, o);
  const ModelAtlasAttractor& a = atlas.attractors.front();
  ASSERT_TRUE(a.found && a.found->solution);
  const BasicOrbit<Model> whole = Unfolded(a.found->solution->orbit, 1);  // slip+ slip-
  ASSERT_EQ(whole.signature.size(), 2);
  BranchMembershipOptions options;
  options.parameter = "omega";
  // From the start of its second segment: the state there, the phase omega d1 later.
  BasicOrbit<Model> other = whole;
  other.signature = Signature::Parse("slip- slip+");
  other.durations = {whole.durations[1], whole.durations[0]};
  WalkSegments(model, whole, Extent::kListed, PhaseRule::kFromOrigin, [&](const SegmentVisit<double, Model>& s) {
    if (s.index == 1) other.start = s.start, other.phi = s.phase;
  });
  EXPECT_TRUE(FindOnModelBranches(model, other, atlas.Branches(), options).on_branch);
  BasicOrbit<Model> shifted = whole;
  shifted.phi += std::numbers::pi / 2.0;
  const BranchMembership off = FindOnModelBranches(model, shifted, atlas.Branches(), options);
  EXPECT_FALSE(off.on_branch);
  EXPECT_NEAR(off.distance, 0.25, 1e-9) << off.message;  // a quarter of a forcing cycle
  BasicOrbit<Model> larger = whole;
  larger.start *= 1.01;
  EXPECT_FALSE(FindOnModelBranches(model, larger, atlas.Branches(), options).on_branch);
}

// Bad input is refused before any work, naming the field.
TEST(ModelAtlas, RefusesOptionsOutOfRangeNamingTheField) {
  const Model forced = DenHartogsMass();
  const Model::Parameters p{1.5, 0.25, 0.25, 0.0};
  const auto field = [&](const Model& model, const Model::Parameters& base, ModelAtlasOptions o) -> std::string {
    try {
      o.Validate(model, base);
    } catch (const InvalidInput& e) {
      return e.field();
    }
    return "";
  };
  ModelAtlasOptions o;
  o.from = 1.5;
  o.to = 2.5;
  EXPECT_EQ(field(forced, p, o), "");
  for (const auto& [name, edit] : std::vector<std::pair<std::string, void (*)(ModelAtlasOptions&)>>{
           {"parameter", [](ModelAtlasOptions& x) { x.parameter = "chi"; }},
           {"range", [](ModelAtlasOptions& x) { x.to = x.from; }},
           {"range", [](ModelAtlasOptions& x) { x.to = std::nan(""); }},
           {"range", [](ModelAtlasOptions& x) { x.from = 0.5, x.to = 1.0; }},  // omega = 1: the natural frequency
           {"range", [](ModelAtlasOptions& x) { x.parameter = "F_s", x.from = 0.1, x.to = 0.3; }},  // F_s < F_k
           {"steps", [](ModelAtlasOptions& x) { x.steps = 0; }},
           {"steps", [](ModelAtlasOptions& x) { x.steps = 100000000; }},
           {"max-multiple", [](ModelAtlasOptions& x) { x.max_multiple = 0; }},
           {"max-multiple", [](ModelAtlasOptions& x) { x.max_multiple = 1000000; }},
           {"periods", [](ModelAtlasOptions& x) { x.brute_force.recorded_periods = 4; }},  // below 2 max_multiple
           {"scatter", [](ModelAtlasOptions& x) { x.brute_force.scatter = 1e300; }},
           {"find-rounds", [](ModelAtlasOptions& x) { x.find_rounds = 0; }},
           {"tolerance", [](ModelAtlasOptions& x) { x.brute_force.periodicity_tolerance = 0.0; }},
           {"max_amplitude", [](ModelAtlasOptions& x) { x.trace.max_amplitude = -1.0; }},
           {"centre", [](ModelAtlasOptions& x) { x.brute_force.centre = Eigen::VectorXd::Zero(3); }},
       }) {
    ModelAtlasOptions bad = o;
    edit(bad);
    EXPECT_EQ(field(forced, p, bad), name);
  }
  // Without forcing: omega is no parameter of the motion, and a time unit is needed.
  BeltCycle belt;
  const Model free(belt.Data());
  const Model::Parameters q{1.0, belt.F_k, belt.F_s, 0.5};
  EXPECT_EQ(field(free, q, o), "parameter");
  ModelAtlasOptions speed = o;
  speed.parameter = "v_b";
  speed.from = 0.2;
  speed.to = 0.8;
  EXPECT_EQ(field(free, q, speed), "time-unit");
}

}  // namespace
}  // namespace stickslip
