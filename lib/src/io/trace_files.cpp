#include "stickslip/io/trace_files.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <set>
#include <system_error>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "csv_table.hpp"
#include "result_directory.hpp"
#include "trace_directory.hpp"
#include "stickslip/branches/trace.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/io/atomic_file.hpp"
#include "stickslip/io/result_files.hpp"
#include "stickslip/model/linear_oscillator.hpp"
#include "stickslip/orbits/orbit_layout.hpp"

namespace stickslip {

namespace {

namespace fs = std::filesystem;
namespace ov = orbit_variables;
using detail::CsvTable;
using detail::KeyError;
using Json = nlohmann::ordered_json;

constexpr const char* kTraceCsv = "trace.csv";
constexpr const char* kTraceJson = "trace.json";
constexpr const char* kBranchPrefix = "branch-";

const char* WayName(int direction) { return direction > 0 ? "up" : "down"; }

std::string Number(double v) { return fmt::format("{}", v); }

// trace.csv's columns; the parameter's name stands second after the label, the model's start
// state's names after the period.
std::vector<std::string> CsvHeader(const std::string& parameter, const std::vector<std::string>& start) {
  std::vector<std::string> header = {"branch", "signature", "pt", "label", parameter, "phi", "period"};
  header.insert(header.end(), start.begin(), start.end());
  header.insert(header.end(), {"stable", "admissible"});
  return header;
}

// The start state's names of a run's model (the reader checked the columns' order).
std::vector<std::string> StartNamesOf(const StoredRun& run) { return StartStateNames(run.branch.front().solution); }

// The trace's: its first branch's, or, for a trace without a branch, the paper's.
std::vector<std::string> StartNames(const StoredTrace& t) {
  if (!t.runs.empty()) return StartNamesOf(t.runs.front());
  std::vector<std::string> names;
  const OrbitLayout layout(Pascal2014{}.Description(), 0);
  for (int k = 0; k < layout.StartVariables(); ++k) names.push_back(layout.Name(k));
  return names;
}

// ---- trace.json

// Typed access to one JSON object of trace.json; every key read is required, and Done() refuses
// the keys not read.
class JsonObject {
 public:
  JsonObject(const Json& json, fs::path file, std::string path) : json_(json), file_(std::move(file)), path_(std::move(path)) {
    if (!json_.is_object()) throw KeyError(file_, path_, fmt::format("= {} is invalid: valid a JSON object", json_.dump()));
  }
  const Json& Get(const std::string& key) {
    const auto it = json_.find(key);
    if (it == json_.end()) throw KeyError(file_, Name(key), "is missing");
    read_.push_back(key);
    return *it;
  }
  std::string Text(const std::string& key) { return Typed<std::string>(key, &Json::is_string, "a string"); }
  // A signature (Signature::Parse reads it), or "" where `may_be_empty`.
  std::string SignatureText(const std::string& key, bool may_be_empty) {
    std::string text = Text(key);
    if (may_be_empty && text.empty()) return text;
    try {
      Signature::Parse(text);
    } catch (const InvalidInput& e) {
      throw KeyError(file_, Name(key), fmt::format("= '{}' is invalid: {}", text, e.what()));
    }
    return text;
  }
  bool Flag(const std::string& key) { return Typed<bool>(key, &Json::is_boolean, "true or false"); }
  double Number(const std::string& key) { return Typed<double>(key, &Json::is_number, "a number"); }
  // A number of a column kind (column_kinds.hpp).
  double Number(const std::string& key, const detail::ValidValues& valid) {
    const double value = Number(key);
    if (!valid.Holds(value)) throw KeyError(file_, Name(key), fmt::format("= {} is invalid: valid {}", value, valid.text));
    return value;
  }
  std::size_t Count(const std::string& key) {
    return Typed<std::size_t>(key, &Json::is_number_unsigned, "a count (an integer >= 0)");
  }
  template <class T>
  T Typed(const std::string& key, bool (Json::*is)() const noexcept, const char* valid) {
    const Json& v = Get(key);
    if (!(v.*is)()) throw KeyError(file_, Name(key), fmt::format("= {} is invalid: valid {}", v.dump(), valid));
    return v.get<T>();
  }
  std::string Name(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
  void Done() const {
    for (const auto& [key, value] : json_.items()) {
      if (std::find(read_.begin(), read_.end(), key) == read_.end()) {
        throw KeyError(file_, Name(key), fmt::format("is unknown: valid {}", fmt::join(read_, ", ")));
      }
    }
  }
  const fs::path& file() const { return file_; }

 private:
  const Json& json_;
  fs::path file_;
  std::string path_;
  std::vector<std::string> read_;
};

Json Bifurcations(const std::vector<StoredBifurcation>& met) {
  Json list = Json::array();
  for (const StoredBifurcation& m : met) {
    list.push_back({{"label", m.label}, {"type", m.type}, {"parameter", m.lambda}, {"signature", m.signature},
                    {"singularity", m.singularity}, {"message", m.message}, {"followed", m.followed}});
  }
  return list;
}

std::string FormatJson(const StoredTrace& t) {
  Json json = Json::object();
  json["run_file"] = t.run_file;
  json["stickslip_version"] = t.stickslip_version;
  json["output"] = t.output;
  json["parameter"] = t.parameter;
  json["signature"] = t.signature;
  if (!t.model.empty()) json["model"] = t.model;
  if (!t.natural_frequencies.empty()) json["natural_frequencies"] = t.natural_frequencies;
  json["directions"] = Json::array();
  for (const StoredTraceDirection& d : t.directions) {
    json["directions"].push_back(
        {{"direction", d.direction}, {"end", d.end}, {"message", d.message}, {"branches", d.branches}});
  }
  json["branches"] = Json::array();
  for (const StoredTraceBranch& b : t.branches) {
    const StoredSwitch& w = b.type_switch;
    const Json sw = b.has_switch ? Json{{"status", w.status},     {"bifurcation", w.bifurcation},
                                        {"edit", w.edit},         {"adjacent", w.adjacent},
                                        {"persists", w.persists}, {"from_past", w.from_past}}
                                 : Json(nullptr);
    json["branches"].push_back({{"name", b.name},
                                {"chain", b.chain},
                                {"direction", b.direction},
                                {"signature", b.signature},
                                {"points", b.points},
                                {"start", b.start},
                                {"margin", b.margin},
                                {"switch", sw},
                                {"end", b.end},
                                {"message", b.message},
                                {"bifurcations", Bifurcations(b.bifurcations)}});
  }
  return json.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

// A [model]'s keys: "model" and its "natural_frequencies" (neither in a trace of the paper's model).
void ParseModelKeys(const Json& json, JsonObject& top, StoredTrace& t) {
  const fs::path& file = top.file();
  if (json.contains("model")) {
    t.model = top.Text("model");
    if (t.model != kLinearOscillatorModel) {
      throw KeyError(file, "model", fmt::format("= '{}' is invalid: valid '{}' (or no key, for the paper's model)", t.model,
                                                kLinearOscillatorModel));
    }
  }
  if (!json.contains("natural_frequencies")) return;
  const Json& frequencies = top.Get("natural_frequencies");
  const auto positive = [](const Json& f) { return f.is_number() && f.get<double>() > 0.0 && std::isfinite(f.get<double>()); };
  if (t.model.empty() || !frequencies.is_array() || !std::all_of(frequencies.begin(), frequencies.end(), positive)) {
    throw KeyError(file, "natural_frequencies",
                   fmt::format("= {} is invalid: valid a [model]'s list of positive frequencies", frequencies.dump()));
  }
  for (const Json& f : frequencies) t.natural_frequencies.push_back(f.get<double>());
}

StoredTraceDirection ParseDirection(const Json& json, const fs::path& file, std::size_t k) {
  JsonObject d(json, file, fmt::format("directions[{}]", k));
  StoredTraceDirection direction{.direction = d.Text("direction"), .end = d.Text("end"), .message = d.Text("message")};
  if (direction.direction != (k == 0 ? "down" : "up")) {
    throw KeyError(file, d.Name("direction"), fmt::format("= '{}' is invalid: valid '{}'", direction.direction, k == 0 ? "down" : "up"));
  }
  const Json& branches = d.Get("branches");
  if (!branches.is_array()) throw KeyError(file, d.Name("branches"), "is invalid: valid an array of branch numbers");
  for (const Json& b : branches) {
    if (!b.is_number_unsigned()) throw KeyError(file, d.Name("branches"), "is invalid: valid an array of branch numbers");
    direction.branches.push_back(b.get<std::size_t>());
  }
  d.Done();
  return direction;
}

// The bifurcations a branch met; `lambda` holds the trace parameter's valid values.
std::vector<StoredBifurcation> ParseBifurcations(JsonObject& b, const std::string& branch, const detail::ValidValues& lambda) {
  const fs::path& file = b.file();
  const Json& met = b.Get("bifurcations");
  if (!met.is_array()) throw KeyError(file, b.Name("bifurcations"), "is invalid: valid an array");
  std::vector<StoredBifurcation> bifurcations;
  for (std::size_t i = 0; i < met.size(); ++i) {
    JsonObject m(met[i], file, fmt::format("{}[{}]", b.Name("bifurcations"), i));
    bifurcations.push_back({.label = m.Text("label"),
                            .type = m.Text("type"),
                            .lambda = m.Number("parameter", lambda),
                            .signature = m.SignatureText("signature", true),
                            .singularity = m.Number("singularity", detail::NonNegative()),
                            .message = m.Text("message"),
                            .followed = m.Text("followed")});
    m.Done();
    // Only the directory the writer names: a trace.json cannot point elsewhere.
    const StoredBifurcation& read = bifurcations.back();
    if (!read.followed.empty() && read.followed != fmt::format("{}-{}", branch, read.label)) {
      throw KeyError(file, m.Name("followed"), fmt::format("= '{}' is invalid: valid '' or '{}-{}'", read.followed, branch, read.label));
    }
  }
  return bifurcations;
}

StoredTraceBranch ParseBranch(const Json& json, const fs::path& file, std::size_t k, const detail::ValidValues& lambda) {
  JsonObject b(json, file, fmt::format("branches[{}]", k));
  StoredTraceBranch branch{.name = b.Text("name"),
                           .chain = b.Text("chain"),
                           .direction = b.Text("direction"),
                           .signature = b.SignatureText("signature", false),
                           .points = b.Count("points"),
                           .start = b.Text("start"),
                           .margin = b.Text("margin")};
  if (branch.name != fmt::format("{}{}", kBranchPrefix, k + 1)) {
    throw KeyError(file, b.Name("name"), fmt::format("= '{}' is invalid: valid '{}{}'", branch.name, kBranchPrefix, k + 1));
  }
  const Json& sw = b.Get("switch");
  if (!sw.is_null()) {
    JsonObject s(sw, file, b.Name("switch"));
    branch.has_switch = true;
    branch.type_switch = {.status = s.Text("status"),
                          .bifurcation = s.Text("bifurcation"),
                          .edit = s.Text("edit"),
                          .adjacent = s.SignatureText("adjacent", true),
                          .persists = s.Flag("persists"),
                          .from_past = s.Flag("from_past")};
    s.Done();
  }
  branch.end = b.Text("end");
  branch.message = b.Text("message");
  branch.bifurcations = ParseBifurcations(b, branch.name, lambda);
  b.Done();
  return branch;
}

// Every branch belongs to one direction, in the order the files number them.
void CheckDirectionsListBranches(const StoredTrace& t, const fs::path& file) {
  std::vector<std::size_t> listed;
  for (const StoredTraceDirection& d : t.directions) listed.insert(listed.end(), d.branches.begin(), d.branches.end());
  for (std::size_t k = 0; k < listed.size() || k < t.branches.size(); ++k) {
    if (k >= listed.size() || k >= t.branches.size() || listed[k] != k + 1) {
      throw KeyError(file, "directions", fmt::format("list branches {}: valid 1 to {} in order, the down chain first",
                                                     fmt::join(listed, ", "), t.branches.size()));
    }
  }
}

StoredTrace ParseJson(const std::string& text, const fs::path& file) {
  const Json json = detail::ParseJsonObject(text, file);
  JsonObject top(json, file, "");
  StoredTrace t;
  t.run_file = top.Text("run_file");
  t.stickslip_version = top.Text("stickslip_version");
  t.output = top.Text("output");
  t.parameter = top.Text("parameter");
  t.signature = top.SignatureText("signature", false);
  ParseModelKeys(json, top, t);
  const Json& directions = top.Get("directions");
  if (!directions.is_array() || directions.size() != 2) {
    throw KeyError(file, "directions", "is invalid: valid an array of two directions, down and up");
  }
  for (std::size_t k = 0; k < 2; ++k) t.directions.push_back(ParseDirection(directions[k], file, k));
  const Json& branches = top.Get("branches");
  if (!branches.is_array()) throw KeyError(file, "branches", "is invalid: valid an array of branches");
  // Another model's parameter has the range of its file, which the trace's files do not hold.
  const std::optional<ParameterId> parameter = t.model.empty() ? ParameterFromString(t.parameter) : std::nullopt;
  const detail::ValidValues lambda = parameter ? detail::BranchParameter(*parameter) : detail::Finite();
  for (std::size_t k = 0; k < branches.size(); ++k) t.branches.push_back(ParseBranch(branches[k], file, k, lambda));
  top.Done();
  CheckDirectionsListBranches(t, file);
  return t;
}

// ---- trace.csv

std::string FormatCsv(const StoredTrace& t) {
  std::string text = fmt::format("{}\n", fmt::join(CsvHeader(t.parameter, StartNames(t)), ","));
  for (const StoredTracePoint& p : t.points) {
    std::vector<std::string> start;
    for (const auto& [name, value] : p.start) start.push_back(Number(value));
    text += fmt::format("{},{},{},{},{},{},{},{},{},{}\n", p.branch, p.signature, p.pt, p.label, Number(p.lambda),
                        Number(p.phi), Number(p.period), fmt::join(start, ","), p.stable ? 1 : 0, p.admissible ? 1 : 0);
  }
  return text;
}

// A signature column: one Signature::Parse reads.
std::string ParsedSignature(const CsvTable& table, int row, int column) {
  const std::string& text = table.Text(row, column);
  try {
    Signature::Parse(text);
  } catch (const InvalidInput& e) {
    throw table.Error(row, column, fmt::format("is invalid: {}", e.what()));
  }
  return text;
}

std::vector<StoredTracePoint> ParseCsv(const std::string& text, const fs::path& file, const std::string& parameter,
                                       const std::vector<std::string>& start) {
  const CsvTable table(text, file);
  const std::vector<std::string> header = CsvHeader(parameter, start);
  if (table.header() != header) {
    throw table.HeaderError(fmt::format("the columns are invalid: valid {}", fmt::join(header, ",")));
  }
  std::vector<StoredTracePoint> points;
  const detail::ValidValues finite = detail::Finite();
  const int m = static_cast<int>(start.size());
  for (int r = 0; r < table.rows(); ++r) {
    NamedValues state;
    for (int k = 0; k < m; ++k) state.emplace_back(start[k], table.Value(r, 7 + k, finite));
    points.push_back({.branch = static_cast<std::size_t>(table.Integer(r, 0, 1, std::numeric_limits<int>::max())),
                      .signature = ParsedSignature(table, r, 1),
                      .pt = table.Integer(r, 2, 1, std::numeric_limits<int>::max()),
                      .label = table.Text(r, 3),
                      .lambda = table.Value(r, 4, finite),
                      .phi = table.Value(r, 5, finite),
                      .period = table.Value(r, 6, detail::NonNegative()),
                      .start = std::move(state),
                      .stable = table.Flag(r, 7 + m),
                      .admissible = table.Flag(r, 8 + m)});
  }
  return points;
}

std::vector<StoredTracePoint> PointsOf(const StoredTrace& t) {
  const std::vector<std::string> start = StartNames(t);
  std::vector<StoredTracePoint> points;
  for (std::size_t k = 0; k < t.runs.size(); ++k) {
    const Signature signature = Signature::Parse(t.runs[k].summary.signature);
    for (const StoredPoint& p : t.runs[k].branch) {
      NamedValues state;
      for (const std::string& name : start) state.emplace_back(name, Named(p.solution, name));
      points.push_back({.branch = k + 1,
                        .signature = t.runs[k].summary.signature,
                        .pt = p.pt,
                        .label = p.label,
                        .lambda = Named(p.solution, t.parameter),
                        .phi = Named(p.solution, "phi"),
                        .period = StoredPeriod(signature, p),
                        .start = std::move(state),
                        .stable = p.stable,
                        .admissible = p.admissible});
    }
  }
  return points;
}

}  // namespace

template <OscillatorModel Model>
StoredTrace RecordTrace(const Model& model, const StoredSummary& identity, const BasicTraceResult<Model>& trace) {
  StoredTrace t;
  t.run_file = identity.run_file;
  t.output = identity.output;
  t.model = std::is_same_v<Model, Pascal2014> ? "" : kLinearOscillatorModel;
  t.parameter = trace.parameter;
  for (const BasicTraceDirection<Model>* chain : {&trace.down, &trace.up}) {
    StoredTraceDirection direction{.direction = WayName(chain->direction), .end = ToString(chain->end), .message = chain->message};
    for (const BasicTraceLink<Model>& link : chain->links) {
      const std::size_t k = t.branches.size() + 1;
      StoredSummary branch_run = identity;
      branch_run.output = fmt::format("{}{}", kBranchPrefix, k);
      StoredRun stored = RecordRun(model, branch_run, link.branch);
      if (t.stickslip_version.empty()) t.stickslip_version = stored.summary.stickslip_version;
      if (t.signature.empty()) t.signature = link.signature;
      StoredTraceBranch b{.name = branch_run.output,
                          .chain = direction.direction,
                          .direction = WayName(link.direction),
                          .signature = link.signature,
                          .points = stored.branch.size(),
                          .start = ToString(link.start),
                          .margin = link.margin,
                          .end = ToString(link.end),
                          .message = link.message};
      if (link.type_switch) {
        const BasicTypeSwitch<Model>& sw = *link.type_switch;
        const bool confirmed = sw.status == TypeSwitchStatus::kConfirmed;
        b.has_switch = true;
        b.type_switch = {.status = ToString(sw.status),
                         .bifurcation = confirmed ? sw.adjacent->bifurcation : "",
                         .edit = confirmed ? ToString(sw.adjacent->kind) : "",
                         .adjacent = confirmed ? sw.adjacent->edit.signature.ToString() : "",
                         .persists = confirmed && sw.persists,
                         .from_past = confirmed && sw.singular_start};
      }
      for (const BasicBifurcationMet<Model>& m : link.bifurcations) {
        // Its label, as the branch's special-points.csv has it.
        std::string label;
        for (const StoredSpecialPoint& s : stored.special_points) {
          if (s.point.pt == m.point + 1 && s.type == m.type) label = s.point.label;
        }
        std::string followed;
        if (m.followed && !m.followed->orbits.empty()) {
          followed = fmt::format("{}-{}", branch_run.output, label);
          StoredSummary followed_run = identity;
          followed_run.output = followed;
          t.followed_runs.push_back(RecordRun(model, followed_run, *m.followed));
        }
        b.bifurcations.push_back({label, m.type, m.lambda, m.signature, m.singularity, m.message, followed});
      }
      t.branches.push_back(std::move(b));
      t.runs.push_back(std::move(stored));
      direction.branches.push_back(k);
    }
    t.directions.push_back(std::move(direction));
  }
  t.points = PointsOf(t);
  return t;
}

StoredTrace RecordTrace(const RunFile& run, const TraceResult& trace) {
  return RecordTrace(Pascal2014{}, StoredSummary{.run_file = run.path, .output = run.output, .parameter = run.parameter},
                     trace);
}

template StoredTrace RecordTrace(const Pascal2014&, const StoredSummary&, const BasicTraceResult<Pascal2014>&);
template StoredTrace RecordTrace(const DynamicLinearOscillator&, const StoredSummary&,
                                 const BasicTraceResult<DynamicLinearOscillator>&);

TraceFiles FormatTraceFiles(const StoredTrace& trace) { return {FormatCsv(trace), FormatJson(trace)}; }

bool IsTraceDirectory(const fs::path& directory) {
  std::error_code ignored;
  return fs::is_directory(fs::symlink_status(directory, ignored)) && fs::exists(directory / kTraceJson, ignored);
}

bool IsPartOfTrace(const fs::path& results_root, const std::string& output) {
  return IsTraceDirectory(results_root) &&
         (output == kTraceCsv || output == kTraceJson || detail::IsNumberedName(output, kBranchPrefix, true));
}

void CheckTraceOutputDirectory(const fs::path& results_root, const std::string& output) {
  const fs::path target = results_root / output;
  if (IsTraceDirectory(target)) {
    // Recognised by what any version's trace.json has, not read whole: a trace written by an older
    // stickslip (fewer keys) is replaced, as a run is by its summary.json.
    try {
      const fs::path file = target / kTraceJson;
      const Json json = detail::ParseJsonObject(detail::ReadTextFile(file), file);
      for (const char* key : {"stickslip_version", "directions", "branches"}) {
        if (!json.contains(key)) throw KeyError(file, key, "is missing");
      }
    } catch (const InvalidInput& e) {
      throw InvalidInput::WithMessage(
          "output", fmt::format("output = '{}' is invalid: '{}' holds no stickslip trace ({}): valid a new name or the "
                                "directory of a stickslip run or trace",
                                output, target.string(), e.what()));
    }
    if (const std::error_code failed = CanCreateFileIn(results_root)) {
      throw InvalidInput::WithMessage(
          "results", fmt::format("results = '{}' is invalid: no file can be created in it ({}): valid a directory, or a "
                                 "path where one can be created",
                                 results_root.string(), failed.message()));
    }
    return;
  }
  CheckOutputDirectory(results_root, output);
}

namespace detail {

namespace {
bool IsTraceFile(std::string_view name) { return name == kTraceCsv || name == kTraceJson || IsRunFileName(name); }
}  // namespace

OwnedEntry TraceEntries() {
  // The files a trace writes (its branches branch-<k>, its followed runs branch-<k>-<label>, and
  // their run files); every other entry, at any depth, is the user's ("branch-notes.md", an export
  // in branch-2/, a continuation written into branch-1/).
  return EntriesWithRuns(IsTraceFile, [](std::string_view name) { return IsNumberedName(name, kBranchPrefix, true); });
}

OwnedEntry TraceEntriesBefore(const fs::path& directory) {
  // Of the old directory's branches only those its trace.json lists are the trace's: a "branch-9" it
  // does not list (a directory or a file of the user's) is kept whole.
  const std::set<std::string> listed = ListedNames(directory / kTraceJson, {"name", "followed"});
  return EntriesWithRuns(IsTraceFile, [listed](std::string_view name) { return listed.contains(std::string(name)); });
}

void WriteTraceInto(const fs::path& directory, const StoredTrace& trace) {
  const TraceFiles files = FormatTraceFiles(trace);
  for (const StoredRun& run : trace.runs) WriteRunFiles(directory, run);
  for (const StoredRun& run : trace.followed_runs) WriteRunFiles(directory, run);
  WriteFileAtomically(directory / kTraceCsv, files.trace_csv);
  WriteFileAtomically(directory / kTraceJson, files.trace_json);
}

}  // namespace detail

std::vector<std::string> WriteTraceFiles(const fs::path& results_root, const StoredTrace& trace) {
  CheckTraceOutputDirectory(results_root, trace.output);
  return detail::ReplaceDirectory(
      results_root, trace.output, [&](const fs::path& directory) { detail::WriteTraceInto(directory, trace); },
      detail::TraceEntries(), detail::TraceEntriesBefore(results_root / trace.output));
}

StoredTrace ReadTraceFiles(const fs::path& trace_directory) {
  const fs::path json_file = trace_directory / kTraceJson;
  StoredTrace t = ParseJson(detail::ReadTextFile(json_file), json_file);
  for (const StoredTraceBranch& b : t.branches) {
    StoredRun run = ReadRunFiles(trace_directory / b.name);
    if (run.branch.size() != b.points || run.summary.signature != b.signature) {
      throw KeyError(json_file, b.name,
                     fmt::format("says {} points of '{}': {} has {} of '{}'", b.points, b.signature, b.name,
                                 run.branch.size(), run.summary.signature));
    }
    if (run.summary.model != t.model) {
      throw KeyError(json_file, b.name, fmt::format("is a run of another model than the trace's ('{}', not '{}')",
                                                    run.summary.model, t.model));
    }
    // trace.csv's columns are read as these variables of every branch's orbits.
    if (!t.runs.empty() && StartNamesOf(run) != StartNamesOf(t.runs.front())) {
      throw KeyError(json_file, b.name,
                     fmt::format("has the start state {} where branch-1 has {}: valid the same model's branches",
                                 fmt::join(StartNamesOf(run), ","), fmt::join(StartNamesOf(t.runs.front()), ",")));
    }
    if (run.summary.parameter != t.parameter) {
      throw KeyError(json_file, "parameter",
                     fmt::format("= '{}' differs from the parameter of {}, '{}'", t.parameter, b.name, run.summary.parameter));
    }
    t.runs.push_back(std::move(run));
    for (const StoredBifurcation& m : b.bifurcations) {
      if (!m.followed.empty()) t.followed_runs.push_back(ReadRunFiles(trace_directory / m.followed));
    }
  }
  const fs::path csv_file = trace_directory / kTraceCsv;
  t.points = ParseCsv(detail::ReadTextFile(csv_file), csv_file, t.parameter, StartNames(t));
  const std::string read = FormatCsv(t);
  StoredTrace from_branches = t;
  from_branches.points = PointsOf(t);
  const std::string expected = FormatCsv(from_branches);
  if (read != expected) {
    const auto [r, e] = std::mismatch(read.begin(), read.end(), expected.begin(), expected.end());
    const auto line = 1 + std::count(read.begin(), r, '\n');
    throw InvalidInput::WithMessage(csv_file.string(),
                                    fmt::format("{}:{}: differs from the branches' files: valid one row per point of "
                                                "every branch, as they have them",
                                                csv_file.string(), line));
  }
  return t;
}

}  // namespace stickslip
