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
#include "model_find.hpp"
#include "start_options.hpp"
#include "stickslip/io/atomic_file.hpp"
#include "stickslip/io/command_options.hpp"
#include "stickslip/io/map_file.hpp"
#include "stickslip/io/model_map.hpp"
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
  std::string model;  // --model FILE: a run file's [model] (io/model_map.hpp)
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
  std::vector<std::string> texts;
  for (const std::string& path : args.shards) texts.push_back(ReadShardFile(path));
  const MapFile merged = MergeMapFiles(texts, args.shards, args.merge);
  WriteFileAtomically(args.merge, merged.text);
  fmt::print("merged {} shard(s): {}", args.shards.size(), merged.summary);
  return kExitOk;
}

template <typename Map>
std::string MapSweepSummary(const Map& map, const std::string& output) {
  int attractors = 0, coexisting = 0, unsettled = 0;
  for (const auto& cell : map.cells) {
    attractors += static_cast<int>(cell.attractors.size());
    coexisting += cell.attractors.size() > 1;
    for (const auto& a : cell.attractors) unsettled += a.status != AttractorStatus::kPeriodic;
  }
  return fmt::format("map {} x {} ({} x {} cells): {} cell(s), {} attractor(s), {} cell(s) with more than one, {} "
                     "not settled or incomplete; written to {}\n",
                     AxisName(map.first), AxisName(map.second), map.first_count, map.second_count, map.cells.size(),
                     attractors, coexisting, unsettled, output);
}

// The command as the library reads it: the axes, the brute force's flags and the shard.
MapSweepCommand CommandOf(const MapSweepArgs& args) {
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
  return c;
}

// Ranks split the rows as shards do (rank 0, the first shard, has the most), so the bound on the
// runs is checked for a rank's rows.
MapSweepCommand CheckedForRanks(MapSweepCommand c, int ranks) {
  if (ranks > 1 && c.shards == 1) c.shards = ranks;
  return c;
}

// The plan that computes a shard of the map `compute` makes of `options` (either model's).
template <typename Options, typename Compute>
MapSweepPlan PlanWith(const Options& options, Compute compute, const MapSweepCommand& c, const MapSweepArgs& args) {
  const auto shard = [options, compute, output = args.output](int k, int n, const ProgressCallback& progress) {
    Options o = options;
    o.shard = k;
    o.shards = n;
    o.progress = progress;
    const auto map = compute(o);
    return MapFile{BruteForceMapCsv(map), MapSweepSummary(map, output)};
  };
  return {shard, c.shard, c.shards, args.output, args.force};
}

// --merge joins files: an option of the computation given with it would be ignored.
void RefuseWithMerge(const CLI::App& cmd) {
  for (const CLI::Option* option : cmd.get_options()) {
    const std::string name = option->get_name();
    if (option->count() == 0 || name == "--merge" || name == "--force" || name == "shards") continue;
    throw InvalidInput::WithMessage(name.substr(name.starts_with("--") ? 2 : 0),
                                    fmt::format("{} is not taken with --merge: it joins the shard files as they are "
                                                "(--merge OUT SHARD.csv... [--force])",
                                                name));
  }
}

MapSweepPlan PlanOf(const MapSweepArgs& args, int ranks) {
  const ModelStart input = BuildModelStart(ToStartInput(args.origin));
  const MapSweepCommand c = CommandOf(args);
  const auto compute = [base = input.parameters, phi = input.phi](const BruteForceMapOptions& o) {
    return ComputeBruteForceMap(base, phi, o);
  };
  return PlanWith(MapOptionsOf(CheckedForRanks(c, ranks), input), compute, c, args);
}

// map-sweep --model: the run file's oscillator at its parameters and --set's, the scattered starts
// around its start state, the section at its phase.
MapSweepPlan ModelPlanOf(const MapSweepArgs& args, const CLI::App& cmd, int ranks) {
  RefuseWithModel(cmd, {"--preset", "--point", "--results"},
                  "the run file's [model] and --set give the oscillator, its parameters and the start the "
                  "scattered starts are drawn around");
  RefuseOutputOverModel(args.output, args.model, "output");
  const ModelFileStart start = ReadModelFileStart(args.model, ModelSetOf(args.origin.set));
  MapSweepCommand c = CommandOf(args);
  if (cmd.count("--first") == 0) c.first.clear();  // the model's own defaults (ModelMapOptionsOf)
  if (cmd.count("--second") == 0) c.second.clear();
  const auto compute = [model = start.model, base = start.parameters](const ModelBruteForceMapOptions& o) {
    return ComputeModelBruteForceMap(model, base, o);
  };
  return PlanWith(ModelMapOptionsOf(CheckedForRanks(c, ranks), start), compute, c, args);
}

}  // namespace

