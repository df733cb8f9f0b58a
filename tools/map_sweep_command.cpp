// stickslip map-sweep: the brute-force map of motions over two parameters, in this process on
// every core, in shards (--shard k/N) merged afterwards (--merge), or across machines with MPI
// (stickslip-mpi map-sweep).
#include "map_sweep_command.hpp"

#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "brute_force_flags.hpp"
#include "cli_common.hpp"
#include "progress_line.hpp"
#include "start_options.hpp"
#include "stickslip/io/atomic_file.hpp"
#include "stickslip/io/command_options.hpp"
#include "stickslip/io/map_file.hpp"
#include "stickslip/io/output_marker.hpp"
#include "stickslip/model/transient.hpp"

namespace stickslip::cli {

namespace {

// The options as given, with the library's defaults (BruteForceMapOptions).
const BruteForceMapOptions kDefaults;
struct MapSweepArgs {
  StartFlags origin;
  std::string first = ToString(kDefaults.first.parameter);
  std::string second = ToString(kDefaults.second.parameter);
  double first_from = 0.0, first_to = 0.0, second_from = 0.0, second_to = 0.0;  // required
  int first_steps = kDefaults.first.steps;
  int second_steps = kDefaults.second.steps;
  BruteForceFlags brute;
  std::string shard = fmt::format("{}/{}", kDefaults.shard, kDefaults.shards);
  std::string output;
  std::string merge;  // the merged file
  std::vector<std::string> shards;
  bool force = false;
};

const std::string kShardRange = fmt::format("k/N with whole numbers 1 <= k <= N <= {}", BruteForceMapOptions::kMaxShards);

// "k/N" -> (k, N).
std::pair<int, int> ParseShard(const std::string& text) {
  const auto slash = text.find('/');
  if (slash != std::string::npos) {
    try {
      const int k = ParseCount("shard", text.substr(0, slash), 1, BruteForceMapOptions::kMaxShards);
      const int n = ParseCount("shard", text.substr(slash + 1), 1, BruteForceMapOptions::kMaxShards);
      if (k <= n) return {k, n};
    } catch (const InvalidInput&) {
    }
  }
  throw InvalidInput("shard", "'" + text + "'", kShardRange);
}

// A shard file whole. Regular files only: a device would be read without end (/dev/zero) and a
// pipe would block.
std::string ReadShardFile(const std::string& path) {
  const auto refuse = [&] { return InvalidInput("shards", "'" + path + "'", "a readable map file of stickslip map-sweep"); };
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) throw refuse();
  std::ifstream in(path, std::ios::binary);
  if (!in) throw refuse();
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

int RunMerge(const MapSweepArgs& args) {
  if (args.shards.empty()) throw InvalidInput("merge", "'" + args.merge + "'", "--merge OUT SHARD.csv... with at least one shard file");
  CheckMapOutputFile(args.merge, "merge", args.force);
  for (const std::string& path : args.shards) {
    std::error_code error;  // none when OUT does not exist yet
    if (std::filesystem::equivalent(args.merge, path, error)) {
      throw InvalidInput::WithMessage("merge", fmt::format("merge = '{}' is invalid: it is the shard '{}': valid a file "
                                                           "other than the shards (the merge would replace it)",
                                                           args.merge, path));
    }
  }
  std::vector<BruteForceMap> maps;
  for (const std::string& path : args.shards) maps.push_back(ReadBruteForceMapCsv(ReadShardFile(path), path));
  const BruteForceMap merged = MergeBruteForceMaps(maps, args.shards);
  WriteFileAtomically(args.merge, BruteForceMapCsv(merged));
  fmt::print("merged {} shard(s): {}", args.shards.size(), MapSweepSummary(merged, args.merge));
  return kExitOk;
}

MapSweepPlan PlanOf(const MapSweepArgs& args, int ranks) {
  const ModelStart input = BuildModelStart(ToStartInput(args.origin));
  MapSweepCommand c = WithBruteForceFlags(MapSweepCommand{}, args.brute);
  c.first = args.first;
  c.second = args.second;
  c.first_from = args.first_from;
  c.first_to = args.first_to;
  c.first_steps = args.first_steps;
  c.second_from = args.second_from;
  c.second_to = args.second_to;
  c.second_steps = args.second_steps;
  std::tie(c.shard, c.shards) = ParseShard(args.shard);
  // Ranks split the rows as shards do (rank 0, the first shard, has the most), so the bound on the
  // runs is checked for a rank's rows.
  MapSweepCommand checked = c;
  if (ranks > 1 && c.shards == 1) checked.shards = ranks;
  BruteForceMapOptions options = MapOptionsOf(checked, input);
  options.shard = c.shard;
  options.shards = c.shards;
  return {input.parameters, input.phi, options, args.output, args.force};
}

}  // namespace

void CheckMapOutputFile(const std::string& path, const std::string& field, bool force) {
  CheckReplaceableOutputFile(path, field, {"stickslip map-sweep", IsBruteForceMapCsvHeader}, force);
}

std::string MapSweepSummary(const BruteForceMap& map, const std::string& output) {
  int attractors = 0, coexisting = 0, unsettled = 0;
  for (const MapCell& cell : map.cells) {
    attractors += static_cast<int>(cell.attractors.size());
    coexisting += cell.attractors.size() > 1;
    for (const Attractor& a : cell.attractors) unsettled += a.status != AttractorStatus::kPeriodic;
  }
  return fmt::format("map {} x {} ({} x {} cells): {} cell(s), {} attractor(s), {} cell(s) with more than one, {} "
                     "not settled or incomplete; written to {}\n",
                     ToString(map.first), ToString(map.second), map.first_count, map.second_count, map.cells.size(),
                     attractors, coexisting, unsettled, output);
}

int RunMapSweepHere(const MapSweepPlan& plan) {
  CheckMapOutputFile(plan.output, "output", plan.force);
  BruteForceMapOptions options = plan.options;
  ProgressLine line("map-sweep");
  options.progress = line.Callback();
  const BruteForceMap map = ComputeBruteForceMap(plan.base, plan.phi, options);
  line.Clear();
  WriteFileAtomically(plan.output, BruteForceMapCsv(map));
  fmt::print("{}", MapSweepSummary(map, plan.output));
  return kExitOk;
}

Command AddMapSweepCommand(CLI::App& app, MapSweepRunner runner, bool shards, int ranks) {
  auto args = std::make_shared<MapSweepArgs>();
  CLI::App* cmd = app.add_subcommand(
      "map-sweep",
      std::string("Brute-force map of motions over two parameters (exit codes as stickslip's): a grid of (--first-steps"
      " + 1) x (--second-steps + 1) cells, and in each cell the attractors that simulation finds from rest,"
      " from where the run of the neighbouring cell (i - 1, same j) ended, and from --starts states: the "
      "given one (--preset's, --set x10=...) and states scattered around it (--scatter, --seed): "
      "--transients forcing periods simulated out, then --periods recorded on the stroboscopic section (the"
      " state at forcing phase phi). Runs that end on the same periodic section orbit (to --tolerance, any "
      "shift) are one attractor, listed with its period, stops and sticks per period, signature (orbit "
      "type) and how many starts found it; motions that do not settle are listed as not-settled. ") +
          (shards ? "The file does not depend on --threads, --shard or MPI ranks. --shard k/N computes the rows j with j "
                    "mod N = k - 1; --merge OUT SHARD.csv... joins the shards into the file the whole run writes. "
                  : "The file does not depend on --threads or the number of ranks. ") +
          "Time is the paper's scaled time.");
  AddStartOptions(*cmd, &args->origin, StartOptions::kMotion);
  cmd->add_option("--results", args->origin.results, "where the runs of --point are stored")->capture_default_str();
  const std::string range = "the parameter's valid range (every cell is checked)";
  cmd->add_option("--first", args->first, "the parameter stepped along i: chi, eta, omega, u_s or u_r")->capture_default_str();
  AddNumberOption(*cmd, "--first-from", &args->first_from, range, "its value at i = 0 (its range under --set; every cell is checked)");
  AddNumberOption(*cmd, "--first-to", &args->first_to, range, "its value at i = --first-steps");
  AddCountOption(*cmd, "--first-steps", &args->first_steps, 0, BruteForceMapOptions::kMaxSteps,
                 "intervals along i (0 to 1e4)");
  cmd->add_option("--second", args->second, "the parameter stepped along j (a row per value)")->capture_default_str();
  AddNumberOption(*cmd, "--second-from", &args->second_from, range, "its value at j = 0 (its range under --set)");
  AddNumberOption(*cmd, "--second-to", &args->second_to, range, "its value at j = --second-steps");
  AddCountOption(*cmd, "--second-steps", &args->second_steps, 0, BruteForceMapOptions::kMaxSteps,
                 "intervals along j (0 to 1e4)");
  AddBruteForceFlags(*cmd, &args->brute, "cell");
  if (shards) {
    cmd->add_option("--shard", args->shard, "compute only the rows j with j mod N = k - 1 (k/N, 1 <= k <= N)")
        ->type_name("K/N")->capture_default_str();
  }
  cmd->add_option("--output", args->output,
                  "CSV file: i,j,ni,nj,<first>,<second>,section_phase,run,attractors,attractor,status,period,"
                  "stops_per_period,sticks_per_period,starts,signature,k,x1,x2,v1,v2");
  cmd->add_flag("--force", args->force, kForceHelp);
  if (shards) {
    cmd->add_option("--merge", args->merge, "merge the SHARD files into this file instead of computing");
    cmd->add_option("shards", args->shards, "with --merge: the shard files (every cell of one map once)");
  }
  return {cmd, [args, runner, cmd, shards, ranks] {
            if (shards && cmd->count("--merge") > 0) return RunMerge(*args);
            if (!args->shards.empty()) {
              throw InvalidInput("shards", "'" + args->shards.front() + "'", "shard files only with --merge OUT");
            }
            for (const char* option : {"first-from", "first-to", "second-from", "second-to", "output"}) {
              if (cmd->count(fmt::format("--{}", option)) == 0) {
                throw InvalidInput(option, "(not given)", fmt::format("--{} is required unless --merge", option));
              }
            }
            return runner(PlanOf(*args, ranks));
          }};
}

}  // namespace stickslip::cli
