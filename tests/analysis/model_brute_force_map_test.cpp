// The brute-force map of an oscillator of the user's (analysis/model_brute_force_map.hpp) against
// closed forms that share none of its code: Den Hartog's non-sticking orbit in every cell of a
// forced map, the stick-slip cycle of a mass on a belt in every cell of an autonomous one; and its
// file (io/map_file.hpp): the same bytes for any thread count, its shards merged, read back.
#include "stickslip/analysis/model_brute_force_map.hpp"

#include <cstdint>
#include <functional>
#include <limits>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/io/map_file.hpp"
#include "support/belt_cycle.hpp"
#include "support/den_hartog_orbit.hpp"
#include "support/den_hartogs_mass.hpp"

namespace stickslip {
namespace {

using Model = DynamicLinearOscillator;

// Den Hartog's mass above resonance over omega x F_k (F_s = 0.25 >= every F_k), a few starts. Its
// only dissipation is friction: at F_k = 0.1 and omega = 1.2 a run has not settled to 1e-6 in 200
// periods, so the lightest friction taken is 0.15.
ModelBruteForceMapOptions DenHartogGrid() {
  ModelBruteForceMapOptions o;
  o.first = {"omega", 1.2, 2.0, 4};
  o.second = {"F_k", 0.15, 0.25, 2};
  o.runs.transient_periods = 200;
  o.runs.scattered_starts = 2;
  return o;
}

const Model::Parameters kDenHartogBase{1.5, 0.25, 0.25, 0.0};

// In every cell one attractor, his non-sticking orbit (two stops, no stick a period), its amplitude
// his X = sqrt(V^2 - beta^2 U^2) at r = omega and beta = F_k, to the settling of the simulation.
TEST(ModelBruteForceMap, ReadsDenHartogsAmplitudeInEveryCell) {
  const ModelBruteForceMap map = ComputeModelBruteForceMap(DenHartogsMass(), kDenHartogBase, DenHartogGrid());
  ASSERT_EQ(map.cells.size(), 15u);
  EXPECT_EQ(map.first, "omega");
  EXPECT_EQ(map.second, "F_k");
  EXPECT_EQ(map.contact, "m1");
  for (const ModelMapCell& cell : map.cells) {
    ASSERT_EQ(cell.attractors.size(), 1u) << cell.first << ", " << cell.second;
    const ModelAttractor& a = cell.attractors.front();
    EXPECT_EQ(a.status, AttractorStatus::kPeriodic);
    EXPECT_EQ(a.period, 1);
    EXPECT_EQ(a.stops_per_period, 2.0);
    EXPECT_EQ(a.sticks_per_period, 0.0);
    EXPECT_EQ(a.starts, 5);  // rest, two scattered, the chained sweep up and down
    // The simulated motion's, which repeats on the section to the tolerance (1e-6 of its size): it
    // is as near the orbit as its slowest contraction has brought it (1e-8 at omega = 1.2).
    const double amplitude = DenHartogOrbit(cell.first, cell.second).amplitude;
    EXPECT_NEAR(a.contact_amplitude, amplitude, 1e-6 * amplitude) << cell.first << ", " << cell.second;
  }
}

// A mass on a belt, autonomous, over v_b x F_s: the stick-slip cycle in every cell (read on its
// stick entries), its largest excursion F_k/k + sqrt(d^2 + (v_b/omega_n)^2).
TEST(ModelBruteForceMap, ReadsTheBeltsStickSlipCycleInEveryCell) {
  const BeltCycle belt;
  const Model model(belt.Data());
  ModelBruteForceMapOptions o;
  o.first = {"v_b", 0.2, 0.8, 3};
  o.second = {"F_s", 1.2, 1.6, 2};
  o.runs.transient_periods = 30;
  o.runs.recorded_periods = 4;
  o.runs.scattered_starts = 1;
  o.runs.scatter = 0.5;
  o.runs.time_unit = 2.0 * std::numbers::pi;
  const ModelBruteForceMap map = ComputeModelBruteForceMap(model, {1.0, belt.F_k, belt.F_s, 0.5}, o);
  ASSERT_EQ(map.cells.size(), 12u);
  for (const ModelMapCell& cell : map.cells) {
    BeltCycle at = belt;
    at.v_b = cell.first;
    at.F_s = cell.second;
    int cycles = 0;
    for (const ModelAttractor& a : cell.attractors) {
      if (a.status != AttractorStatus::kPeriodic || a.sticks_per_period != 1.0) continue;
      ++cycles;
      const double largest = at.F_k / at.k + at.Radius();
      EXPECT_NEAR(a.contact_amplitude, largest, 1e-9 * largest) << cell.first << ", " << cell.second;
    }
    EXPECT_EQ(cycles, 1) << cell.first << ", " << cell.second;
  }
}

// A mass on a belt faster than its slip ever moves (v_b = 0.7 > F_k omega_n): from rest it slides
// for ever about x = F_k/k, an undamped oscillation of amplitude F_k whose every time unit (2 pi)
// brings it back to rest at x = 0. Its section is that one point at rest, which alone gives the
// relative tolerance no scale (1e-21): the contact's excursion over the record does.
TEST(ModelBruteForceMap, ReadsASlideThroughRestAsPeriodic) {
  const BeltCycle belt;
  const Model model(belt.Data());
  ModelBruteForceOptions o;
  o.transient_periods = 50;
  o.recorded_periods = 6;
  o.scattered_starts = 0;
  o.time_unit = 2.0 * std::numbers::pi;
  const auto cells = ModelBruteForce(model, {1.0, 0.2, 1.5, 0.7}, {"F_k", 0.2, 0.3, 1}, o);
  for (int i = 0; i < 2; ++i) {
    const ModelAttractor& from_rest = cells[i].front();
    EXPECT_EQ(from_rest.status, AttractorStatus::kPeriodic) << "F_k = " << 0.2 + 0.1 * i;
    EXPECT_EQ(from_rest.stops_per_period, 0.0);
    EXPECT_NEAR(from_rest.contact_amplitude, 2.0 * (0.2 + 0.1 * i), 1e-12);  // from 0 to 2 F_k/k
  }
}

TEST(ModelBruteForceMap, FileDoesNotDependOnTheNumberOfThreads) {
  ModelBruteForceMapOptions o = DenHartogGrid();
  o.runs.threads = 1;
  const std::string serial = BruteForceMapCsv(ComputeModelBruteForceMap(DenHartogsMass(), kDenHartogBase, o));
  o.runs.threads = 3;
  EXPECT_EQ(BruteForceMapCsv(ComputeModelBruteForceMap(DenHartogsMass(), kDenHartogBase, o)), serial);
}

// Three rows in two shards (rows 0 and 2, row 1) merged in any order are the whole map's file; a
// shard twice, one left out or one of another run is refused; the file reads back to its bytes.
TEST(ModelBruteForceMap, ShardsMergedGiveTheUnshardedFile) {
  ModelBruteForceMapOptions o = DenHartogGrid();
  const std::string whole = BruteForceMapCsv(ComputeModelBruteForceMap(DenHartogsMass(), kDenHartogBase, o));
  EXPECT_TRUE(IsBruteForceMapCsvHeader(whole.substr(0, whole.find('\n'))));
  EXPECT_TRUE(IsModelBruteForceMapCsv(whole));
  EXPECT_EQ(BruteForceMapCsv(ReadModelBruteForceMapCsv(whole, "map.csv")), whole);
  std::vector<ModelBruteForceMap> maps;
  const std::vector<std::string> names = {"2", "1"};
  for (const int shard : {2, 1}) {
    o.shard = shard;
    o.shards = 2;
    maps.push_back(ReadModelBruteForceMapCsv(BruteForceMapCsv(ComputeModelBruteForceMap(DenHartogsMass(), kDenHartogBase, o)),
                                             names[maps.size()]));
  }
  EXPECT_EQ(BruteForceMapCsv(MergeBruteForceMaps(maps, names)), whole);
  EXPECT_THROW(MergeBruteForceMaps({maps[0], maps[1], maps[1]}, {"2", "1", "1 again"}), InvalidInput);
  EXPECT_THROW(MergeBruteForceMaps({maps[0]}, {"2"}), InvalidInput);
  ModelBruteForceMap other = maps[1];
  other.run ^= 1;
  EXPECT_THROW(MergeBruteForceMaps({maps[0], other}, {"2", "other"}), InvalidInput);
}

// A header the writer could not have written, with as many fields as the rows (so that it is the
// header's names that are refused), or a row's value out of its kind, is refused; an amplitude not
// computed (nan) reads back as written.
TEST(ModelBruteForceMap, DamagedFileIsRefused) {
  const std::string whole = BruteForceMapCsv(ComputeModelBruteForceMap(DenHartogsMass(), kDenHartogBase, DenHartogGrid()));
  const auto damaged = [&](const std::string& from, const std::string& to) {
    std::string text = whole;
    text.replace(text.find(from), from.size(), to);
    return text;
  };
  for (const auto& [from, to] : {std::pair<std::string, std::string>{",k,m1,v_m1", ",k,m1,m1"},  // a column twice
                                 {",amplitude:m1,", ",amplitude:v_m1,"},  // the contact's velocity
                                 {",amplitude:m1,", ",amplitude:,"},       // no coordinate
                                 {"omega,F_k,", "F_k,F_k,"},                 // one parameter twice
                                 {"omega,F_k,", "omega,m1,"},                // a parameter named as a state column
                                 {",k,m1,v_m1", ",kk,m1,v_m1"},
                                 {"\n1,0,5,3,1.4,0.15,", "\n1,0,5,3,1.4,0.16,"},  // a row's F_k not its neighbours'
                                 {"\n1,1,5,3,1.4,", "\n1,1,5,3,1.41,"},           // a column's omega not its own
                                 {",periodic,", ",cyclic,"},
                                 {",0,periodic,1,2,0,5,", ",0,periodic,1,2,0,5,-"}}) {  // a negative amplitude
    EXPECT_THROW(ReadModelBruteForceMapCsv(damaged(from, to), "map.csv"), InvalidInput) << from << " -> " << to;
  }
  ModelBruteForceMap map = ReadModelBruteForceMapCsv(whole, "map.csv");
  map.cells[0].attractors[0].contact_amplitude = std::numeric_limits<double>::quiet_NaN();
  const std::string with_nan = BruteForceMapCsv(map);
  EXPECT_EQ(BruteForceMapCsv(ReadModelBruteForceMapCsv(with_nan, "map.csv")), with_nan);
}

// The run fingerprint changes with everything the cells depend on, and with nothing else.
TEST(ModelBruteForceMap, FingerprintTellsRunsApart) {
  const Model model = DenHartogsMass();
  const ModelBruteForceMapOptions o = DenHartogGrid();
  const std::uint64_t run = ModelMapRunFingerprint(model, kDenHartogBase, o);
  ModelBruteForceMapOptions same = o;
  same.shard = 2;
  same.shards = 3;
  same.runs.threads = 5;
  same.progress = [](const Progress&) {};
  EXPECT_EQ(ModelMapRunFingerprint(model, kDenHartogBase, same), run);
  const std::vector<std::function<void(ModelBruteForceMapOptions&)>> changes = {
      [](auto& x) { x.first.to = 2.1; },          [](auto& x) { x.second.steps = 3; },
      [](auto& x) { x.second.parameter = "F_s"; }, [](auto& x) { x.runs.transient_periods = 201; },
      [](auto& x) { x.runs.seed = 2; },            [](auto& x) { x.runs.scatter = 0.5; },
      [](auto& x) { x.runs.periodicity_tolerance = 1e-7; }, [](auto& x) { x.runs.section_phase = 0.1; }};
  for (std::size_t k = 0; k < changes.size(); ++k) {
    ModelBruteForceMapOptions other = o;
    changes[k](other);
    EXPECT_NE(ModelMapRunFingerprint(model, kDenHartogBase, other), run) << "change " << k;
  }
  EXPECT_NE(ModelMapRunFingerprint(model, {1.5, 0.25, 0.3, 0.0}, o), run);
  LinearOscillatorData damped = model.Data();
  damped.damping(0, 0) = 0.01;
  EXPECT_NE(ModelMapRunFingerprint(Model(damped), kDenHartogBase, o), run);
}

TEST(ModelBruteForceMap, ValidateNamesTheField) {
  const Model forced = DenHartogsMass();
  const BeltCycle belt;
  const Model autonomous(belt.Data());
  const auto field = [](const Model& model, const Model::Parameters& base, const ModelBruteForceMapOptions& o) {
    try {
      ComputeModelBruteForceMap(model, base, o);
    } catch (const InvalidInput& e) {
      return e.field();
    }
    return std::string("(accepted)");
  };
  ModelBruteForceMapOptions o = DenHartogGrid();
  o.first.parameter = "chi";
  EXPECT_EQ(field(forced, kDenHartogBase, o), "first");
  o = DenHartogGrid();
  o.second.parameter = "omega";
  EXPECT_EQ(field(forced, kDenHartogBase, o), "second");
  o = DenHartogGrid();
  o.first.steps = 0;
  EXPECT_EQ(field(forced, kDenHartogBase, o), "first-steps");
  o = DenHartogGrid();
  o.second.to = 0.3;  // F_k above F_s = 0.25 in the last row
  EXPECT_EQ(field(forced, kDenHartogBase, o), "grid");
  o = DenHartogGrid();
  o.first.to = 1e300;
  EXPECT_EQ(field(forced, kDenHartogBase, o), "grid");
  o = DenHartogGrid();
  o.shard = 3;
  o.shards = 2;
  EXPECT_EQ(field(forced, kDenHartogBase, o), "shard");
  o = DenHartogGrid();
  o.first.steps = ModelBruteForceMapOptions::kMaxSteps;
  o.second.steps = ModelBruteForceMapOptions::kMaxSteps;
  EXPECT_EQ(field(forced, kDenHartogBase, o), "grid");  // 1e8 cells: more runs than one shard may hold
  o = DenHartogGrid();
  o.runs.periodicity_tolerance = 0.0;
  EXPECT_EQ(field(forced, kDenHartogBase, o), "tolerance");
  o = DenHartogGrid();
  o.first.from = -1.5e308;  // every value finite, not the step between them
  o.first.to = 1.5e308;
  EXPECT_EQ(field(forced, kDenHartogBase, o), "first-to");
  o = DenHartogGrid();
  o.second.from = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(field(forced, kDenHartogBase, o), "second-from");
  o = DenHartogGrid();
  o.first.parameter = "";
  EXPECT_EQ(field(forced, kDenHartogBase, o), "first");
  EXPECT_THROW(ModelBruteForce(forced, kDenHartogBase, {"chi", 1.2, 2.0, 2}, o.runs), InvalidInput);
  o = DenHartogGrid();  // omega plays no part without forcing
  o.second.parameter = "F_s";
  o.second.from = 1.2;
  o.second.to = 1.5;
  o.runs.time_unit = 1.0;
  EXPECT_EQ(field(autonomous, {1.0, belt.F_k, belt.F_s, 0.5}, o), "first");
  // A coordinate 'b' has the velocity column v_b, which the belt's speed would share in the file.
  LinearOscillatorData named = belt.Data();
  named.coordinates = {"b"};
  o.first = {"v_b", 0.2, 0.4, 2};
  EXPECT_EQ(field(Model(named), {1.0, belt.F_k, belt.F_s, 0.5}, o), "first");
}

}  // namespace
}  // namespace stickslip
