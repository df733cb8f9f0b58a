// The brute-force map: where a paper orbit is stable, its cell holds an attractor whose section
// point is the exact orbit's start (the orbit solver, an independent computation); the file does
// not depend on the number of threads; shards merged give the unsharded file; the file reads
// back to the same bytes; a cell's neighbour run starts where the previous cell's ended.
#include "stickslip/analysis/brute_force_map.hpp"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "stickslip/analysis/settled_motion.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/io/map_file.hpp"
#include "stickslip/orbits/stability.hpp"
#include "stickslip/orbits/margins.hpp"
#include "support/solved_presets.hpp"

namespace stickslip {
namespace {

// A 3 x 3 grid in (omega, u_r) with the orbit's own data at cell (0, 0) (ValueAt(0) is `from`
// exactly), sections at the orbit's phase: the orbit's start (x10, x20, v10, 0) is a section point.
// The given start is 1e-6 off the orbit (the 4.1 orbit is 3e-4 from a change of type, so a larger
// step may leave its basin); 300 transient periods shrink that below 1e-10 at multipliers <= 0.97.
BruteForceMapOptions SmallGrid(const Orbit& orbit) {
  BruteForceMapOptions o;
  o.first = {ParameterId::kOmega, orbit.parameters.omega, orbit.parameters.omega + 0.01, 2};
  o.second = {ParameterId::kStaticFriction, orbit.parameters.u_r, orbit.parameters.u_r + 0.02, 2};
  o.transient_periods = 300;
  o.recorded_periods = 8;
  o.scattered_starts = 2;
  o.centre = State(orbit.x10 + 1e-6, orbit.x20, orbit.v10, 0.0);  // near the orbit, not on it
  o.scatter = 0.5;
  o.threads = 2;
  return o;
}

double DistanceToOrbitStart(const Attractor& a, const Orbit& orbit) {
  const State start(orbit.x10, orbit.x20, orbit.v10, 0.0);
  double best = 1e300;
  for (const State& x : a.section) best = std::min(best, (x - start).lpNorm<Eigen::Infinity>());
  return best;
}

TEST(BruteForceMap, FindsTheStablePaperOrbitsAtTheirOwnData) {
  int stable_checked = 0;
  for (const auto& [name, paper_choice] : {std::pair{"paper-4.1", false}, std::pair{"paper-4.2", false},
                                           std::pair{"paper-5.1", false}, std::pair{"paper-5.2", true},
                                           std::pair{"paper-6", false}}) {
    const Orbit orbit = SolvedPreset(name, paper_choice);
    // A motion (every margin > 0) whose multipliers are all inside the unit circle: 4.1, 4.2 and
    // 5.2 (with the paper's own unknowns: at the printed data a margin is negative, ERRATA).
    if (!StabilityOf(orbit).stable || !(SmallestMargin(AdmissibilityMargins(orbit)).value > 0.0)) continue;
    ++stable_checked;
    const BruteForceMap map = ComputeBruteForceMap(orbit.parameters, orbit.phi, SmallGrid(orbit));
    ASSERT_EQ(map.cells.size(), 9u);
    const MapCell& cell = map.cells.front();
    ASSERT_EQ(cell.i, 0);
    ASSERT_EQ(cell.j, 0);
    double best = 1e300;
    const Attractor* found = nullptr;
    for (const Attractor& a : cell.attractors) {
      if (a.status == AttractorStatus::kPeriodic && DistanceToOrbitStart(a, orbit) < best) {
        best = DistanceToOrbitStart(a, orbit);
        found = &a;
      }
    }
    ASSERT_NE(found, nullptr) << name;
    EXPECT_LT(best, 1e-7) << name;
    EXPECT_EQ(found->signature, orbit.signature.ToString()) << name;
    EXPECT_EQ(found->period, orbit.signature.period_multiple()) << name;
  }
  EXPECT_EQ(stable_checked, 3);
}

// A grid of the section 6 data with a row count that shards unevenly.
BruteForceMapOptions QuickGrid() {
  BruteForceMapOptions o;
  o.first = {ParameterId::kOmega, 0.55, 0.6, 3};
  o.second = {ParameterId::kStaticFriction, 1.2, 1.5, 2};
  o.transient_periods = 30;
  o.recorded_periods = 6;
  o.scattered_starts = 2;
  return o;
}

TEST(BruteForceMap, FileDoesNotDependOnTheNumberOfThreads) {
  const Orbit orbit = SolvedPreset("paper-6");
  BruteForceMapOptions o = QuickGrid();
  o.threads = 1;
  const std::string serial = BruteForceMapCsv(ComputeBruteForceMap(orbit.parameters, orbit.phi, o));
  for (int threads : {2, 5}) {
    o.threads = threads;
    EXPECT_EQ(BruteForceMapCsv(ComputeBruteForceMap(orbit.parameters, orbit.phi, o)), serial) << threads << " threads";
  }
}

TEST(BruteForceMap, ShardsMergedGiveTheUnshardedFile) {
  const Orbit orbit = SolvedPreset("paper-6");
  BruteForceMapOptions o = QuickGrid();
  const std::string whole = BruteForceMapCsv(ComputeBruteForceMap(orbit.parameters, orbit.phi, o));
  // 3 rows in 2 shards: rows 0 and 2, row 1; and in 4 shards, one of them empty.
  for (int shards : {2, 4}) {
    std::vector<BruteForceMap> maps;
    std::vector<std::string> names;
    for (int k = shards; k >= 1; --k) {  // in any order
      o.shard = k;
      o.shards = shards;
      const std::string text = BruteForceMapCsv(ComputeBruteForceMap(orbit.parameters, orbit.phi, o));
      names.push_back(std::to_string(k));
      maps.push_back(ReadBruteForceMapCsv(text, names.back()));
    }
    EXPECT_EQ(BruteForceMapCsv(MergeBruteForceMaps(maps, names)), whole) << shards << " shards";
    // A shard given twice, or one left out, is refused.
    std::vector<BruteForceMap> twice = maps;
    twice.push_back(maps.back());  // shard 1, which holds row 0
    std::vector<std::string> twice_names = names;
    twice_names.push_back("again");
    EXPECT_THROW(MergeBruteForceMaps(twice, twice_names), InvalidInput);
    maps.pop_back();
    names.pop_back();
    EXPECT_THROW(MergeBruteForceMaps(maps, names), InvalidInput);
  }
}

TEST(BruteForceMap, FileReadsBackToTheSameBytes) {
  const Orbit orbit = SolvedPreset("paper-6");
  const std::string text = BruteForceMapCsv(ComputeBruteForceMap(orbit.parameters, orbit.phi, QuickGrid()));
  EXPECT_EQ(BruteForceMapCsv(ReadBruteForceMapCsv(text, "map.csv")), text);
  std::string damaged = text;
  damaged.replace(damaged.find(",periodic,"), 10, ",periodik,");
  EXPECT_THROW(ReadBruteForceMapCsv(damaged, "map.csv"), InvalidInput);
  // A cell count beyond the grid's bound (a merge would loop over it) is refused.
  std::string huge = text;
  const std::size_t row = huge.find('\n') + 1;  // "0,0,4,3,..."
  huge.replace(huge.find(",4,", row), 3, ",2000000000,");
  EXPECT_THROW(ReadBruteForceMapCsv(huge, "map.csv"), InvalidInput);
}

// The rows of one attractor agree on everything but k and the state, the rows of one cell on its
// attractor count: a file that does not is refused, not read as its first rows say.
TEST(BruteForceMap, FileWhoseRowsOfOneAttractorDisagreeIsRefused) {
  const std::string header =
      "i,j,ni,nj,omega,u_r,section_phase,run,attractors,attractor,status,period,stops_per_period,sticks_per_period,"
      "starts,signature,k,x1,x2,v1,v2\n";
  const std::string first = "0,0,1,1,0.5,1,0,0123456789abcdef,2,0,periodic,2,1,0,3,,0,1,2,3,4\n";
  const std::string second = "0,0,1,1,0.5,1,0,0123456789abcdef,2,0,periodic,2,1,0,3,,1,5,6,7,8\n";
  const std::string other = "0,0,1,1,0.5,1,0,0123456789abcdef,2,1,not-settled,0,0,0,1,,0,0,0,0,0\n";
  const std::string text = header + first + second + other;
  EXPECT_EQ(BruteForceMapCsv(ReadBruteForceMapCsv(text, "map.csv")), text);
  for (const auto& [from, to] : {std::pair{",3,,1,", ",4,,1,"}, std::pair{",periodic,2,1,0,3,,1", ",periodic,2,1,1,3,,1"},
                                 std::pair{",2,0,periodic,2,1,0,3,,1", ",3,0,periodic,2,1,0,3,,1"}}) {
    std::string damaged = text;
    damaged.replace(damaged.find(from), std::string(from).size(), to);
    EXPECT_THROW(ReadBruteForceMapCsv(damaged, "map.csv"), InvalidInput) << from;
  }
}

// Every run accounted for: each cell's attractors hold all its runs (rest, the neighbour but in
// cell 0, the scattered starts), and a periodic attractor lists `period` section points.
TEST(BruteForceMap, EveryRunEndsOnOneListedAttractor) {
  const Orbit orbit = SolvedPreset("paper-6");
  const BruteForceMapOptions o = QuickGrid();
  const BruteForceMap map = ComputeBruteForceMap(orbit.parameters, orbit.phi, o);
  ASSERT_EQ(map.cells.size(), 12u);
  for (const MapCell& cell : map.cells) {
    int starts = 0;
    for (const Attractor& a : cell.attractors) {
      starts += a.starts;
      EXPECT_EQ(a.section.size(), a.status == AttractorStatus::kPeriodic ? static_cast<std::size_t>(a.period) : 1u);
    }
    EXPECT_EQ(starts, (cell.i == 0 ? 1 : 2) + o.scattered_starts) << cell.i << ", " << cell.j;
  }
}

// The neighbour run of cell (1, 0) starts where cell 0's rest run ended: the same motion as a
// settled simulation from there (SimulateSettled, the sweep's per-point computation).
TEST(BruteForceMap, NeighbourRunStartsWhereThePreviousCellEnded) {
  const Orbit orbit = SolvedPreset("paper-6");
  BruteForceMapOptions o = QuickGrid();
  o.second.steps = 0;
  o.scattered_starts = 0;
  const BruteForceMap map = ComputeBruteForceMap(orbit.parameters, orbit.phi, o);
  const SettleOptions settle{o.transient_periods, o.recorded_periods, o.periodicity_tolerance, o.max_events_per_simulation};
  Parameters p = orbit.parameters;
  p.u_r = o.second.from;
  p.omega = o.first.ValueAt(0);
  const SettledMotion rest0 = SimulateSettled(p, State::Zero(), orbit.phi, settle);
  p.omega = o.first.ValueAt(1);
  const SettledMotion neighbour1 = SimulateSettled(p, rest0.last, orbit.phi, settle);
  const SettledMotion rest1 = SimulateSettled(p, State::Zero(), orbit.phi, settle);
  const MapCell& cell = map.cells[1];
  ASSERT_EQ(cell.i, 1);
  // The attractors of cell 1 in order: rest's, then the neighbour's unless the same.
  ASSERT_GE(cell.attractors.size(), 1u);
  EXPECT_EQ(cell.attractors.front().section.front(), rest1.period > 0 ? rest1.section.front() : rest1.last);
  const State neighbour_point = neighbour1.period > 0 ? neighbour1.section.front() : neighbour1.last;
  bool listed = false;
  for (const Attractor& a : cell.attractors) {
    for (const State& x : a.section) listed = listed || (x - neighbour_point).lpNorm<Eigen::Infinity>() <= o.periodicity_tolerance;
  }
  EXPECT_TRUE(listed);
}

TEST(BruteForceMap, ValidateNamesTheField) {
  const Orbit orbit = SolvedPreset("paper-6");
  BruteForceMapOptions o = QuickGrid();
  o.recorded_periods = 1;
  try {
    o.Validate(orbit.parameters);
    FAIL();
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.field(), "recorded_periods");
  }
  o = QuickGrid();
  o.second = {ParameterId::kStaticFriction, 0.01, 0.5, 2};  // u_r < u_s = 0.06 at j = 0
  try {
    o.Validate(orbit.parameters);
    FAIL();
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.field(), "grid");
  }
}

}  // namespace
}  // namespace stickslip
