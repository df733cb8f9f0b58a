// stickslip atlas: every periodic motion over a range of one parameter (analysis/atlas.hpp): the
// brute force on a grid, the exact orbit of every attractor, a trace from each one on no branch
// yet; written to results/<output>/ (io/atlas_files.hpp).
#include <chrono>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "brute_force_flags.hpp"
#include "cli_common.hpp"
#include "commands.hpp"
#include "progress_line.hpp"
#include "start_options.hpp"
#include "stickslip/analysis/atlas.hpp"
#include "stickslip/io/atlas_files.hpp"
#include "model_find.hpp"
#include "stickslip/io/command_options.hpp"
#include "stickslip/io/model_atlas.hpp"
#include "stickslip/io/run.hpp"

namespace stickslip::cli {

namespace {

// The options as given, with the library's defaults (AtlasCommand).
const AtlasCommand kDefaults;
struct AtlasArgs {
  StartFlags origin;
  std::string parameter = kDefaults.parameter;
  std::string range;  // LO,HI: required
  int steps = static_cast<int>(kDefaults.steps);
  BruteForceFlags brute;
  int max_multiple = static_cast<int>(kDefaults.max_multiple);
  double max_amplitude = kDefaults.max_amplitude;
  int max_points = static_cast<int>(kDefaults.max_points);
  double resonance_approach = kDefaults.resonance_approach;
  std::string output;  // required
  std::string model;   // --model FILE: the atlas of a user's oscillator (analysis/model_atlas.hpp)
};

// "LO,HI": two numbers (AtlasOptionsOf checks LO < HI and each grid value).
std::pair<double, double> ParseRange(const std::string& text) {
  const std::string valid = "LO,HI with LO < HI, both within the parameter's valid range";
  const auto comma = text.find(',');
  if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos) {
    throw InvalidInput("range", "'" + text + "'", valid);
  }
  return {ParseNumber("range", text.substr(0, comma), valid), ParseNumber("range", text.substr(comma + 1), valid)};
}

AtlasCommand CommandOf(const AtlasArgs& args) {
  AtlasCommand c = WithBruteForceFlags(AtlasCommand{}, args.brute);
  c.parameter = args.parameter;
  std::tie(c.from, c.to) = ParseRange(args.range);
  c.steps = args.steps;
  c.max_multiple = args.max_multiple;
  c.max_amplitude = args.max_amplitude;
  c.max_points = args.max_points;
  c.resonance_approach = args.resonance_approach;
  return c;
}

template <typename AnyAtlas>
void Report(const std::string& output, const AnyAtlas& atlas, std::size_t values, const StoredAtlas& stored,
            double seconds, const std::vector<std::string>& kept, const std::filesystem::path& results) {
  std::size_t branches = 0;
  for (const StoredTrace& t : stored.traces) branches += t.branches.size();
  const int unexplained = static_cast<int>(atlas.attractors.size()) - atlas.OnBranches();
  fmt::print("{}: {} attractor(s) at {} value(s) of {}: {} periodic within the limit, {} on a branch, {} listed with "
             "the reason; {} trace(s), {} branch(es) in {:.1f} s\n",
             output, atlas.attractors.size(), values, atlas.parameter, atlas.PeriodicWithinLimit(),
             atlas.OnBranches(), unexplained, stored.traces.size(), branches, seconds);
  for (const auto& a : atlas.attractors) {
    if (a.fate == AttractorFate::kOnBranch) continue;
    fmt::print("  {} = {:.6g}, attractor {}: {}: {}\n", atlas.parameter, a.value, a.index + 1, ToString(a.fate), a.reason);
  }
  if (!kept.empty()) {
    fmt::print("{}: kept {} other file(s) of {}: {}\n", output, kept.size(), (results / output).string(), fmt::join(kept, ", "));
  }
}

std::size_t GridValues(const Atlas& atlas) { return atlas.brute_force.cells.size(); }
std::size_t GridValues(const ModelAtlas& atlas) { return atlas.grid.size(); }

// Checks the output before the work, computes the atlas (compute(progress)) under a progress line,
// records it (record(atlas)), writes its files and reports.
template <typename Compute, typename Record>
int ComputeAndWrite(const RunFile& run, const std::filesystem::path& results, Compute compute, Record record) {
  CheckAtlasOutputDirectory(results, run.output);
  ProgressLineOptions line_options;
  line_options.value_name = run.parameter;
  ProgressLine line(run.output, line_options);
  const auto started = std::chrono::steady_clock::now();
  const auto atlas = compute(line.Callback());
  line.Clear();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  const StoredAtlas stored = record(atlas);
  const std::vector<std::string> kept = WriteAtlasFiles(results, stored);
  Report(run.output, atlas, GridValues(atlas), stored, seconds, kept, results);
  return kExitOk;
}

int RunAtlas(const AtlasArgs& args) {
  const ModelStart origin = BuildModelStart(ToStartInput(args.origin));
  RunFile run = AsOneOffRun({});
  run.output = args.output;
  run.parameter = args.parameter;
  AtlasOptions options = AtlasOptionsOf(CommandOf(args), origin);
  return ComputeAndWrite(
      run, args.origin.results,
      [&](ProgressCallback progress) {
        options.progress = std::move(progress);
        return ComputeAtlas(origin.parameters, options);
      },
      [&](const Atlas& atlas) { return RecordAtlas(run, atlas, options); });
}

int RunModelAtlas(const AtlasArgs& args, const CLI::App& cmd) {
  RefuseWithModel(cmd, {"--preset", "--point"}, "the run file's [model] and --set give the oscillator and its parameters");
  const NamedValues set = ModelSetOf(args.origin.set);
  const ModelFileStart start = ReadModelFileStart(args.model, set);
  RunFile run;
  run.output = args.output;
  run.parameter = args.parameter;
  ModelAtlasOptions options = ModelAtlasOptionsOf(CommandOf(args), start);
  return ComputeAndWrite(
      run, args.origin.results,
      [&](ProgressCallback progress) {
        options.progress = std::move(progress);
        return ComputeModelAtlas(start.model, start.parameters, options);
      },
      [&](const ModelAtlas& atlas) { return StoredModelAtlas(atlas, options, start, args.model, set, args.output); });
}

}  // namespace

