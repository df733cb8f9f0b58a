// The orbit-type map against the brute force (issue 13's test), on a small rectangle of the
// section 6 data in (omega, u_r): the map from the stored trace results/paper-6-omega-trace, the
// brute-force map computed here by simulation (the exact simulator, independent of the
// continuation).
#include "stickslip/analysis/map_comparison.hpp"

#include <filesystem>
#include <set>

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

TEST(MapComparison, SectionSixMapAgreesWithTheBruteForceAwayFromItsCurves) {
  const fs::path root(STICKSLIP_SOURCE_DIR);
  const StoredTrace trace = ReadTraceFiles(root / "results/paper-6-omega-trace");
  const RunFile run = ReadRunFile(root / trace.run_file);
  const MapTrace input = MapTraceOf(trace, &run);
  const MapRectangle rectangle{.first = "omega", .second = "u_r", .first_min = 0.54, .first_max = 0.59,
                               .second_min = 1.2, .second_max = 1.6};
  OrbitTypeMapOptions options;
  options.raster = 64;
  const OrbitTypeMap map = BuildOrbitTypeMap(input, rectangle, options);
  // The stable stretch of the antisymmetric sticking orbit is bounded by its fold and torus on one
  // side and by a grazing (G:2, and exit-slope:2 where the stick's exit turns tangential) on the
  // other: a curve of each, both ways from the trace's point.
  std::set<std::string> kinds;
  for (const MapCurve& curve : map.curves) kinds.insert(curve.kind);
  EXPECT_EQ(kinds, (std::set<std::string>{"LP", "TR", "margin:G:2", "margin:exit-slope:2"}));

  StartInput start;
  start.preset = "paper-6";
  const ModelStart model = BuildModelStart(start);
  BruteForceMapOptions grid;
  // Steps of 1e-3 in omega: the stable stretch is 0.01 wide, and a compared cell keeps two steps
  // from every curve.
  grid.first = {ParameterId::kOmega, 0.545, 0.58, 35};
  grid.second = {ParameterId::kStaticFriction, 1.2, 1.6, 2};
  grid.centre = model.initial_state;
  grid.threads = 2;
  const BruteForceMap brute = ComputeBruteForceMap(model.parameters, model.phi, grid);

  // The simulation (independent of the continuation) finds, in every cell clear of the curves, the
  // stable orbits of the cell's region; some of those cells hold one (the comparison is not only
  // of cells without a stable orbit).
  const MapComparison c = CompareWithBruteForce(map, &input, TraceTypes(trace), brute);
  EXPECT_EQ(c.cells, 108);
  EXPECT_GT(c.compared, 10);
  EXPECT_GT(c.agreeing_stable, 0);
  EXPECT_EQ(c.agreeing, c.compared);
  for (const MapCellComparison& d : c.disagreements) {
    ADD_FAILURE() << "cell (" << d.i << ", " << d.j << "): " << d.explanation;
  }
}

}  // namespace
}  // namespace stickslip
