// The geometry of orbit-type maps on known arrangements of curves (CutIntoRegions), the options'
// and the rectangle's validation, the bound the regions' content is continued under, and a map of
// a user's model (Den Hartog's oscillator) against its closed form.
#include "stickslip/branches/orbit_type_map.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gtest/gtest.h>

#include "stickslip/branches/trace.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/io/orbit_type_map_files.hpp"
#include "stickslip/io/run_file.hpp"
#include "stickslip/io/trace_files.hpp"
#include "support/den_hartog_oscillator.hpp"
#include "support/den_hartog_orbit.hpp"

namespace stickslip {
namespace {

namespace fs = std::filesystem;
using Polyline = std::vector<std::pair<double, double>>;

const MapRectangle kUnit{.first = "omega", .second = "u_r", .first_min = 0.0, .first_max = 1.0, .second_min = 0.0, .second_max = 2.0};

OrbitTypeMapOptions Raster(int n) {
  OrbitTypeMapOptions o;
  o.raster = n;
  return o;
}

TEST(CutIntoRegions, NoCurveLeavesOneRegionCentredInTheRectangle) {
  const OrbitTypeMap map = CutIntoRegions(kUnit, {}, Raster(100));
  ASSERT_EQ(map.regions.size(), 1u);
  EXPECT_EQ(map.regions[0].cells, 100 * 100);
  EXPECT_NEAR(map.regions[0].first, 0.5, 0.01);
  EXPECT_NEAR(map.regions[0].second, 1.0, 0.02);
}

TEST(CutIntoRegions, ACrossCutsFourQuartersWithTheirCentresAsInteriorPoints) {
  const std::vector<Polyline> lines = {{{0.5, -1.0}, {0.5, 3.0}}, {{-1.0, 1.0}, {2.0, 1.0}}};
  const OrbitTypeMap map = CutIntoRegions(kUnit, lines, Raster(200));
  ASSERT_EQ(map.regions.size(), 4u);
  for (const MapRegion& r : map.regions) {
    EXPECT_NEAR(r.cells, 9900, 300);  // a quarter, less the cut row and column
    EXPECT_NEAR(std::abs(r.first - 0.5), 0.25, 0.01) << r.id;
    EXPECT_NEAR(std::abs(r.second - 1.0), 0.5, 0.02) << r.id;
    EXPECT_EQ(map.RegionAt(r.first, r.second), r.id - 1);
  }
  EXPECT_EQ(map.RegionAt(0.5, 0.3), OrbitTypeMap::kCut);
  EXPECT_EQ(map.RegionAt(1.5, 0.3), OrbitTypeMap::kCut);  // outside
}

TEST(CutIntoRegions, ACurveEndingInsideCutsNothingApart) {
  // A curve from the left edge to the middle (it ends at a codimension-two point): one region.
  const OrbitTypeMap map = CutIntoRegions(kUnit, {{{0.0, 1.0}, {0.3, 1.2}, {0.5, 1.0}}}, Raster(100));
  ASSERT_EQ(map.regions.size(), 1u);
  // Its interior point keeps away from the curve and the edges.
  EXPECT_GE(map.regions[0].clearance, 20);
}

TEST(CutIntoRegions, DropsSliversBelowTheSmallestRegion) {
  // A thin strip at the bottom, 2 % of the height: a sliver with min_region = 0.05, a region without.
  const std::vector<Polyline> lines = {{{0.0, 0.04}, {1.0, 0.04}}};
  OrbitTypeMapOptions o = Raster(100);
  o.min_region = 0.05;
  const OrbitTypeMap coarse = CutIntoRegions(kUnit, lines, o);
  ASSERT_EQ(coarse.regions.size(), 1u);
  EXPECT_EQ(coarse.RegionAt(0.5, 0.01), OrbitTypeMap::kSliver);
  o.min_region = 0.0;
  EXPECT_EQ(CutIntoRegions(kUnit, lines, o).regions.size(), 2u);
}

TEST(CutIntoRegions, AClosedCurveCutsItsInsideFromItsOutside) {
  Polyline circle;
  for (int k = 0; k <= 400; ++k) {
    const double t = 2.0 * 3.141592653589793 * k / 400;
    circle.emplace_back(0.5 + 0.25 * std::cos(t), 1.0 + 0.5 * std::sin(t));
  }
  const OrbitTypeMap map = CutIntoRegions(kUnit, {circle}, Raster(200));
  ASSERT_EQ(map.regions.size(), 2u);
  const int inside = map.RegionAt(0.5, 1.0);
  ASSERT_GE(inside, 0);
  EXPECT_NEAR(map.regions[inside].first, 0.5, 0.01);
  EXPECT_NEAR(map.regions[inside].second, 1.0, 0.02);
  EXPECT_NE(map.RegionAt(0.05, 0.1), inside);
}

TEST(OrbitTypeMapOptions, RejectOutOfRangeValuesNamingTheField) {
  OrbitTypeMapOptions o;
  o.raster = 100000;
  EXPECT_THROW(o.Validate(), InvalidInput);
  o = {};
  o.min_region = 0.9;
  EXPECT_THROW(o.Validate(), InvalidInput);
  MapRectangle r = kUnit;
  r.second_max = 1e300 * 1e300;
  try {
    r.Validate(Pascal2014{}.Description(), false);
    FAIL();
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.field(), "second_min");
  }
  r = kUnit;
  r.second = "omega";
  EXPECT_THROW(r.Validate(Pascal2014{}.Description(), false), InvalidInput);
}

// The map continues the trace's orbits with the trace's bound on the amplitude (a resonance ends a
// continuation): the stored §4.1 trace's orbits (amplitude:x2 3.3 at omega = 0.6) reach the point
// on the trace's line under its bound, 1e3, and none reach it under a bound of 2; the region is then
// labelled unknown, not motionless.
TEST(OrbitsAt, ContinuesTheTracesOrbitsUnderTheTracesMaxAmplitude) {
  const fs::path root(STICKSLIP_SOURCE_DIR);
  const StoredTrace trace = ReadTraceFiles(root / "results/paper-4.1-omega-trace");
  RunFile run = ReadRunFile(root / trace.run_file);
  ASSERT_TRUE(run.trace.has_value());
  run.trace->max_amplitude = 1234.0;
  EXPECT_EQ(MapTraceOf(trace, &run).max_amplitude, 1234.0);
  EXPECT_EQ(MapTraceOf(trace, nullptr).max_amplitude, kDefaultMaxAmplitude);
  MapTrace input = MapTraceOf(trace, &run);
  const MapRectangle r{.first = "omega", .second = "u_r", .first_min = 0.55, .first_max = 0.65, .second_min = 0.2, .second_max = 0.4};
  const MapOrbitsAt within = OrbitsAt(input, r, 0.62, 0.2996, OrbitTypeMapOptions{});
  ASSERT_FALSE(within.orbits.empty());
  EXPECT_TRUE(within.failures.empty());
  input.max_amplitude = 2.0;
  const MapOrbitsAt bounded = OrbitsAt(input, r, 0.62, 0.2996, OrbitTypeMapOptions{});
  EXPECT_TRUE(bounded.orbits.empty());
  ASSERT_FALSE(bounded.failures.empty());
  for (const std::string& f : bounded.failures) EXPECT_NE(f.find("resonance: the amplitude"), std::string::npos) << f;
  MapRegion region;
  region.failures = bounded.failures;
  EXPECT_TRUE(region.Label().starts_with("unknown: none of the trace's orbits found")) << region.Label();
  region.failures.clear();
  EXPECT_EQ(region.Label(), "none of the trace's orbits");
}

// A branch's recorded column `name` at point `p`.
double Recorded(const BasicOrbitBranch<DynamicLinearOscillator>& branch, const BranchPoint& p, std::string_view name) {
  for (const PointColumn& c : branch.columns) {
    if (c.name == name) return c.monitored ? p.tests(c.index) : p.recorded(c.index);
  }
  return std::numeric_limits<double>::quiet_NaN();
}

// A trace's branches and special points as the map's input, each branch's unknowns its type's at
// fixed parameters: what io/orbit_type_map_files.hpp reads back from a stored trace.
BasicMapTrace<DynamicLinearOscillator> MapTraceOfTrace(const DynamicLinearOscillator& model,
                                                       const BasicTraceResult<DynamicLinearOscillator>& trace) {
  BasicMapTrace<DynamicLinearOscillator> map{.parameter = trace.parameter, .options = {}, .shooting = ShootingChoice::kAuto,
                                             .max_amplitude = kDefaultMaxAmplitude, .branches = {}, .model = model};
  for (const BasicTraceDirection<DynamicLinearOscillator>* chain : {&trace.down, &trace.up}) {
    for (const BasicTraceLink<DynamicLinearOscillator>& link : chain->links) {
      const auto& orbits = link.branch.orbits;
      BasicMapTraceBranch<DynamicLinearOscillator> b{fmt::format("branch-{}", map.branches.size() + 1),
                                                     UnknownsAtFixedParameters(VariableSetOf(model, orbits.front().signature)),
                                                     orbits, {}, {}, {}};
      for (const SpecialPoint& p : link.branch.branch.special_points) {
        b.special.push_back({b.name, p.type, p.type, p.test_function, orbits[p.point]});
      }
      for (const BranchPoint& p : link.branch.branch.points) {
        b.admissible.push_back(Recorded(link.branch, p, orbit_columns::kAdmissible) == 1.0);
        b.stable.push_back(Recorded(link.branch, p, orbit_columns::kStable) == 1.0);
      }
      map.branches.push_back(std::move(b));
    }
  }
  return map;
}

// Den Hartog's oscillator (k = m = 1, forcing amplitude 1) with the kinetic level beta = 0.2 and
// the static level F_s free: its non-sticking orbit does not depend on F_s, and its turning points
// stick where the force that holds the mass there, r^2 X(r, beta) (Den Hartog's amplitude X; the
// relation his beta* = |V| / sqrt(U^2 + 1/r^4) solves for F_s = beta), is at most F_s. The map in
// (omega, F_s) from a trace in omega at F_s = 0.5 must cut the rectangle along F_s = r^2 X(r, 0.2)
// alone, the non-sticking orbit stable below that curve and not admissible above it, a sticking one
// a motion above it only.
TEST(ModelOrbitTypeMap, CutsDenHartogsRectangleAlongTheClosedFormStickBoundary) {
  const double beta = 0.2, r0 = 0.7;
  const DynamicLinearOscillator model(DenHartogData());
  const DenHartogOrbit start(r0, beta);
  Eigen::VectorXd state(2);
  state << start.amplitude, 0.0;
  BasicOrbitContinuationSetup<DynamicLinearOscillator> setup{
      {Signature::Parse("slip- / antisymmetric"), {r0, beta, 0.5, 0.0}, state, start.phi, {start.Period() / 2}},
      {}, "omega", ShootingChoice::kAuto, LinearSolverType::kKlu, {}, {}, {}, {}, kDefaultMaxAmplitude,
      kDefaultResonanceApproach, model};
  setup.unknowns = UnknownsAtFixedParameters(VariableSetOf(model, setup.start.signature));
  setup.options.lambda_min = 0.55;  // away from the degenerate r = 1/2
  setup.options.lambda_max = 0.8;
  const BasicMapTrace<DynamicLinearOscillator> trace = MapTraceOfTrace(model, TraceOrbits(setup));
  const MapRectangle rectangle{.first = "omega", .second = "F_s", .first_min = 0.55, .first_max = 0.8, .second_min = 0.25,
                               .second_max = 0.8};
  const BasicOrbitTypeMap<DynamicLinearOscillator> map = BuildOrbitTypeMap(trace, rectangle);
  ASSERT_FALSE(map.curves.empty());
  double worst = 0.0;
  for (const BasicMapCurve<DynamicLinearOscillator>& curve : map.curves) {
    ASSERT_GT(curve.first.size(), 5u) << curve.kind << ": " << curve.branch.branch.end_message;
    for (std::size_t k = 0; k < curve.first.size(); ++k) {
      const double r = curve.first[k];
      const double holding = r * r * DenHartogOrbit(r, beta).amplitude;
      EXPECT_NEAR(curve.second[k], holding, 1e-9) << curve.kind << " at r = " << r;
      worst = std::max(worst, std::abs(curve.second[k] - holding));
    }
  }
  RecordProperty("worst_boundary_difference", fmt::format("{:.3g}", worst));
  ASSERT_EQ(map.regions.size(), 2u);
  for (const BasicMapRegion<DynamicLinearOscillator>& region : map.regions) {
    const double holding = region.first * region.first * DenHartogOrbit(region.first, beta).amplitude;
    const bool sticks = region.second > holding;
    const auto non_sticking = std::find_if(region.orbits.begin(), region.orbits.end(), [](const auto& o) {
      return o.orbit.signature.size() == 1;  // a slip from stop to stop: no stick
    });
    ASSERT_NE(non_sticking, region.orbits.end()) << region.Label();
    EXPECT_EQ(non_sticking->admissible, !sticks) << region.Label();
    if (!sticks) {
      EXPECT_TRUE(non_sticking->stable) << region.Label();
      EXPECT_NEAR(non_sticking->orbit.start.cwiseAbs().maxCoeff(), DenHartogOrbit(region.first, beta).amplitude, 1e-9);
    }
    // The trace's sticking branch ends at the boundary, short of the region above it in omega: its
    // end is continued there, and its orbit is a motion above the curve only.
    const bool sticking_motion = std::any_of(region.orbits.begin(), region.orbits.end(), [](const auto& o) {
      const std::vector<Mode>& modes = o.orbit.signature.segments();
      return o.admissible && std::find(modes.begin(), modes.end(), Mode::kStick) != modes.end();
    });
    EXPECT_EQ(sticking_motion, sticks) << region.Label();
    EXPECT_TRUE(region.failures.empty()) << region.failures.front();
    EXPECT_EQ(region.differing, 0) << region.Label() << ": " << fmt::format("{}", fmt::join(region.elsewhere, "; "));
  }
}

TEST(CurveCondition, IsTheMarginOfATypeChangeAndTheTypeOtherwise) {
  EXPECT_EQ(CurveCondition("SK", "margin:reversal:1"), "margin:reversal:1");
  EXPECT_EQ(CurveCondition("LP", "tangent:lambda"), "LP");
  EXPECT_EQ(CurveCondition("TR", "floquet:torus"), "TR");
}

}  // namespace
}  // namespace stickslip