Command AddAtlasCommand(CLI::App& app) {
  auto args = std::make_shared<AtlasArgs>();
  CLI::App* cmd = app.add_subcommand(
      "atlas",
      "Every periodic motion over a range of one parameter: a brute force on a grid (--steps + 1 values; at each, "
      "runs from rest, from the neighbouring value's attractor and from --starts scattered states, as map-sweep's), "
      "the exact orbit of every attractor of period up to --max-multiple (find, whose transient doubles until the "
      "motion has settled), and a trace over the whole range from each exact orbit that lies on no branch traced "
      "before it. Every attractor ends on a branch (named with its point) or listed with the reason. Writes "
      "results/<output>/: trace-<t>/ (each a trace's directory), atlas.json, atlas-intervals.csv and brute-force.csv; "
      "`stickslip plot results/<output>` draws its frequency response. Exit 0 when it ran to its ends, whatever "
      "they were; 2 for bad input (nothing written). The files do not depend on --threads. Time is the paper's "
      "scaled time (with --model the model's own).");
  AddStartOptions(*cmd, &args->origin, StartOptions::kMotion);
  cmd->add_option("--results", args->origin.results, "where the atlas is written (and --point read)")->capture_default_str();
  cmd->add_option("--output", args->output, "the atlas's directory name under --results (required)");
  cmd->add_option("--parameter", args->parameter, "the parameter over the range: chi, eta, omega, u_s or u_r")
      ->capture_default_str();
  cmd->add_option("--range", args->range, "LO,HI: the parameter's range (LO < HI; every grid value is checked against "
                                          "the parameter's valid range; required)");
  AddCountOption(*cmd, "--steps", &args->steps, 0, BruteForceMapOptions::kMaxSteps,
                 "intervals of the brute-force grid over the range (0 to 1e4)");
  AddBruteForceFlags(*cmd, &args->brute, "grid value");
  AddCountOption(*cmd, "--max-multiple", &args->max_multiple, 1, AtlasOptions::kMaxMultiple,
                 fmt::format("the period limit, in forcing periods: longer attractors are listed, not solved (1 to {})",
                             AtlasOptions::kMaxMultiple));
  AddNumberOption(*cmd, "--max-amplitude", &args->max_amplitude, "a finite max-amplitude > 0",
                  "a trace's direction ends at a resonance where max |x1|, |x2| over the orbit passes this (> 0)");
  AddCountOption(*cmd, "--max-points", &args->max_points, 1, kMaxRunPoints,
                 "points per branch of every trace (1 to 1e6): near a natural frequency a branch may creep, and this "
                 "ends it (max-points) before its amplitude reaches --max-amplitude");
  AddNumberOption(*cmd, "--resonance-approach", &args->resonance_approach, "0 <= resonance-approach < 1",
                  "a trace's branch of orbits that never stick ends as a resonance at its first point within this "
                  "(relative) of a natural frequency of the undamped slip that it approaches (0: never)");
  cmd->add_option("--model", args->model,
                  "the atlas of the oscillator in this run file's [model] (see describe) instead of the paper's, in "
                  "its own units (SI unless its units say otherwise): --parameter one of the model's (omega, F_k, F_s, v_b), --set its parameters, "
                  "start state (x1_0, v1_0, ...) and phi; at every grid value the brute force runs from rest, from the "
                  "start's state and --starts - 1 states scattered in the box |x - x0| <= --scatter around it, and "
                  "from the neighbouring value's end both ways, read at forcing phase phi; --tolerance is relative to "
                  "the section states' size, --max-amplitude in the model's units, --max-multiple at most 20 and "
                  "--steps at least 1. Without forcing (a belt) --parameter must be given (F_k, F_s or v_b), the "
                  "section is the stick entry, --transients counts periods of its slowest free oscillation 2 pi/"
                  "omega_1 and the period limit is one stick-slip cycle. The mirror image of an asymmetric orbit is "
                  "traced where the model has the symmetry (v_b = 0)");
  return {cmd, [args, cmd] {
            if (cmd->count("--range") == 0) throw InvalidInput("range", "(not given)", "--range LO,HI is required");
            if (cmd->count("--output") == 0) throw InvalidInput("output", "(not given)", "--output NAME is required");
            if (cmd->count("--model") != 0 && args->model.empty()) throw InvalidInput("model", "''", "a run file's path");
            return args->model.empty() ? RunAtlas(*args) : RunModelAtlas(*args, *cmd);
          }};
}

}  // namespace stickslip::cli
