#include "stickslip/io/atlas_files.hpp"

#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <system_error>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "result_directory.hpp"
#include "stickslip/branches/orbit_monitor.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/io/atomic_file.hpp"
#include "stickslip/io/map_file.hpp"
#include "stickslip/io/result_files.hpp"
#include "stickslip/orbits/orbit_measures.hpp"
#include "stickslip/version.hpp"
#include "trace_directory.hpp"

namespace stickslip {

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

constexpr const char* kAtlasJson = "atlas.json";
constexpr const char* kIntervalsCsv = "atlas-intervals.csv";
constexpr const char* kBruteForceCsv = "brute-force.csv";
constexpr const char* kTracePrefix = "trace-";

std::string TraceName(std::size_t t) { return fmt::format("{}{}", kTracePrefix, t + 1); }

// "trace-<t>/branch-<k>" of the atlas's branch `branch` (an index into its Branches()).
template <typename AnyAtlas>
std::string BranchPlace(const AnyAtlas& atlas, int branch) {
  for (std::size_t t = 0; t < atlas.traces.size(); ++t) {
    const auto& trace = atlas.traces[t];
    if (branch >= trace.first_branch && branch < trace.first_branch + trace.count) {
      return fmt::format("{}/branch-{}", TraceName(t), branch - trace.first_branch + 1);
    }
  }
  return "";
}

// The trace the attractor's own exact orbit started ("trace-<t>"), or "".
template <typename AnyAtlas, typename AnyAttractor>
std::string StartedTrace(const AnyAtlas& atlas, const AnyAttractor& a) {
  for (std::size_t t = 0; t < atlas.traces.size(); ++t) {
    const auto& trace = atlas.traces[t];
    bool mirror = false;
    if constexpr (requires { trace.mirror; }) mirror = trace.mirror;
    if (&atlas.attractors[trace.attractor] == &a && !mirror && trace.from_branch < 0) return TraceName(t);
  }
  return "";
}

// Where the attractor ended: its fate, the branch and point, and the reason.
template <typename AnyAtlas, typename AnyAttractor>
void AddFate(Json& json, const AnyAtlas& atlas, const AnyAttractor& a) {
  const bool on = a.fate == AttractorFate::kOnBranch;
  json["fate"] = ToString(a.fate);
  json["branch"] = on ? BranchPlace(atlas, a.branch) : "";
  json["point"] = on ? a.point + 1 : 0;
  json["started_trace"] = StartedTrace(atlas, a);
  json["reason"] = on ? fmt::format("on {} between its points {} and {}", BranchPlace(atlas, a.branch), a.point + 1, a.point + 2)
                      : a.reason;
}

Json AttractorJson(const Atlas& atlas, const AtlasAttractor& a) {
  const bool solved = a.found && a.found->solution;
  const OrbitMeasures m = solved ? Measure(a.found->solution->orbit) : OrbitMeasures{NAN, NAN, NAN, NAN, 0, 0};
  Json json{{"status", ToString(a.attractor.status)},
            {"period", a.attractor.period},
            {"signature", a.attractor.signature},
            {"starts", a.attractor.starts},
            {"find", a.found ? ToString(a.found->status) : ""},
            {"exact_signature", solved ? a.found->solution->orbit.signature.ToString() : ""},
            {"amplitude_x1", m.amplitude_x1},
            {"amplitude_x2", m.amplitude_x2}};
  AddFate(json, atlas, a);
  return json;
}

// A [model]'s attractor: the brute force's reading (no signature: its runs count stops and sticks),
// and the exact orbit's amplitude of every coordinate, by the columns' names.
Json AttractorJson(const ModelAtlas& atlas, const ModelAtlasAttractor& a) {
  const bool solved = a.found && a.found->solution && a.found->measures;
  Json json{{"status", ToString(a.attractor.status)},
            {"period", a.attractor.period},
            {"stops_per_period", a.attractor.stops_per_period},
            {"sticks_per_period", a.attractor.sticks_per_period},
            {"starts", a.attractor.starts},
            {"find", a.found ? ToString(a.found->status) : ""},
            {"exact_signature", solved ? a.found->solution->orbit.signature.ToString() : ""}};
  const std::vector<std::string>& coordinates = atlas.model.Description().coordinates;
  for (std::size_t k = 0; k < coordinates.size(); ++k) {
    json[orbit_columns::AmplitudeOf(coordinates[k])] = solved ? Json(a.found->measures->coordinates[k].Amplitude()) : Json(nullptr);
  }
  AddFate(json, atlas, a);
  return json;
}

// Per grid value (index, value): its attractors, and the branches its stable motions (the
// attractors placed) lie on, each once.
template <typename AnyAtlas>
Json GridJson(const AnyAtlas& atlas, const std::vector<std::pair<int, double>>& values) {
  Json grid = Json::array();
  for (const auto& [i, value] : values) {
    Json attractors = Json::array();
    std::set<std::string> stable;
    for (const auto& a : atlas.attractors) {
      if (a.grid != i) continue;
      attractors.push_back(AttractorJson(atlas, a));
      if (a.fate == AttractorFate::kOnBranch) stable.insert(BranchPlace(atlas, a.branch));
    }
    grid.push_back({{"value", value}, {"attractors", attractors}, {"stable_on", stable}});
  }
  return grid;
}

// Where a trace started: an attractor's exact orbit, its mirror image, or a switch another trace
// confirmed at a branch's end and did not take.
template <typename AnyAtlas, typename AnyTrace>
Json FromJson(const AnyAtlas& atlas, const AnyTrace& trace) {
  const auto& a = atlas.attractors[trace.attractor];
  if (trace.from_branch >= 0) {
    return {{"switch_at_end_of", BranchPlace(atlas, trace.from_branch)}, {"adjacent", trace.adjacent}};
  }
  bool mirror = false;  // a [model]'s atlas traces no mirror image
  if constexpr (requires { trace.mirror; }) mirror = trace.mirror;
  return {{"value", a.value}, {"attractor", a.index + 1}, {"mirror_image", mirror}};
}

template <typename AnyAtlas>
Json TracesJson(const AnyAtlas& atlas, const std::vector<StoredTrace>& stored) {
  Json traces = Json::array();
  for (std::size_t t = 0; t < atlas.traces.size(); ++t) {
    Json directions = Json::array();
    for (const StoredTraceDirection& d : stored[t].directions) {
      directions.push_back({{"direction", d.direction}, {"end", d.end}, {"message", d.message}});
    }
    traces.push_back({{"name", TraceName(t)},
                      {"from", FromJson(atlas, atlas.traces[t])},
                      {"signature", stored[t].signature},
                      {"branches", stored[t].branches.size()},
                      {"directions", directions}});
  }
  return traces;
}

template <typename AnyAtlas>
Json CountsJson(const AnyAtlas& atlas, const std::vector<StoredTrace>& stored) {
  std::set<std::string> types;
  std::size_t branches = 0;
  for (const StoredTrace& t : stored) {
    branches += t.branches.size();
    for (const StoredTraceBranch& b : t.branches) types.insert(b.signature);
  }
  const int placed = atlas.OnBranches();
  Json fates = Json::object();
  for (const auto& a : atlas.attractors) {
    const char* fate = ToString(a.fate);
    fates[fate] = fates.value(fate, 0) + 1;
  }
  return {{"attractors", atlas.attractors.size()},
          {"fates", fates},
          {"periodic_within_limit", atlas.PeriodicWithinLimit()},
          {"on_branches", placed},
          {"unexplained", static_cast<int>(atlas.attractors.size()) - placed},
          {"traces", stored.size()},
          {"branches", branches},
          {"orbit_types", types}};
}

// What atlas.json says of the run before its counts: the range, grid and period limit.
struct AtlasHeader {
  const RunFile& run;
  std::string model;  // "" for the paper's (no key), kLinearOscillatorModel for a [model]'s
  std::string parameter;
  double from = 0.0;
  double to = 0.0;
  int grid_points = 0;
  int max_multiple = 0;
};

template <typename AnyAtlas>
std::string FormatAtlasJson(const AtlasHeader& header, const AnyAtlas& atlas, const std::vector<std::pair<int, double>>& grid,
                            const std::vector<StoredTrace>& stored) {
  Json json = Json::object();
  json["run_file"] = header.run.path;
  json["stickslip_version"] = Version();
  if (!header.model.empty()) json["model"] = header.model;
  json["output"] = header.run.output;
  json["parameter"] = header.parameter;
  json["range"] = {header.from, header.to};
  json["grid_points"] = header.grid_points;
  json["max_multiple"] = header.max_multiple;
  json["counts"] = CountsJson(atlas, stored);
  json["grid"] = GridJson(atlas, grid);
  json["traces"] = TracesJson(atlas, stored);
  return json.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

// A point's stability and admissibility as its piece of branch has them: a labelled point (a
// located change, whose margin is zero to rounding and may read inadmissible) takes those of the
// unlabelled point before it on its branch, or after it at the branch's start.
std::vector<std::pair<bool, bool>> PieceFlags(const std::vector<StoredTracePoint>& points) {
  std::vector<std::pair<bool, bool>> flags(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    std::size_t from = i;
    while (!points[from].label.empty() && from > 0 && points[from - 1].branch == points[i].branch) --from;
    while (!points[from].label.empty() && from + 1 < points.size() && points[from + 1].branch == points[i].branch) ++from;
    flags[i] = {points[from].stable, points[from].admissible};
  }
  return flags;
}

// atlas-intervals.csv: each branch cut where its stability or admissibility changes.
std::string FormatIntervalsCsv(const std::vector<StoredTrace>& traces) {
  std::string csv = "trace,branch,signature,from,to,stable,admissible,first_label,last_label,branch_end\n";
  for (std::size_t t = 0; t < traces.size(); ++t) {
    const std::vector<StoredTracePoint>& points = traces[t].points;
    const std::vector<std::pair<bool, bool>> flags = PieceFlags(points);
    for (std::size_t begin = 0; begin < points.size();) {
      std::size_t end = begin;
      while (end + 1 < points.size() && points[end + 1].branch == points[begin].branch && flags[end + 1] == flags[begin]) ++end;
      // A piece begins where the one before it ends: at a located change.
      const bool after_change = begin > 0 && points[begin - 1].branch == points[begin].branch && !points[begin - 1].label.empty();
      const StoredTracePoint& first = after_change ? points[begin - 1] : points[begin];
      const bool branch_ends = end + 1 == points.size() || points[end + 1].branch != first.branch;
      // A piece ends where the next begins: at the next one's first point when that is a located change.
      const StoredTracePoint& last = !branch_ends && !points[end + 1].label.empty() ? points[end + 1] : points[end];
      csv += fmt::format("{},branch-{},{},{},{},{:d},{:d},{},{},{}\n", TraceName(t), first.branch, first.signature,
                         first.lambda, last.lambda, flags[begin].first, flags[begin].second, first.label, last.label,
                         branch_ends ? traces[t].branches[first.branch - 1].end : "");
      begin = end + 1;
    }
  }
  return csv;
}

bool IsAtlasFile(std::string_view name) { return name == kAtlasJson || name == kIntervalsCsv || name == kBruteForceCsv; }

// The atlas's files and trace directories, `own_trace` telling which trace-<t> names are its and
// `in_trace` what is the trace's inside one of them. A run's three files directly in a trace-<t>/
// are the user's: an atlas's trace never replaced a run.
detail::OwnedEntry AtlasEntries(const detail::OwnedName& own_trace,
                                const std::function<detail::OwnedEntry(const std::string& trace)>& in_trace) {
  return [own_trace, in_trace](const fs::path& relative) {
    const std::string top = relative.begin()->string();
    const auto depth = std::distance(relative.begin(), relative.end());
    if (!own_trace(top)) return depth == 1 && IsAtlasFile(top);
    if (depth == 1) return true;
    const fs::path inside = relative.lexically_relative(top);
    if (depth == 2 && detail::IsRunFileName(inside.string())) return false;
    return in_trace(top)(inside);
  };
}

// What an atlas writes: its files, trace-<t>/ and in them what a trace writes.
detail::OwnedEntry AtlasEntries() {
  const detail::OwnedEntry trace = detail::TraceEntries();
  return AtlasEntries([](std::string_view name) { return detail::IsNumberedName(name, kTracePrefix, false); },
                      [trace](const std::string&) { return trace; });
}

// What the atlas in `directory` wrote: its files, the traces its atlas.json lists and in them what
// their trace.json lists, and a trace-<t>/ left holding only the user's files by an earlier re-run
// that wrote fewer traces (no trace.json: the directory is the atlas's, everything in it the
// user's). A trace-<t>/ of the user's with a trace.json in it is the user's whole.
detail::OwnedEntry AtlasEntriesBefore(const fs::path& directory) {
  const std::set<std::string> listed = detail::ListedNames(directory / kAtlasJson, {"name"});
  const auto own = [directory, listed](std::string_view name) {
    std::error_code ignored;
    return listed.contains(std::string(name)) ||
           (detail::IsNumberedName(name, kTracePrefix, false) &&
            fs::is_directory(fs::symlink_status(directory / name, ignored)) &&
            !fs::exists(fs::symlink_status(directory / name / "trace.json", ignored)));
  };
  return AtlasEntries(own, [directory](const std::string& name) { return detail::TraceEntriesBefore(directory / name); });
}

}  // namespace

StoredAtlas RecordAtlas(const RunFile& run, const Atlas& atlas, const AtlasOptions& options) {
  StoredAtlas stored{.output = run.output};
  for (std::size_t t = 0; t < atlas.traces.size(); ++t) {
    RunFile trace_run = run;
    trace_run.output = TraceName(t);
    stored.traces.push_back(RecordTrace(trace_run, atlas.traces[t].result));
  }
  const MapAxis& axis = options.brute_force.first;
  std::vector<std::pair<int, double>> grid;
  for (const MapCell& cell : atlas.brute_force.cells) grid.emplace_back(cell.i, cell.first);
  const AtlasHeader header{run, "", atlas.parameter, axis.from, axis.to, axis.Count(), options.max_multiple};
  stored.files = {FormatAtlasJson(header, atlas, grid, stored.traces), FormatIntervalsCsv(stored.traces),
                  BruteForceMapCsv(atlas.brute_force)};
  return stored;
}

StoredAtlas RecordModelAtlas(const RunFile& run, const ModelAtlas& atlas, const ModelAtlasOptions& options,
                             const std::vector<double>& natural_frequencies) {
  StoredAtlas stored{.output = run.output};
  for (std::size_t t = 0; t < atlas.traces.size(); ++t) {
    const StoredSummary identity{.run_file = run.path, .output = TraceName(t), .parameter = atlas.parameter};
    stored.traces.push_back(RecordTrace(atlas.model, identity, atlas.traces[t].result));
    stored.traces.back().natural_frequencies = natural_frequencies;
  }
  std::vector<std::pair<int, double>> grid;
  for (std::size_t i = 0; i < atlas.grid.size(); ++i) grid.emplace_back(static_cast<int>(i), atlas.grid[i]);
  const AtlasHeader header{run, kLinearOscillatorModel, atlas.parameter, options.from, options.to,
                           static_cast<int>(atlas.grid.size()), options.max_multiple};
  stored.files = {FormatAtlasJson(header, atlas, grid, stored.traces), FormatIntervalsCsv(stored.traces),
                  BruteForceMapCsv(atlas.brute_force)};
  return stored;
}

void CheckAtlasOutputDirectory(const fs::path& results_root, const std::string& output) {
  const fs::path target = results_root / output;
  const std::string shown = "'" + output + "'";
  if (!IsRunName(output)) throw InvalidInput("output", shown, std::string(kRunNameRule));
  std::error_code error;
  const fs::file_status status = fs::symlink_status(target, error);
  if (!fs::exists(status)) return CheckOutputDirectory(results_root, output);
  // Only an atlas is replaced: recognised by what any version's atlas.json has, not read whole. A
  // link is refused (its target's entries would move out from under it), as is any other directory.
  const auto refuse = [&](const std::string& why) {
    return InvalidInput::WithMessage("output", fmt::format("output = {} is invalid: '{}' {}: valid a new name or the "
                                                           "directory of a stickslip atlas",
                                                           shown, target.string(), why));
  };
  if (fs::is_symlink(status)) throw refuse("is a symbolic link");
  if (!fs::is_directory(status)) throw refuse("is not a directory");
  try {
    const fs::path file = target / kAtlasJson;
    const Json json = detail::ParseJsonObject(detail::ReadTextFile(file), file);
    for (const char* key : {"stickslip_version", "grid", "traces"}) {
      if (!json.contains(key)) throw detail::KeyError(file, key, "is missing");
    }
  } catch (const InvalidInput& e) {
    throw refuse(fmt::format("holds no stickslip atlas ({})", e.what()));
  }
  // A link at a name the atlas writes is the user's (no writer makes links): refused before any
  // work, rather than kept at the end by failing the replacement.
  for (const std::string& name : detail::ListedNames(target / kAtlasJson, {"name"})) {
    if (fs::is_symlink(fs::symlink_status(target / name, error))) {
      throw refuse(fmt::format("holds '{}', a symbolic link at a name the atlas writes", name));
    }
  }
  if (const std::error_code failed = CanCreateFileIn(target)) throw refuse(fmt::format("cannot be written ({})", failed.message()));
}

std::vector<std::string> WriteAtlasFiles(const fs::path& results_root, const StoredAtlas& atlas) {
  CheckAtlasOutputDirectory(results_root, atlas.output);
  return detail::ReplaceDirectory(
      results_root, atlas.output,
      [&](const fs::path& directory) {
        for (std::size_t t = 0; t < atlas.traces.size(); ++t) {
          fs::create_directory(directory / TraceName(t));
          detail::WriteTraceInto(directory / TraceName(t), atlas.traces[t]);
        }
        WriteFileAtomically(directory / kAtlasJson, atlas.files.atlas_json);
        WriteFileAtomically(directory / kIntervalsCsv, atlas.files.intervals_csv);
        WriteFileAtomically(directory / kBruteForceCsv, atlas.files.brute_force_csv);
      },
      AtlasEntries(), AtlasEntriesBefore(results_root / atlas.output));
}

}  // namespace stickslip
