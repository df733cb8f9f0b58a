// stickslip map: the orbit-type map of a rectangle of two parameters from a stored trace
// (branches/orbit_type_map.hpp): the curves through the trace's special points, the regions they
// cut, each region's orbits; with --brute-force, the comparison with a map of `stickslip
// map-sweep` (analysis/map_comparison.hpp). Written to --output (io/orbit_type_map_files.hpp).
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>

#include <fmt/format.h>

#include "cli_common.hpp"
#include "commands.hpp"
#include "progress_line.hpp"
#include "stickslip/analysis/map_comparison.hpp"
#include "stickslip/io/map_file.hpp"
#include "stickslip/io/orbit_type_map_files.hpp"
#include "stickslip/io/model_restart.hpp"
#include "stickslip/io/run_file.hpp"

namespace stickslip::cli {

namespace {

const OrbitTypeMapOptions kDefaults;

struct MapArgs {
  std::string trace;
  std::string second;
  double second_from = 0.0, second_to = 0.0;  // required
  double first_from = 0.0, first_to = 0.0;    // default: the trace's range
  std::string brute_force;
  std::string output;
  int raster = kDefaults.raster;
  double min_region = kDefaults.min_region;
};

std::string ReadWholeFile(const std::string& path, const std::string& field, const std::string& what) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) throw InvalidInput(field, "'" + path + "'", what);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InvalidInput(field, "'" + path + "'", what);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Each corner of the rectangle, with the trace's other data, must be valid model data: `error_at(a,
// b)` is the model's refusal of the corner (first = a, second = b), if any. A violation is blamed on
// the bound given: u_s's range given u_r where u_r >= u_s fails for u_s given; a held parameter's
// range (F_s >= F_k, F_s held, F_k the second) on the bound that leaves it.
template <typename CornerError>
void CheckCorners(const MapRectangle& r, const CornerError& error_at) {
  for (double a : {r.first_min, r.first_max}) {
    for (double b : {r.second_min, r.second_max}) {
      const std::optional<InvalidInput> error = error_at(a, b);
      if (!error) continue;
      const bool is_first = error->field() == r.first;
      const bool axis = is_first || error->field() == r.second;
      throw InvalidInput(is_first ? (a == r.first_min ? "first-from" : "first-to") : (b == r.second_min ? "second-from" : "second-to"),
                         is_first ? a : b,
                         fmt::format("{} {}: {}", axis ? "a valid" : "one with which the trace's", error->field(),
                                     axis ? error->valid_range() : error->valid_range() + " holds"));
    }
  }
}

void CheckCorners(const MapRectangle& r, const Parameters& base) {
  const ParameterId first = *ParameterFromString(r.first), second = *ParameterFromString(r.second);
  CheckCorners(r, [&](double a, double b) {
    Parameters p = base;
    p[first] = a;
    p[second] = b;
    std::optional<InvalidInput> error = Validate(p, second);
    if (error && error->field() != r.second) error = Validate(p, first);
    return error;
  });
}

void CheckCorners(const MapRectangle& r, const DynamicLinearOscillator& model, const DynamicLinearOscillator::Parameters& base) {
  const ModelDescription& d = model.Description();
  const int first = *d.ParameterIndex(r.first), second = *d.ParameterIndex(r.second);
  CheckCorners(r, [&](double a, double b) {
    DynamicLinearOscillator::Parameters p = base;
    DynamicLinearOscillator::ParameterAt(p, first) = a;
    DynamicLinearOscillator::ParameterAt(p, second) = b;
    return model.Validate(p);
  });
}

// The rectangle: the trace's parameter over its range (or --first-from/--first-to), the second's as given.
MapRectangle RectangleOf(const MapArgs& args, const CLI::App& cmd, const StoredTrace& trace) {
  MapRectangle r{.first = trace.parameter, .second = args.second, .second_min = args.second_from, .second_max = args.second_to};
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const StoredTracePoint& p : trace.points) {
    lo = std::min(lo, p.lambda);
    hi = std::max(hi, p.lambda);
  }
  r.first_min = cmd.count("--first-from") ? args.first_from : lo;
  r.first_max = cmd.count("--first-to") ? args.first_to : hi;
  return r;
}

