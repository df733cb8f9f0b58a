// The brute-force map of motions over two parameters: a grid of cells (i, j), the first parameter
// stepped along i and the second along j, and in each cell the attractors that simulation finds
// from several initial states, each simulated out (SimulateSettled, analysis/settled_motion.hpp,
// the sweep's per-point computation):
//   - rest (x1 = x2 = v1 = v2 = 0),
//   - the neighbouring cell's final state: along each row j, cell i > 0 starts from where the
//     neighbour run of cell i - 1 ended (cell 0's neighbour run is its rest run), so the
//     attractor is followed along the row as a chained sweep follows it; rows are independent,
//   - scattered_starts states: `centre` and states drawn around it (ScatteredStarts, as the
//     sweep's chains start; the same in every cell).
// The runs that end on the same periodic section orbit (same period, the same section points to
// periodicity_tolerance under some cyclic shift) are one attractor; a run whose period was reduced
// to the least one it contracts onto (SettledMotion::period) widens that tolerance by the distance
// it may still be from that orbit (SettledMotion::settling). A run that does not settle on
// a periodic section (period 0) is kept as a "not-settled" entry (all such runs of a cell are one
// entry: they cannot be told apart), one whose simulation stopped early as "incomplete"; none is
// dropped. Periodic attractors carry the signature read off the exact simulator's events over one
// period (ReadMotionType, analysis/motion_type.hpp, as FindOrbit reads it).
//
// The result does not depend on the number of threads: every run writes its own slot and the
// neighbour chain of a row is one sequential work item. shard/shards computes only the rows j with
// j mod shards = shard - 1 (for job arrays and MPI ranks); the shards merged (io/map_file.hpp) give
// the unsharded map.
//
//   BruteForceMapOptions o;  // by default omega along i and u_r along j: their ranges
//   o.first.from = 0.5, o.first.to = 0.7, o.first.steps = 20;
//   o.second.from = 0.2, o.second.to = 0.6, o.second.steps = 20;
//   const BruteForceMap map = ComputeBruteForceMap(paper_parameters, phi, o);
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "stickslip/model/pascal_2014/flows.hpp"
#include "stickslip/model/pascal_2014/parameters.hpp"
#include "stickslip/model/pascal_2014.hpp"
#include "stickslip/progress.hpp"

namespace stickslip {

// The axes a map has unless told: the model's forcing frequency along i, its static friction level
// along j (omega and u_r in the paper's model).
inline constexpr ParameterId kDefaultFirstAxis = kAllParameters[Pascal2014::kForcingFrequencyParameter];
inline constexpr ParameterId kDefaultSecondAxis = kAllParameters[Pascal2014::kStaticLevelParameter];

// The value at index 0..steps of steps + 1 values from `from` to `to`, evenly spaced; index steps is
// `to` exactly (from + (to - from) may miss it by an ulp).
double GridValueAt(double from, double to, int steps, int index);

// One axis of the grid: steps + 1 values from `from` to `to`, evenly spaced.
struct MapAxis {
  ParameterId parameter = kDefaultFirstAxis;
  double from = 0.0;
  double to = 0.0;
  int steps = 10;  // intervals between from and to (0 to BruteForceMapOptions::kMaxSteps): one value when 0

  int Count() const { return steps + 1; }
  double ValueAt(int index) const;  // GridValueAt
};

struct BruteForceMapOptions {
  MapAxis first{kDefaultFirstAxis};    // index i; the neighbour chain runs along it
  MapAxis second{kDefaultSecondAxis};  // index j; each value is a row
  int transient_periods = 500;  // forcing periods discarded per run (0 to kMaxTransientPeriods)
  // Forcing periods recorded per run (2 to kMaxRecordedPeriods): periods up to recorded/2 are
  // detected; a signature is read when the record holds the origin and one whole period after it
  // (about 2 k + 1 forcing periods for period k).
  int recorded_periods = 24;
  // Starts per cell besides rest and the neighbour (0 to kMaxScatteredStarts): `centre` first, then
  // states drawn from the box |x - centre|_inf <= scatter (0 to 1e6).
  int scattered_starts = 4;
  State centre = State::Zero();
  double scatter = 1.0;
  std::uint64_t seed = 1;     // of the scattered starts (splitmix64: the same on every platform)
  // Section points repeat (and two runs' section orbits agree) within this, absolute, |.|_inf
  // (kMinTolerance to kMaxTolerance).
  double periodicity_tolerance = 1e-6;
  int max_events_per_simulation = 1000000;  // the simulator's guard against chattering, per simulation
  int shard = 1;   // compute the rows j with j mod shards == shard - 1 (1 <= shard <= shards)
  int shards = 1;  // 1 to kMaxShards
  int threads = 0;  // 0: every hardware thread (0 to 1024). The result does not depend on it.
  // Called after every cell with done = the cells finished and total = the cells of the shard
  // (unit "cells"), one call at a time, done increasing. Empty: no reports.
  ProgressCallback progress = {};

