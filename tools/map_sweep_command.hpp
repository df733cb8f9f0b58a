// stickslip map-sweep: the brute-force map over two parameters (analysis/brute_force_map.hpp, and
// a run file's [model]'s: analysis/model_brute_force_map.hpp), its --shard option and its --merge
// step. Declared here for the MPI front end (map_sweep_mpi_main.cpp), which parses the same options
// and computes the map on every rank.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "commands.hpp"
#include "stickslip/progress.hpp"

namespace stickslip::cli {

struct MapFile {
  std::string text;     // the map's file
  std::string summary;  // the line printed after it is written
};

// What the options describe: checked, the output not yet (the runner checks it where it writes).
struct MapSweepPlan {
  // The map's rows j with j mod shards == shard - 1 as its file (io/map_file.hpp) with the line
  // printed after it is written to `output`; `progress` called per cell or run.
  std::function<MapFile(int shard, int shards, const ProgressCallback& progress)> compute;
  int shard = 1;   // --shard k/N
  int shards = 1;
  std::string output;
  bool force = false;  // --force: replace a file map-sweep did not write
};
using MapSweepRunner = std::function<int(const MapSweepPlan&)>;

// In this process, on --threads threads; writes the map file whole.
int RunMapSweepHere(const MapSweepPlan& plan);
// Throws InvalidInput naming `field` unless `path` can be written and is new, a map file (its
// header is a map file's), or `force` (--force) is given: checked before the work.
void CheckMapOutputFile(const std::string& path, const std::string& field, bool force);

// The map files `texts` (shards of one map, either model's; `names[s]` names texts[s] in messages)
// merged into one. Throws InvalidInput (ReadBruteForceMapCsv, MergeBruteForceMaps).
MapFile MergeMapFiles(const std::vector<std::string>& texts, const std::vector<std::string>& names,
                        const std::string& output);

// The subcommand; `runner` computes and writes the map. With `shards`, --shard k/N and --merge OUT
// SHARD... too; without (the MPI front end, whose ranks split the rows), neither is offered.
// `ranks`: the MPI job's ranks, which split the rows as --shard does (the grid's bound on the runs
// of one computation is checked for one rank's rows).
Command AddMapSweepCommand(CLI::App& app, MapSweepRunner runner = RunMapSweepHere, bool shards = true, int ranks = 1);

}  // namespace stickslip::cli