void CheckOrder(const MapRectangle& r) {
  if (!(r.first_min < r.first_max)) throw InvalidInput("first-from", r.first_min, fmt::format("< first-to ({})", r.first_max));
  if (!(r.second_min < r.second_max)) throw InvalidInput("second-from", r.second_min, fmt::format("< second-to ({})", r.second_max));
}

// The run file the trace was made from (`path`), for its unknowns and step sizes; none where it
// cannot be read (noted once the map is computed: bad input found on the way stays the one line on
// stderr).
std::optional<RunFile> TraceRunFile(const std::filesystem::path& path) {
  try {
    return ReadRunFile(path);
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

// The map's report, for either model: its counts, the regions' labels, the comparison's, and the
// curves that failed (exit 3: the map is written all the same).
template <OscillatorModel Model>
int Report(const MapArgs& args, const BasicOrbitTypeMap<Model>& map, const OrbitTypeMapFiles& files, double seconds,
           const MapComparison* comparison, const std::string& note) {
  const MapRectangle& r = map.rectangle;
  const std::vector<std::string> kept = WriteOrbitTypeMapFiles(args.output, files);
  if (!note.empty()) fmt::print(stderr, "note: {}\n", note);
  fmt::print("map {} x {} from {}: {} curve(s), {} start(s) skipped, {} region(s) in {:.2f} s; written to {}\n", r.first, r.second,
             args.trace, map.curves.size(), map.skipped.size(), map.regions.size(), seconds, args.output);
  if (!kept.empty()) fmt::print("{}: kept {} other file(s): {}\n", args.output, kept.size(), fmt::join(kept, ", "));
  for (const BasicMapRegion<Model>& region : map.regions) {
    fmt::print("  region {} ({} cells) at ({}, {}) = ({:.6g}, {:.6g}): {}\n", region.id, region.cells, r.first, r.second, region.first,
               region.second, region.Label());
  }
  if (comparison) {
    fmt::print("brute force {}: agreement {}/{} = {:.4f} of the cells clear of the curves ({} with a stable orbit); {} "
               "disagreement(s), {} explained\n",
               args.brute_force, comparison->agreeing, comparison->compared, comparison->Agreement(), comparison->agreeing_stable,
               comparison->disagreements.size(), comparison->Explained());
  }
  // A curve whose start did not converge, or whose step fell below ds_min, is a failure of the
  // computation (the map is written all the same); its end elsewhere is the curve's.
  int failed = 0;
  for (const BasicMapCurve<Model>& c : map.curves) {
    const BranchEnd end = c.branch.branch.end;
    if (end == BranchEnd::kMaxPoints) {  // inside the rectangle: the regions on its sides may be joined
      fmt::print(stderr, "note: curve {} ({} from {}) stopped after {} points (max_curve_points) inside the rectangle\n",
                 c.id, c.kind, c.from, c.branch.orbits.size());
    }
    if (end != BranchEnd::kStartFailed && end != BranchEnd::kStepTooSmall) continue;
    ++failed;
    fmt::print(stderr, "curve {} ({} from {}): {}: {}\n", c.id, c.kind, c.from, ToString(end), c.branch.branch.end_message);
  }
  return failed > 0 ? kExitNoConvergence : kExitOk;
}

// The map with the command's raster and progress line, and the seconds it took.
template <OscillatorModel Model>
std::pair<BasicOrbitTypeMap<Model>, double> BuildShowingProgress(const BasicMapTrace<Model>& input, const MapRectangle& r,
                                                                 const MapArgs& args) {
  OrbitTypeMapOptions options;
  options.raster = args.raster;
  options.min_region = args.min_region;
  ProgressLine line("map");
  options.progress = line.Callback();
  const auto started = std::chrono::steady_clock::now();
  BasicOrbitTypeMap<Model> map = BuildOrbitTypeMap(input, r, options);
  line.Clear();
  return {std::move(map), std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count()};
}

// An antisymmetric orbit is a motion only on a fixed surface (its mirror half slips the other way
// on a moving one): a map in the belt's speed from a trace of them is refused, as a curve in it is.
void CheckSurfaceStaysFixed(const BasicMapTrace<DynamicLinearOscillator>& trace, const std::string& second) {
  const ModelDescription& d = trace.model.Description();
  if (d.ParameterIndex(second) != DynamicLinearOscillator::kRestVelocityParameter) return;
  for (const BasicMapTraceBranch<DynamicLinearOscillator>& b : trace.branches) {
    if (!b.orbits.front().signature.antisymmetric()) continue;
    throw InvalidInput("second", "'" + second + "'",
                       fmt::format("a parameter other than {0}: the trace's {1} holds the antisymmetric '{2}', a motion "
                                   "only where {0} = 0 (trace it written over its whole period, or in {0})",
                                   second, b.name, b.orbits.front().signature.ToString()));
  }
}

// A [model]'s trace: its parameters by the model's names, in its units.
int RunModelMap(const MapArgs& args, const CLI::App& cmd, const StoredTrace& trace) {
  if (cmd.count("--brute-force") > 0) {
    throw InvalidInput("brute-force", "'" + args.brute_force + "'",
                       "none for a [model]'s trace (its brute-force maps record amplitudes, not orbit types): leave it out");
  }
  // The [model]'s file, found as restarts find it: a run file with [continuation] too, or (a trace
  // of find --model) the model's alone.
  std::optional<RunFile> run;
  BasicMapTrace<DynamicLinearOscillator> input = [&] {
    try {
      run = TraceRunFile(ModelFileOf(trace.runs.front(), args.trace));
      return ModelMapTraceOf(trace, args.trace, run ? &*run : nullptr);
    } catch (const InvalidInput& e) {  // its model's file: gone, changed, or none (a trace of --set)
      throw InvalidInput::WithMessage("trace", fmt::format("trace = '{}' cannot be mapped: {}", args.trace, e.what()));
    }
  }();
  const MapRectangle r = RectangleOf(args, cmd, trace);
  CheckOrder(r);
  try {
    r.Validate(input.model.Description(), input.model.Autonomous());
  } catch (const InvalidInput& e) {
    if (e.field() == "first") throw e.Renamed("trace");
    throw;
  }
  CheckSurfaceStaysFixed(input, args.second);
  CheckCorners(r, input.model, input.branches.front().orbits.front().parameters);
  const auto [map, seconds] = BuildShowingProgress(input, r, args);
  const std::string note =
      run ? "" : fmt::format("'{}' holds no continuation steps (a trace of find --model?): the map continues with the "
                             "default steps, whatever the trace's were", trace.run_file);
  return Report(args, map, FormatOrbitTypeMapFiles(input.model, trace.run_file, map, args.trace), seconds, nullptr, note);
}

int RunMap(const MapArgs& args, const CLI::App& cmd) {
  for (const char* option : {"trace", "second", "second-from", "second-to", "output"}) {
    if (cmd.count(fmt::format("--{}", option)) == 0) {
      throw InvalidInput(option, "(not given)", fmt::format("--{} is required", option));
    }
  }
  if (!IsTraceDirectory(args.trace)) throw InvalidInput("trace", "'" + args.trace + "'", "a trace's directory (stickslip trace: trace.json)");
  CheckOrbitTypeMapDirectory(args.output);
  const StoredTrace trace = ReadTraceFiles(args.trace);
  if (trace.runs.empty() || trace.runs.front().branch.empty()) {
    throw InvalidInput("trace", "'" + args.trace + "'", fmt::format("a trace with points (it has {})", trace.points.size()));
  }
  if (!trace.model.empty()) return RunModelMap(args, cmd, trace);
  if (!ParameterFromString(trace.parameter)) {
    throw InvalidInput("trace", "'" + args.trace + "'",
                       fmt::format("a trace in a parameter: chi, eta, omega, u_s, u_r (it has '{}')", trace.parameter));
  }
  const MapRectangle r = RectangleOf(args, cmd, trace);
  const std::optional<ParameterId> second = ParameterFromString(args.second);
  if (!second || args.second == trace.parameter) {
    throw InvalidInput("second", "'" + args.second + "'", fmt::format("a parameter other than the trace's {}: chi, eta, omega, u_s, u_r", trace.parameter));
  }
  CheckOrder(r);
  CheckCorners(r, OrbitOf(trace.runs.front(), trace.runs.front().branch.front()).parameters);
  std::optional<BruteForceMap> brute;
  if (cmd.count("--brute-force") > 0) {  // "" too: no file
    brute = ReadBruteForceMapCsv(ReadWholeFile(args.brute_force, "brute-force", "a map file of stickslip map-sweep"), args.brute_force);
    try {
      CheckComparable(*brute, r);
    } catch (const InvalidInput& e) {
      throw InvalidInput("brute-force", fmt::format("'{}' ({})", args.brute_force, e.value()), e.valid_range());
    }
  }
  const std::optional<RunFile> run = TraceRunFile(trace.run_file);
  const MapTrace input = MapTraceOf(trace, run ? &*run : nullptr);
  const auto [map, seconds] = BuildShowingProgress(input, r, args);
  std::optional<MapComparison> comparison;
  if (brute) comparison = CompareWithBruteForce(map, &input, TraceTypes(trace), *brute);
  const OrbitTypeMapFiles files = FormatOrbitTypeMapFiles(map, args.trace, comparison ? &*comparison : nullptr, args.brute_force);
  const std::string note =
      run ? "" : fmt::format("the trace's run file '{}' cannot be read: default unknowns and step sizes", trace.run_file);
  return Report(args, map, files, seconds, comparison ? &*comparison : nullptr, note);
}

}  // namespace

Command AddMapCommand(CLI::App& app) {
  auto args = std::make_shared<MapArgs>();
  CLI::App* cmd = app.add_subcommand(
      "map",
      "Orbit-type map of a rectangle of two parameters from a stored trace (stickslip trace): the curves through "
      "every special point of the trace that a two-parameter curve can be continued from (type changes, LP, PD, "
      "SB, TR), across the rectangle both ways, ending at its edges and at codimension-two points; the rectangle "
      "cut by them into regions, and in each region every orbit of the trace at one interior point (admissible "
      "or not, stable or not). With --brute-force, the comparison with a map of stickslip map-sweep over the same "
      "parameters. Writes --output/: curves.csv, curve-<k>/ (each curve as a run: restart from its labels with "
      "--results OUTPUT), regions.json, comparison.md. Parameters are the trace's model's: the paper's scaled ones, or a "
      "[model]'s by its names in its units (its curves' runs name its run file; no --brute-force yet). Exit 0 when written; "
      "2 for bad input (nothing written); 3 when a curve's start did not converge or its step fell below ds_min "
      "(the map is written, the curve named on stderr).");
  cmd->add_option("--trace", args->trace, "the trace's directory (results/<trace>/, with trace.json)");
  cmd->add_option("--second", args->second,
                  "the second parameter, not the trace's: chi, eta, omega, u_s or u_r for the paper's model; a [model]'s "
                  "omega (with forcing), F_k, F_s or v_b");
  AddNumberOption(*cmd, "--second-from", &args->second_from, "the parameter's valid range, < second-to",
                  "the second parameter's lower bound (the paper's scaled, a [model]'s in its units; its valid "
                  "range: chi in (0, 1), eta > 0, F_s >= F_k, ...)");
  AddNumberOption(*cmd, "--second-to", &args->second_to, "the parameter's valid range", "its upper bound");
  AddNumberOption(*cmd, "--first-from", &args->first_from, "the parameter's valid range, < first-to",
                  "the trace's parameter's lower bound (default: the trace's smallest value)");
  AddNumberOption(*cmd, "--first-to", &args->first_to, "the parameter's valid range",
                  "its upper bound (default: the trace's largest value)");
  cmd->add_option("--brute-force", args->brute_force, "a map file of stickslip map-sweep over the same two parameters to compare with");
  cmd->add_option("--output", args->output, "the map's directory (new, or one holding a map, which is replaced)");
  AddCountOption(*cmd, "--raster", &args->raster, 16, 2000, "cells per side of the raster the regions are cut on (16 to 2000)");
  AddNumberOption(*cmd, "--min-region", &args->min_region, "0 <= min-region <= 0.5",
                  "components smaller than this fraction of the rectangle are slivers, dropped (0 to 0.5)");
  return {cmd, [args, cmd] {
            try {
              return RunMap(*args, *cmd);
            } catch (const InvalidInput& e) {
              // The rectangle's bounds as the options name them (MapRectangle: first_min, ...).
              static const std::map<std::string, std::string> kBounds = {
                  {"first_min", "first-from"}, {"first_max", "first-to"}, {"second_min", "second-from"}, {"second_max", "second-to"}};
              std::string option = kBounds.count(e.field()) ? kBounds.at(e.field()) : e.field();
              std::replace(option.begin(), option.end(), '_', '-');
              throw e.Renamed(option);
            }
          }};
}

}  // namespace stickslip::cli