  static constexpr int kMaxSteps = 10000;
  static constexpr int kMaxRecordedPeriods = 100000;
  static constexpr int kMaxScatteredStarts = 1000;
  static constexpr int kMaxShards = 100000;
  // The runs one computation (one shard) holds in memory, at most: rows of the shard x cells of a
  // row x (2 + scattered_starts). A larger grid is computed in shards (or MPI ranks).
  static constexpr long long kMaxRuns = 10000000;
  static constexpr double kMinTolerance = 1e-14;
  static constexpr double kMaxTolerance = 1e-2;

  // Throws InvalidInput naming the member ("first.steps", "recorded_periods", "shard", ...) out of
  // range, the two axes' parameter when they are the same ("second.parameter"), or "grid" for a
  // cell whose parameters fail Validate (u_r < u_s, a natural frequency, ...) or a shard of more
  // than kMaxRuns runs.
  void Validate(const Parameters& base) const;
};

enum class AttractorStatus {
  kPeriodic,    // the section repeats after `period` forcing periods
  kNotSettled,  // no period <= recorded/2 on the section after the transient
  kIncomplete,  // a simulation stopped early (max events, the event search's bound)
};
const char* ToString(AttractorStatus status);  // "periodic", "not-settled", "incomplete"
std::optional<AttractorStatus> AttractorStatusFromString(std::string_view text);  // nullopt: none

struct Attractor {
  AttractorStatus status = AttractorStatus::kNotSettled;
  int period = 0;  // forcing periods; 0 unless periodic
  double stops_per_period = 0.0;   // over the recorded periods of the first run that found it
  double sticks_per_period = 0.0;
  std::string signature;  // the orbit type (Signature::ToString); empty when none was read
  int starts = 0;         // how many of the cell's runs ended on it
  // Periodic: its `period` section points, from the first recorded one of the first run that
  // found it; otherwise one state, where that run ended.
  std::vector<State> section;
};

struct MapCell {
  int i = 0;
  int j = 0;
  double first = 0.0;   // the first parameter's value
  double second = 0.0;  // the second parameter's value
  std::vector<Attractor> attractors;  // in the order found: rest, neighbour, scattered
};

struct BruteForceMap {
  ParameterId first = kDefaultFirstAxis;
  ParameterId second = kDefaultSecondAxis;
  int first_count = 0;   // cells along i
  int second_count = 0;  // cells along j
  double section_phase = 0.0;  // the forcing phase at the section times
  // What every cell depends on besides its own parameters (MapRunFingerprint): shards of one map
  // share it, shards of other runs (other data, starts or options) do not.
  std::uint64_t run = 0;
  std::vector<MapCell> cells;  // the computed cells, by j then i
};

// A 64-bit hash (FNV-1a over the values' bits, the same on every platform) of the base parameters,
// the section phase, both axes and every option the cells depend on: all of `options` but shard,
// shards, threads and progress.
std::uint64_t MapRunFingerprint(const Parameters& base, double phi_section, const BruteForceMapOptions& options);

// The rows of a shard: j mod shards == shard - 1.
bool RowInShard(int j, int shard, int shards);

// The map around `base` (the two axes' parameters replaced in each cell), sections at forcing
// phase phi_section (time 0 of every run). Throws InvalidInput (Validate); every simulation
// outcome is recorded in the cells. Bounded: per cell at most 2 + scattered_starts runs, each of
// transient_periods + recorded_periods forcing periods within max_events per simulation.
BruteForceMap ComputeBruteForceMap(const Parameters& base, double phi_section, const BruteForceMapOptions& options);

}  // namespace stickslip
