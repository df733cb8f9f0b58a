// The brute-force map of an oscillator of the user's over two of its parameters (the paper's model's
// is brute_force_map.hpp): a grid of cells (i, j), `first` stepped along i and `second` along j,
// each row j the brute force along `first` (model_brute_force.hpp) with `second` at its value:
// runs from rest and from scattered starts, and the chained sweep from rest up and down the row,
// merged into the row's attractors cell by cell.
//
// The result does not depend on the number of threads. shard/shards computes only the rows j with
// j mod shards = shard - 1 (job arrays, MPI ranks); the shards merged (io/map_file.hpp) give the
// unsharded map.
//
//   ModelBruteForceMapOptions o;
//   o.first = {"omega", 0.3, 1.5, 40};
//   o.second = {"F_s", 0.3, 0.6, 10};
//   const ModelBruteForceMap map = ComputeModelBruteForceMap(model, parameters, o);
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "stickslip/analysis/model_brute_force.hpp"
#include "stickslip/model/linear_oscillator.hpp"

namespace stickslip {

struct ModelBruteForceMapOptions {
  // Index i, 1 to kMaxSteps steps: each row's brute force runs along it; index j, 0 to kMaxSteps
  // steps: a row per value. Their parameters by the model's names (DefaultMapAxes: what a front
  // end takes unless told).
  ModelAxis first{""};
  ModelAxis second{""};
  ModelBruteForceOptions runs;  // every row's (its progress replaced by the map's)
  int shard = 1;   // compute the rows j with j mod shards == shard - 1 (1 <= shard <= shards)
  int shards = 1;  // 1 to kMaxShards
  // Called after every run with done = the runs finished and total = the runs of the shard (unit
  // "runs"), one call at a time, done increasing. Empty: no reports.
  ProgressCallback progress = {};

  static constexpr int kMaxSteps = 10000;
  static constexpr int kMaxShards = 100000;
  // Runs of one shard, at most: its rows x cells of a row x ModelBruteForceOptions::RunsPerValue().
  static constexpr long long kMaxRuns = 10000000;

  // Throws InvalidInput naming the field as the command line's flag ("first", "first-from",
  // "first-to", "first-steps", the same of "second", "shard", "shards", the brute force's), or
  // "grid" for a cell whose parameters the model refuses or a shard of more than kMaxRuns runs.
  void Validate(const DynamicLinearOscillator& model, const DynamicLinearOscillator::Parameters& base) const;
};

// The parameters a model's map has unless told: along i its forcing frequency (the belt's speed
// without forcing), along j its static friction level.
inline std::pair<std::string, std::string> DefaultMapAxes(const DynamicLinearOscillator& model) {
  const ModelDescription& d = model.Description();
  return {d.parameters[model.Autonomous() ? DynamicLinearOscillator::kRestVelocityParameter
                                           : DynamicLinearOscillator::kForcingFrequencyParameter].name,
          d.parameters[DynamicLinearOscillator::kStaticLevelParameter].name};
}

// A map's parameter by its name, either model's (the paper's map holds a ParameterId).
inline const std::string& AxisName(const std::string& name) { return name; }
inline std::string AxisName(ParameterId id) { return std::string(ToString(id)); }

struct ModelMapCell {
  int i = 0;
  int j = 0;
  double first = 0.0;   // the first parameter's value
  double second = 0.0;  // the second parameter's value
  std::vector<ModelAttractor> attractors;  // in the order found
};

struct ModelBruteForceMap {
  std::string first;   // the parameters' names
  std::string second;
  std::string contact;  // the contact's coordinate by the model's name: its amplitude is each attractor's
  std::vector<std::string> state_columns;  // the state's components by the model's names (ModelDescription)
  int first_count = 0;   // cells along i
  int second_count = 0;  // cells along j
  double section_phase = 0.0;
  // What every cell depends on besides its own parameters (ModelMapRunFingerprint): shards of one
  // map share it, shards of other runs do not.
  std::uint64_t run = 0;
  std::vector<ModelMapCell> cells;  // the computed cells, by j then i
};

// A 64-bit hash (FNV-1a over the values' bits, the same on every platform) of the model's data,
// the base parameters, both axes and every option the cells depend on (not shard, shards, threads
// or progress).
std::uint64_t ModelMapRunFingerprint(const DynamicLinearOscillator& model, const DynamicLinearOscillator::Parameters& base,
                                     const ModelBruteForceMapOptions& options);

// The map around `base` (the two parameters replaced in each cell). Throws InvalidInput (Validate);
// every simulation outcome is recorded in the cells.
ModelBruteForceMap ComputeModelBruteForceMap(const DynamicLinearOscillator& model,
                                             const DynamicLinearOscillator::Parameters& base,
                                             const ModelBruteForceMapOptions& options);

}  // namespace stickslip
