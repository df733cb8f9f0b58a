// The orbit-type map against the brute force (issue 13's test), on a small rectangle of the
// section 6 data in (omega, u_r): the map from the stored trace results/paper-6-omega-trace, the
// brute-force map computed here by simulation (the exact simulator, independent of the
// continuation). The agreement is asserted as it is, and every disagreement must carry its reason.
#include "stickslip/analysis/map_comparison.hpp"

#include <filesystem>

#include <gtest/gtest.h>

#include "stickslip/io/orbit_type_map_files.hpp"
#include "stickslip/io/run_file.hpp"
#include "stickslip/io/trace_files.hpp"
#include "stickslip/orbits/start_problem.hpp"

namespace stickslip {
namespace {

namespace fs = std::filesystem;

TEST(CanonicalOrbitType, IsTheSameForEveryCyclicShiftAndKeepsTheSuffix) {
  EXPECT_EQ(CanonicalOrbitType("slip- slip+ stick slip+"), CanonicalOrbitType("stick slip+ slip- slip+"));
  EXPECT_EQ(CanonicalOrbitType("slip- stick slip- / antisymmetric"), "slip- slip- stick / antisymmetric");
  EXPECT_NE(CanonicalOrbitType("slip- stick"), CanonicalOrbitType("slip- stick / antisymmetric"));
  EXPECT_EQ(CanonicalOrbitType(""), "");
}

TEST(MapComparison, SectionSixMapAgreesWithTheBruteForceWhereItsRegionIsUniformAndExplainsTheRest) {
  const fs::path root(STICKSLIP_SOURCE_DIR);
  const StoredTrace trace = ReadTraceFiles(root / "results/paper-6-omega-trace");
  const RunFile run = ReadRunFile(root / trace.run_file);
  const MapTrace input = MapTraceOf(trace, &run);
  const MapRectangle rectangle{.first = "omega", .second = "u_r", .first_min = 0.55, .first_max = 0.575,
                               .second_min = 1.3, .second_max = 1.5};
  OrbitTypeMapOptions options;
  options.raster = 64;
  const OrbitTypeMap map = BuildOrbitTypeMap(input, rectangle, options);

  StartInput start;
  start.preset = "paper-6";
  const ModelStart model = BuildModelStart(start);
  BruteForceMapOptions grid;
  grid.first = {ParameterId::kOmega, 0.55, 0.575, 5};
  grid.second = {ParameterId::kStaticFriction, 1.3, 1.5, 4};
  grid.centre = model.initial_state;
  grid.threads = 2;
  const BruteForceMap brute = ComputeBruteForceMap(model.parameters, model.phi, grid);

  const MapComparison c = CompareWithBruteForce(map, &input, TraceTypes(trace), brute);
  EXPECT_EQ(c.cells, 30);
  // The LP and TR curves cross the rectangle (each both ways from its point on the trace); the
  // grazing that bounds the stable stretch below is not continued yet (BoundaryCurve refuses G:2 and
  // exit-slope:2), so the stable region reaches past it, where its cells disagree, explained by the
  // orbits solved at the cells themselves.
  EXPECT_EQ(map.curves.size(), 4u);
  EXPECT_EQ(c.compared, 11);
  EXPECT_EQ(c.agreeing, 6);
  for (const MapCellComparison& d : c.disagreements) {
    EXPECT_TRUE(d.explained) << "cell (" << d.i << ", " << d.j << "): " << d.explanation;
    EXPECT_FALSE(d.explanation.empty());
  }
}

}  // namespace
}  // namespace stickslip