void CheckMapOutputFile(const std::string& path, const std::string& field, bool force) {
  CheckReplaceableOutputFile(path, field, {"stickslip map-sweep", IsBruteForceMapCsvHeader}, force);
}

MapFile MergeMapFiles(const std::vector<std::string>& texts, const std::vector<std::string>& names,
                      const std::string& output) {
  const auto merged = [&](auto read) {
    std::vector<decltype(read(texts[0], names[0]))> maps;
    for (std::size_t s = 0; s < texts.size(); ++s) maps.push_back(read(texts[s], names[s]));
    const auto map = MergeBruteForceMaps(maps, names);
    return MapFile{BruteForceMapCsv(map), MapSweepSummary(map, output)};
  };
  // Either model's map, by the first shard's header; a shard of the other kind has a header its reader refuses.
  if (!texts.empty() && IsModelBruteForceMapCsv(texts[0])) return merged(ReadModelBruteForceMapCsv);
  return merged(ReadBruteForceMapCsv);
}

int RunMapSweepHere(const MapSweepPlan& plan) {
  CheckMapOutputFile(plan.output, "output", plan.force);
  ProgressLine line("map-sweep");
  const MapFile map = plan.compute(plan.shard, plan.shards, line.Callback());
  line.Clear();
  WriteFileAtomically(plan.output, map.text);
  fmt::print("{}", map.summary);
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
      "type) and how many starts found it; motions that do not settle are listed as not-settled. With --model "
      "each row is the brute force of atlas --model: rest, --starts scattered states and the neighbouring "
      "cells' ends both ways along the row (a chained sweep up and down). ") +
          (shards ? "The file does not depend on --threads, --shard or MPI ranks. --shard k/N computes the rows j with j "
                    "mod N = k - 1; --merge OUT SHARD.csv... joins the shards into the file the whole run writes. "
                  : "The file does not depend on --threads or the number of ranks. ") +
          "Time is the paper's scaled time; with --model the model's own units, --tolerance relative to the "
          "section states' size and each attractor's amplitude:<contact> in place of its signature.");
  AddStartOptions(*cmd, &args->origin, StartOptions::kMotion);
  cmd->add_option("--model", args->model,
                  "a run file with a [model] (an oscillator of your own, in its units): its map over two of its "
                  "parameters (--first, --second by its names; unless given omega, v_b without forcing, and F_s); --set NAME=VALUE sets "
                  "its parameters and the start the scattered starts are drawn around (x1_0=..., phi=...)")
      ->type_name("FILE");
  cmd->add_option("--results", args->origin.results, "where the runs of --point are stored")->capture_default_str();
  const std::string range = "the parameter's valid range (every cell is checked)";
  cmd->add_option("--first", args->first,
                  "the parameter stepped along i: chi, eta, omega, u_s or u_r (a [model]'s by its names)")
      ->capture_default_str();
  AddNumberOption(*cmd, "--first-from", &args->first_from, range, "its value at i = 0 (its range under --set; every cell is checked)");
  AddNumberOption(*cmd, "--first-to", &args->first_to, range, "its value at i = --first-steps");
  AddCountOption(*cmd, "--first-steps", &args->first_steps, 0, BruteForceMapOptions::kMaxSteps,
                 "intervals along i (0 to 1e4; with --model 1 to 1e4)");
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
                  "stops_per_period,sticks_per_period,starts,signature,k,x1,x2,v1,v2 (with --model: "
                  "...,starts,amplitude:<contact>,k,<the state by the model's names>)");
  cmd->add_flag("--force", args->force, kForceHelp);
  if (shards) {
    cmd->add_option("--merge", args->merge, "merge the SHARD files into this file instead of computing");
    cmd->add_option("shards", args->shards, "with --merge: the shard files (every cell of one map once)");
  }
  return {cmd, [args, runner, cmd, shards, ranks] {
            if (shards && cmd->count("--merge") > 0) {
              RefuseWithMerge(*cmd);
              return RunMerge(*args);
            }
            if (!args->shards.empty()) {
              throw InvalidInput("shards", "'" + args->shards.front() + "'", "shard files only with --merge OUT");
            }
            for (const char* option : {"first-from", "first-to", "second-from", "second-to", "output"}) {
              if (cmd->count(fmt::format("--{}", option)) == 0) {
                throw InvalidInput(option, "(not given)", fmt::format("--{} is required unless --merge", option));
              }
            }
            if (cmd->count("--model") > 0) {
              if (args->model.empty()) throw InvalidInput("model", "''", "a run file with a [model]");
              return runner(ModelPlanOf(*args, *cmd, ranks));
            }
            return runner(PlanOf(*args, ranks));
          }};
}

}  // namespace stickslip::cli
