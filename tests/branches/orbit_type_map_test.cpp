// The geometry of orbit-type maps on known arrangements of curves (CutIntoRegions), the options'
// and the rectangle's validation, and the bound the regions' content is continued under.
#include "stickslip/branches/orbit_type_map.hpp"

#include <algorithm>
#include <filesystem>

#include <gtest/gtest.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/io/orbit_type_map_files.hpp"
#include "stickslip/io/run_file.hpp"
#include "stickslip/io/trace_files.hpp"

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
    r.Validate();
    FAIL();
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.field(), "second_min");
  }
  r = kUnit;
  r.second = "omega";
  EXPECT_THROW(r.Validate(), InvalidInput);
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
  EXPECT_TRUE(region.Label().starts_with("unknown: no periodic motion found")) << region.Label();
  region.failures.clear();
  EXPECT_EQ(region.Label(), "no periodic motion");
}

TEST(CurveCondition, IsTheMarginOfATypeChangeAndTheTypeOtherwise) {
  EXPECT_EQ(CurveCondition("SK", "margin:reversal:1"), "margin:reversal:1");
  EXPECT_EQ(CurveCondition("LP", "tangent:lambda"), "LP");
  EXPECT_EQ(CurveCondition("TR", "floquet:torus"), "TR");
}

}  // namespace
}  // namespace stickslip
