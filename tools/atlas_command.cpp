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
#include "stickslip/io/command_options.hpp"
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

AtlasOptions OptionsOf(const AtlasArgs& args, const ModelStart& origin) {
  AtlasCommand c = WithBruteForceFlags(AtlasCommand{}, args.brute);
  c.parameter = args.parameter;
  std::tie(c.from, c.to) = ParseRange(args.range);
  c.steps = args.steps;
  c.max_multiple = args.max_multiple;
  c.max_amplitude = args.max_amplitude;
  c.max_points = args.max_points;
  c.resonance_approach = args.resonance_approach;
  return AtlasOptionsOf(c, origin);
}

void Report(const std::string& output, const Atlas& atlas, const StoredAtlas& stored, double seconds,
            const std::vector<std::string>& kept, const std::filesystem::path& results) {
  std::size_t branches = 0;
  for (const StoredTrace& t : stored.traces) branches += t.branches.size();
  const int unexplained = static_cast<int>(atlas.attractors.size()) - atlas.OnBranches();
  fmt::print("{}: {} attractor(s) at {} value(s) of {}: {} periodic within the limit, {} on a branch, {} listed with "
             "the reason; {} trace(s), {} branch(es) in {:.1f} s\n",
             output, atlas.attractors.size(), atlas.brute_force.cells.size(), atlas.parameter, atlas.PeriodicWithinLimit(),
             atlas.OnBranches(), unexplained, stored.traces.size(), branches, seconds);
  for (const AtlasAttractor& a : atlas.attractors) {
    if (a.fate == AttractorFate::kOnBranch) continue;
    fmt::print("  {} = {:.6g}, attractor {}: {}: {}\n", atlas.parameter, a.value, a.index + 1, ToString(a.fate), a.reason);
  }
  if (!kept.empty()) {
    fmt::print("{}: kept {} other file(s) of {}: {}\n", output, kept.size(), (results / output).string(), fmt::join(kept, ", "));
  }
}

int RunAtlas(const AtlasArgs& args) {
  const ModelStart origin = BuildModelStart(ToStartInput(args.origin));
  if (args.output.empty()) throw InvalidInput("output", "(not given)", "--output NAME is required");
  RunFile run;
  run.path = kOneOffRunPath;
  run.output = args.output;
  run.parameter = args.parameter;
  AtlasOptions options = OptionsOf(args, origin);
  const std::filesystem::path results = args.origin.results;
  CheckAtlasOutputDirectory(results, run.output);
  ProgressLineOptions line_options;
  line_options.value_name = args.parameter;
  ProgressLine line(run.output, line_options);
  options.progress = line.Callback();
  const auto started = std::chrono::steady_clock::now();
  const Atlas atlas = ComputeAtlas(origin.parameters, options);
  line.Clear();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  const StoredAtlas stored = RecordAtlas(run, atlas, options);
  const std::vector<std::string> kept = WriteAtlasFiles(results, stored);
  Report(run.output, atlas, stored, seconds, kept, results);
  return kExitOk;
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
      "scaled time.");
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
  return {cmd, [args, cmd] {
            if (cmd->count("--range") == 0) throw InvalidInput("range", "(not given)", "--range LO,HI is required");
            return RunAtlas(*args);
          }};
}

}  // namespace stickslip::cli
