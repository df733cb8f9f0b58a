#include "stickslip/io/orbit_type_map_files.hpp"

#include <algorithm>
#include <iterator>
#include <set>
#include <system_error>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "result_directory.hpp"
#include "stickslip/io/atomic_file.hpp"
#include "stickslip/io/result_files.hpp"
#include "stickslip/io/run.hpp"
#include "stickslip/io/model_file_start.hpp"
#include "stickslip/io/model_restart.hpp"
#include "stickslip/io/start_input.hpp"
#include "stickslip/io/stored_run.hpp"

namespace stickslip {

namespace fs = std::filesystem;
namespace ov = orbit_variables;
using Json = nlohmann::ordered_json;

namespace {

constexpr const char* kCurvesCsv = "curves.csv";
constexpr const char* kRegionsJson = "regions.json";
constexpr const char* kComparisonMd = "comparison.md";
// The keys a map's regions.json has (FormatRegionsJson), by which a directory holds a map.
constexpr const char* kRegionsKeys[] = {"trace", "first", "second", "rectangle", "raster", "regions", "curves", "cells"};

template <OscillatorModel Model>
std::string CurveDirectory(const BasicMapCurve<Model>& c) {
  return fmt::format("curve-{}", c.id);
}

// The run file a paper's curve's directory records: its name and parameter.
RunFile CurveRun(const MapCurve& c, const OrbitTypeMap& map) {
  RunFile run;
  run.path = fmt::format("stickslip map ({} from {}, {} = [{}, {}])", c.kind, c.from, map.rectangle.second,
                         map.rectangle.second_min, map.rectangle.second_max);
  run.output = CurveDirectory(c);
  run.parameter = map.rectangle.first;
  return run;
}

// An orbit's variables as its model's files name and order them (SolutionColumns), its durations
// d1..dn apart: the model's parameters, phi, the start state.
struct OrbitColumns {
  NamedValues variables;
  std::vector<double> durations;
};
template <OscillatorModel Model>
OrbitColumns ColumnsOf(const Model& model, const BasicOrbit<Model>& orbit) {
  NamedValues all = SolutionColumns(model, orbit);
  const std::size_t n = orbit.durations.size();
  return {NamedValues(all.begin(), all.end() - static_cast<std::ptrdiff_t>(n)), orbit.durations};
}
template <OscillatorModel Model>
std::vector<std::string> ColumnNames(const Model& model) {
  const BasicOrbit<Model> orbit{Signature({Mode::kSlipNegative, Mode::kSlipPositive}), {}, Model::State::Zero(model.StateSize()), 0.0,
                                {0.0, 0.0}};
  std::vector<std::string> names;
  for (const auto& [name, value] : ColumnsOf(model, orbit).variables) names.push_back(name);
  return names;
}

template <OscillatorModel Model>
std::string FormatCurvesCsv(const Model& model, const BasicOrbitTypeMap<Model>& map) {
  const MapRectangle& r = map.rectangle;
  const std::vector<std::string> names = ColumnNames(model);
  std::string out = fmt::format("curve,kind,from,direction,signature,pt,label,{},{},stable,admissible,{},durations\n",
                                r.first, r.second, fmt::join(names, ","));
  for (const BasicMapCurve<Model>& c : map.curves) {
    const std::vector<std::string> labels = PointLabels(c.branch.branch);
    for (std::size_t k = 0; k < c.branch.orbits.size(); ++k) {
      const OrbitOfModel<Model>& o = c.branch.orbits[k];
      std::vector<double> values;
      for (const auto& [name, value] : ColumnsOf(model, AsBasicOrbit(o)).variables) values.push_back(value);
      out += fmt::format("{},{},{},{},{},{},{},{},{},{:d},{:d},{},{}\n", c.id, c.kind, c.from, c.direction,
                         o.signature.ToString(), k + 1, labels[k], c.first[k], c.second[k], static_cast<int>(c.stable[k]),
                         static_cast<int>(c.admissible[k]), fmt::join(values, ","), fmt::join(o.durations, ";"));
    }
  }
  return out;
}

// phi first, then the start state by the model's names, as the keys have always come.
template <OscillatorModel Model>
Json OrbitJson(const Model& model, const BasicMapOrbit<Model>& o) {
  Json out{{"signature", o.signature}, {"admissible", o.admissible}, {"stable", o.stable}, {"from", o.from},
           {"phi", o.orbit.phi}};
  const NamedValues variables = ColumnsOf(model, AsBasicOrbit(o.orbit)).variables;
  const auto phi = std::find_if(variables.begin(), variables.end(), [](const auto& v) { return v.first == "phi"; });
  for (auto v = phi + 1; v != variables.end(); ++v) out[v->first] = v->second;
  out["durations"] = o.orbit.durations;
  return out;
}

// The raster, a row of region ids (or negative cell codes) per value of the second parameter.
template <OscillatorModel Model>
Json CellRows(const BasicOrbitTypeMap<Model>& map) {
  const int n = map.options.raster;
  Json rows = Json::array();
  for (int j = 0; j < n; ++j) {
    std::string row;
    for (int i = 0; i < n; ++i) {
      const int cell = map.cells[static_cast<std::size_t>(j) * n + i];
      row += fmt::format("{}{}", i ? " " : "", cell >= 0 ? map.regions[cell].id : cell);
    }
    rows.push_back(row);
  }
  return rows;
}

template <OscillatorModel Model>
Json RegionsJson(const Model& model, const BasicOrbitTypeMap<Model>& map) {
  const MapRectangle& r = map.rectangle;
  Json regions = Json::array();
  for (const BasicMapRegion<Model>& region : map.regions) {
    Json orbits = Json::array();
    for (const BasicMapOrbit<Model>& o : region.orbits) orbits.push_back(OrbitJson(model, o));
    regions.push_back(Json{{"id", region.id},
                           {"cells", region.cells},
                           {r.first, region.first},
                           {r.second, region.second},
                           {"clearance", region.clearance},
                           {"label", region.Label()},
                           {"stable_types", region.StableTypes()},
                           {"orbits", orbits},
                           {"failures", region.failures},
                           {"differing", region.differing},
                           {"elsewhere", region.elsewhere}});
  }
  return regions;
}

template <OscillatorModel Model>
Json CurvesJson(const BasicOrbitTypeMap<Model>& map) {
  const MapRectangle& r = map.rectangle;
  Json curves = Json::array();
  for (const BasicMapCurve<Model>& c : map.curves) {
    Json special = Json::array();
    const std::vector<std::string> labels = SpecialPointLabels(c.branch.branch);  // as curve-<k>/special-points.csv
    for (std::size_t k = 0; k < labels.size(); ++k) {
      const SpecialPoint& s = c.branch.branch.special_points[k];
      special.push_back(Json{{"label", labels[k]},
                             {"type", s.type},
                             {"test_function", s.test_function},
                             {r.first, c.first[s.point]},
                             {r.second, c.second[s.point]}});
    }
    curves.push_back(Json{{"id", c.id},
                          {"kind", c.kind},
                          {"from", c.from},
                          {"direction", c.direction},
                          {"directory", CurveDirectory(c)},
                          {"points", c.branch.orbits.size()},
                          {"end", ToString(c.branch.branch.end)},
                          {"message", c.branch.branch.end_message},
                          {"special_points", special}});
  }
  return curves;
}

// The comparison with a brute-force map, or null without one.
Json ComparisonJson(const MapComparison* comparison, const std::string& brute_force) {
  if (!comparison) return nullptr;
  return Json{{"brute_force", brute_force},
              {"cells", comparison->cells},
              {"compared", comparison->compared},
              {"agreeing", comparison->agreeing},
              {"agreeing_stable", comparison->agreeing_stable},
              {"agreement", comparison->Agreement()},
              {"disagreements", comparison->disagreements.size()},
              {"explained", comparison->Explained()}};
}

template <OscillatorModel Model>
std::string FormatRegionsJson(const Model& model, const BasicOrbitTypeMap<Model>& map, const std::string& trace,
                              const MapComparison* comparison, const std::string& brute_force) {
  const MapRectangle& r = map.rectangle;
  Json skipped = Json::array();
  for (const MapSkippedStart& s : map.skipped) {
    skipped.push_back(Json{{"from", s.from}, {"condition", s.condition}, {"reason", s.reason}});
  }
  const Json root{{"trace", trace},
                  {"first", r.first},
                  {"second", r.second},
                  {"rectangle", {{"first_min", r.first_min}, {"first_max", r.first_max}, {"second_min", r.second_min}, {"second_max", r.second_max}}},
                  {"raster", map.options.raster},
                  {"min_region", map.options.min_region},
                  {"regions", RegionsJson(model, map)},
                  {"curves", CurvesJson(map)},
                  {"skipped", skipped},
                  {"comparison", ComparisonJson(comparison, brute_force)},
                  {"cells", CellRows(map)}};
  return root.dump(2) + "\n";
}

std::string Joined(const std::vector<std::string>& v) { return v.empty() ? "none" : fmt::format("{}", fmt::join(v, "; ")); }

std::string FormatComparisonMd(const OrbitTypeMap& map, const MapComparison& c, const std::string& trace,
                               const std::string& brute_force) {
  const MapRectangle& r = map.rectangle;
  std::string out = fmt::format(
      "# Orbit-type map of {} against the brute force {}\n\n"
      "({}, {}) in [{}, {}] x [{}, {}]. Of {} brute-force cells, {} lie farther than two grid steps from every curve "
      "and inside a region; in {} of them the stable period-1 attractors are the stable orbit types the map assigns "
      "to the region ({} of them with a stable orbit, {} with none on both sides): agreement {:.4f}. Disagreements: {}, "
      "of which {} explained.\n\n",
      trace, brute_force, r.first, r.second, r.first_min, r.first_max, r.second_min, r.second_max, c.cells, c.compared,
      c.agreeing, c.agreeing_stable, c.agreeing - c.agreeing_stable, c.Agreement(), c.disagreements.size(), c.Explained());
  if (!c.disagreements.empty()) {
    out += fmt::format("| cell (i, j) | {} | {} | region | brute force: stable period 1 | map: stable | solved at the cell: stable | "
                       "other attractors | explanation |\n",
                       r.first, r.second);
    out += "|---|---|---|---|---|---|---|---|---|\n";
    for (const MapCellComparison& d : c.disagreements) {
      out += fmt::format("| ({}, {}) | {:.6g} | {:.6g} | {} | {} | {} | {} | {} | {} |\n", d.i, d.j, d.first, d.second, d.region,
                         Joined(d.found), Joined(d.expected), Joined(d.at_cell), Joined(d.others), d.explanation);
    }
  }
  return out;
}

}  // namespace

namespace {

// The trace's branches with their points (admissible, stable) and special points into `map`, each
// orbit by `orbit_of(stored run, point)`, each branch's unknowns by `unknowns_of(its first orbit)`;
// its steps and max_amplitude `run`'s (nullptr: the defaults).
template <OscillatorModel Model, typename OrbitOf, typename UnknownsOf>
void AddTrace(const StoredTrace& trace, const RunFile* run, const OrbitOf& orbit_of, const UnknownsOf& unknowns_of,
              BasicMapTrace<Model>& map) {
  map.parameter = trace.parameter;
  if (run) map.options = WithContinuationKeys(std::move(map.options), *run);
  if (run && run->trace) map.max_amplitude = run->trace->max_amplitude;
  for (std::size_t k = 0; k < trace.branches.size(); ++k) {
    const StoredRun& stored = trace.runs[k];
    BasicMapTraceBranch<Model> b;
    b.name = trace.branches[k].name;
    for (const StoredPoint& p : stored.branch) {
      b.orbits.push_back(orbit_of(stored, p));
      b.admissible.push_back(p.admissible);
      b.stable.push_back(p.stable);
    }
    if (b.orbits.empty()) continue;
    b.unknowns = unknowns_of(b.orbits.front());
    for (const StoredSpecialPoint& s : stored.special_points) {
      b.special.push_back({b.name, s.point.label, s.type, s.test_function, orbit_of(stored, s.point)});
    }
    map.branches.push_back(std::move(b));
  }
}

}  // namespace

MapTrace MapTraceOf(const StoredTrace& trace, const RunFile* run) {
  // The trace's unknowns as its start had them: a preset's (paper-4.2 releases u_s, tied to u_r),
  // then the run file's. Its restart point gives values only, so it is not read.
  UnknownChoice unknowns;
  if (run) {
    RunFile choice = *run;
    choice.restart_run.clear();
    unknowns = StartUnknowns(StartInputOf(choice, {}));
  }
  MapTrace map;
  AddTrace(
      trace, run, [](const StoredRun& stored, const StoredPoint& p) { return OrbitOf(stored, p); },
      [&unknowns](const Orbit&) { return unknowns; }, map);
  return map;
}

BasicMapTrace<DynamicLinearOscillator> ModelMapTraceOf(const StoredTrace& trace, const fs::path& trace_directory,
                                                       const RunFile* run) {
  using Model = DynamicLinearOscillator;
  const ModelFileStart file = ModelOfStoredRun(trace.runs.front(), trace_directory);
  CheckUnitsUnchanged(trace.runs.front(), file);
  BasicMapTrace<Model> map{.parameter = {}, .options = {}, .shooting = ShootingChoice::kAuto,
                           .max_amplitude = kDefaultMaxAmplitude, .branches = {}, .model = file.model};
  AddTrace(
      trace, run,
      [&file](const StoredRun& stored, const StoredPoint& p) { return OrbitOf(file.model, file.parameters, stored, p); },
      [&file](const BasicOrbit<Model>& o) { return UnknownsAtFixedParameters(VariableSetOf(file.model, o.signature)); },
      map);
  if (!map.branches.empty()) {
    SampledStoredOrbit(file, map.branches.front().orbits.front(), 2, trace.runs.front(), "its first point");
  }
  return map;
}

std::vector<std::string> TraceTypes(const StoredTrace& trace) {
  std::set<std::string> types;
  for (const StoredTraceBranch& b : trace.branches) types.insert(b.signature);
  return {types.begin(), types.end()};
}

OrbitTypeMapFiles FormatOrbitTypeMapFiles(const OrbitTypeMap& map, const std::string& trace, const MapComparison* comparison,
                                          const std::string& brute_force) {
  const Pascal2014 model;
  OrbitTypeMapFiles files{FormatCurvesCsv(model, map), FormatRegionsJson(model, map, trace, comparison, brute_force),
                          comparison ? FormatComparisonMd(map, *comparison, trace, brute_force) : std::string(), {}};
  for (const MapCurve& c : map.curves) files.curves.push_back(RecordRun(CurveRun(c, map), c.branch));
  return files;
}

OrbitTypeMapFiles FormatOrbitTypeMapFiles(const DynamicLinearOscillator& model, const std::string& run_file,
                                          const BasicOrbitTypeMap<DynamicLinearOscillator>& map, const std::string& trace) {
  OrbitTypeMapFiles files{FormatCurvesCsv(model, map), FormatRegionsJson(model, map, trace, nullptr, ""), "", {}};
  for (const BasicMapCurve<DynamicLinearOscillator>& c : map.curves) {
    StoredSummary identity;
    identity.run_file = run_file;
    identity.output = CurveDirectory(c);
    identity.parameter = map.rectangle.first;
    files.curves.push_back(RecordRun(model, identity, c.branch));
  }
  return files;
}

void CheckOrbitTypeMapDirectory(const fs::path& directory) {
  const std::string shown = "'" + directory.string() + "'";
  if (!IsRunName(directory.filename().string())) {
    throw InvalidInput("output", shown, fmt::format("a directory's path ending in its name, {}", kRunNameRule));
  }
  std::error_code error;
  // The nearest existing ancestor must be a directory that takes new entries (the rest is created).
  fs::path up = directory.parent_path();
  while (!up.empty() && up != up.root_path() && !fs::exists(fs::status(up, error))) up = up.parent_path();
  if (up.empty()) up = ".";
  if (!fs::is_directory(up, error) || CanCreateFileIn(up)) throw InvalidInput("output", shown, "a directory that can be created");
  const fs::file_status status = fs::symlink_status(directory, error);
  if (!fs::exists(status)) return;
  // A map's regions.json, not any: a foreign one (and the directory's other files) is the user's.
  const auto is_map = [&] {
    try {
      const Json json = detail::ParseJsonObject(detail::ReadTextFile(directory / kRegionsJson), directory / kRegionsJson);
      return std::all_of(std::begin(kRegionsKeys), std::end(kRegionsKeys), [&](const char* key) { return json.contains(key); });
    } catch (const InvalidInput&) {
      return false;
    }
  };
  if (!fs::is_directory(status) || !is_map()) {
    throw InvalidInput("output", shown, "a new directory, or one holding an orbit-type map (regions.json) to replace");
  }
  // The user's files move out of it into the new map.
  if (CanCreateFileIn(directory)) throw InvalidInput("output", shown, "a map's directory that can be written");
}

namespace {

// Whether the map in `directory` (if any) was compared with a brute-force map (its regions.json's
// comparison not null): then its comparison.md is its own.
bool HadComparison(const fs::path& directory) {
  try {
    const Json json = detail::ParseJsonObject(detail::ReadTextFile(directory / kRegionsJson), directory / kRegionsJson);
    return json.contains("comparison") && !json["comparison"].is_null();
  } catch (const InvalidInput&) {
    return false;
  }
}

}  // namespace

std::vector<std::string> WriteOrbitTypeMapFiles(const fs::path& directory, const OrbitTypeMapFiles& files) {
  CheckOrbitTypeMapDirectory(directory);
  const fs::path parent = directory.parent_path().empty() ? fs::path(".") : directory.parent_path();
  std::error_code error;
  fs::create_directories(parent, error);
  if (error) throw InvalidInput("output", "'" + directory.string() + "'", "a directory that can be created");
  // The curves' directories are curve-<k>; "curve-3-continued" or "curve-notes.md" is the user's.
  // In them, their run files; anything else there is the user's too. Of the old directory's curves
  // only those its regions.json lists are the map's: a "curve-9" it does not list is kept whole.
  // A comparison.md is the old map's only where it had a comparison: else it is the user's.
  const auto own_file = [](bool comparison) {
    return [comparison](std::string_view name) {
      return name == kCurvesCsv || name == kRegionsJson || (comparison && name == kComparisonMd);
    };
  };
  const detail::OwnedEntry ours = detail::EntriesWithRuns(
      own_file(!files.comparison_md.empty()), [](std::string_view name) { return detail::IsNumberedName(name, "curve-", false); });
  const std::set<std::string> listed = detail::ListedNames(directory / kRegionsJson, {"directory"});
  const detail::OwnedEntry ours_before = detail::EntriesWithRuns(
      own_file(HadComparison(directory)), [&listed](std::string_view name) { return listed.contains(std::string(name)); });
  return detail::ReplaceDirectory(
      parent, directory.filename().string(),
      [&](const fs::path& target) {
        for (const StoredRun& curve : files.curves) WriteRunFiles(target, curve);
        WriteFileAtomically(target / kCurvesCsv, files.curves_csv);
        WriteFileAtomically(target / kRegionsJson, files.regions_json);
        if (!files.comparison_md.empty()) WriteFileAtomically(target / kComparisonMd, files.comparison_md);
      },
      ours, ours_before);
}

}  // namespace stickslip
