#include "stickslip/io/run.hpp"

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <system_error>

#include <fmt/format.h>
#include <unistd.h>

#include "stickslip/io/atomic_file.hpp"
#include "stickslip/io/json.hpp"
#include "stickslip/orbits/paper_presets.hpp"

#ifndef STICKSLIP_VERSION
#define STICKSLIP_VERSION "unknown"
#endif

namespace stickslip {

namespace ov = orbit_variables;

std::string ReadTextFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(fmt::format("cannot read '{}'", path.string()));
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

CsvTable ParseCsv(const std::string& text) {
  CsvTable table;
  std::istringstream lines(text);
  std::string line;
  auto split = [](const std::string& l) {
    std::vector<std::string> fields;
    std::string field;
    std::istringstream in(l);
    while (std::getline(in, field, ',')) fields.push_back(field);
    if (!l.empty() && l.back() == ',') fields.emplace_back();
    return fields;
  };
  if (std::getline(lines, line)) table.header = split(line);
  while (std::getline(lines, line)) {
    if (!line.empty()) table.rows.push_back(split(line));
  }
  return table;
}

LabelledPoint ReadLabelledPoint(const std::filesystem::path& results_root, const std::string& run,
                                const std::string& label) {
  if (!IsRunName(run)) {
    throw std::runtime_error(fmt::format("run '{}' is invalid: valid {}", run, kRunNameRule));
  }
  const std::filesystem::path dir = results_root / run;
  const CsvTable table = ParseCsv(ReadTextFile(dir / "special-points.csv"));
  const std::string summary = ReadTextFile(dir / "summary.json");
  LabelledPoint point;
  const std::string key = "\"signature\": \"";
  const auto at = summary.find(key);
  if (at == std::string::npos) throw std::runtime_error(fmt::format("'{}' has no signature", (dir / "summary.json").string()));
  point.signature = summary.substr(at + key.size(), summary.find('"', at + key.size()) - at - key.size());
  std::vector<std::string> labels;
  for (const auto& row : table.rows) {
    if (row.size() != table.header.size()) continue;
    if (labels.empty() || labels.back() != row[1]) labels.push_back(row[1]);  // an end repeats its label
    if (row[1] != label) continue;
    for (std::size_t k = 0; k < row.size(); ++k) point.columns.emplace_back(table.header[k], row[k]);
    return point;
  }
  throw std::runtime_error(fmt::format("label '{}' is not in '{}': valid labels {}", label,
                                       (dir / "special-points.csv").string(), fmt::join(labels, ", ")));
}

OrbitContinuationSetup MakeSetup(const RunFile& run, const std::filesystem::path& results_root) {
  auto fail = [&](const std::string& key, const std::string& what) -> RunFileError {
    return RunFileError(fmt::format("{}: key '{}' {}", run.Location(key), key, what));
  };
  // The start orbit: a preset's printed values, a restart point, or a signature with values.
  std::optional<Orbit> start;
  UnknownChoice unknowns;
  if (!run.preset.empty()) {
    const PaperPreset* preset = FindPaperPreset(run.preset);
    if (preset == nullptr) {
      throw fail("start.preset", fmt::format("= '{}' is unknown: valid paper-4.1, paper-4.2, paper-5.1, paper-5.2, paper-6",
                                             run.preset));
    }
    start = preset->Guess();
    unknowns = preset->unknowns;
  }
  std::string signature_text = run.signature;
  LabelledPoint restart;
  if (!run.restart_run.empty()) {
    try {
      restart = ReadLabelledPoint(results_root, run.restart_run, run.restart_label);
    } catch (const std::runtime_error& e) {
      throw fail("start.restart", fmt::format("cannot be used: {}", e.what()));
    }
    if (signature_text.empty()) signature_text = restart.signature;
  }
  if (!signature_text.empty()) {
    std::string error;
    const std::optional<Signature> signature = Signature::Parse(signature_text, &error);
    if (!signature) throw fail("start.signature", "is invalid: " + error);
    if (!start) {
      start = Orbit{*signature, {}, 0.0, 0.0, 0.0, 0.0, std::vector<double>(signature->size(), 0.0)};
    } else if (!(start->signature == *signature)) {
      throw fail("start.signature", "differs from the preset's; give one of them");
    }
  }
  Eigen::VectorXd variables = ov::Pack(*start);
  const int n = start->signature.size();
  auto assign = [&](const std::string& key, const std::string& name, double value) {
    const std::optional<int> index = ov::IndexOf(n, name);
    if (!index) {
      std::vector<std::string> names;
      for (int i = 0; i < ov::Count(n); ++i) names.push_back(ov::Name(n, i));
      throw fail(key, fmt::format("names '{}', not a variable: valid {}", name, fmt::join(names, ", ")));
    }
    variables(*index) = value;
  };
  for (const auto& [column, text] : restart.columns) {
    if (ov::IndexOf(n, column)) assign("start.restart", column, std::stod(text));
  }
  for (const auto& [name, value] : run.set) assign("start.set", name, value);
  for (const auto& [name, value] : run.guess) assign("start.guess", name, value);
  Orbit orbit = ov::Unpack(start->signature, variables);

  unknowns.release.insert(unknowns.release.end(), run.free.begin(), run.free.end());
  unknowns.fix.insert(unknowns.fix.end(), run.fix.begin(), run.fix.end());
  unknowns.tie_static_friction = unknowns.tie_static_friction || run.tie_u_r;
  if (unknowns.tie_static_friction) orbit.parameters.u_r = orbit.parameters.u_s;
  if (const auto invalid = Validate(orbit.parameters)) throw fail("start", std::string("gives invalid data: ") + invalid->what());
  for (int i = 0; i < n; ++i) {
    if (!(orbit.durations[i] > 0.0)) {
      throw fail("start.guess", fmt::format("misses d{} (> 0): give the duration of segment {}", i + 1, i + 1));
    }
  }
  const FreeVariables free = ResolveUnknowns(orbit.signature, unknowns);
  if (!free.error.empty()) throw fail("unknowns", "is invalid: " + free.error);

  OrbitContinuationSetup setup{orbit, unknowns, run.parameter, ShootingChoice::kAuto, LinearSolverType::kKlu, {}, {}};
  const std::optional<int> parameter = ov::IndexOf(n, run.parameter);
  if (!parameter) throw fail("continuation.parameter", fmt::format("= '{}' is not a variable", run.parameter));
  if (unknowns.tie_static_friction && run.parameter == "u_r") {
    throw fail("continuation.parameter", "= 'u_r' is tied to u_s (tie_u_r): continue in u_s");
  }
  if (std::find(free.indices.begin(), free.indices.end(), *parameter) != free.indices.end()) {
    throw fail("continuation.parameter", fmt::format("= '{}' is an unknown already: continue in a held variable", run.parameter));
  }
  const double lambda = variables(*parameter);
  if (lambda < run.range_min || lambda > run.range_max) {
    throw fail("continuation.range", fmt::format("= [{}, {}] excludes the start, {} = {}", run.range_min,
                                                 run.range_max, run.parameter, lambda));
  }
  setup.shooting = run.shooting == "single" ? ShootingChoice::kSingle
                   : run.shooting == "multiple" ? ShootingChoice::kMultiple
                                                : ShootingChoice::kAuto;
  setup.sparse_solver = *LinearSolverFromString(run.linear_solver);
  ContinuationOptions& o = setup.options;
  o.direction = run.direction;
  o.lambda_min = run.range_min;
  o.lambda_max = run.range_max;
  o.step.ds = run.ds;
  o.step.ds_min = run.ds_min;
  o.step.ds_max = run.ds_max;
  o.max_points = run.max_points;
  o.detect_folds = run.detect_folds;
  o.detect_branch_points = run.detect_branch_points;
  o.continue_past_terminal = run.continue_past_type_changes;
  // User values address unknowns: the free variables in their order, then the parameter.
  std::vector<int> order = free.indices;
  order.push_back(*parameter);
  for (const auto& [name, value] : run.user_values) {
    const std::optional<int> index = ov::IndexOf(n, name);
    const auto position = index ? std::find(order.begin(), order.end(), *index) : order.end();
    if (position == order.end()) {
      throw fail("continuation.user_values_of", fmt::format("names '{}', which is not an unknown of the run", name));
    }
    o.user_values.push_back({static_cast<int>(position - order.begin()), value, fmt::format("{}={}", name, value)});
  }
  return setup;
}

namespace {

std::string Number(double v) { return fmt::format("{}", v); }

std::vector<std::string> Columns(const OrbitBranch& b) {
  const Signature& signature = b.orbits.front().signature;
  std::vector<std::string> columns = {"pt", "label", "chi", "eta", "omega", "u_s", "u_r", "phi", "x10", "x20", "v10"};
  for (int i = 0; i < signature.size(); ++i) columns.push_back(fmt::format("d{}", i + 1));
  for (const PointColumn& c : b.columns) columns.push_back(c.name);
  columns.insert(columns.end(), {"newton_iterations", "step_size"});
  return columns;
}

std::string Row(const OrbitBranch& b, int i, const std::string& label) {
  const BranchPoint& p = b.branch.points[i];
  const Orbit& o = b.orbits[i];
  std::vector<std::string> fields = {std::to_string(i + 1), label};
  for (ParameterId id : kAllParameters) fields.push_back(Number(o.parameters[id]));
  for (double v : {o.phi, o.x10, o.x20, o.v10}) fields.push_back(Number(v));
  for (double d : o.durations) fields.push_back(Number(d));
  for (double v : ColumnValues(b.columns, p)) fields.push_back(Number(v));
  fields.push_back(std::to_string(p.newton_iterations));
  fields.push_back(Number(p.ds));
  return fmt::format("{}", fmt::join(fields, ","));
}

}  // namespace

RunFiles FormatRunFiles(const RunFile& run, const OrbitBranch& b) {
  // AUTO-style labels: the type and a running number, in branch order.
  std::vector<std::string> labels(b.branch.points.size());
  int counter = 0;
  for (std::size_t i = 0; i < b.branch.points.size(); ++i) {
    if (!b.branch.points[i].label.empty()) labels[i] = fmt::format("{}{}", b.branch.points[i].label, ++counter);
  }
  RunFiles files;
  const std::vector<std::string> columns = Columns(b);
  files.branch_csv = fmt::format("{}\n", fmt::join(columns, ","));
  for (std::size_t i = 0; i < b.branch.points.size(); ++i) files.branch_csv += Row(b, static_cast<int>(i), labels[i]) + "\n";
  files.special_points_csv = fmt::format("{},type,test_function,located\n", fmt::join(columns, ","));
  std::map<std::string, int> counts;
  for (const SpecialPoint& s : b.branch.special_points) {
    // An end that coincides with a located point keeps that point's label.
    const std::string label = labels[s.point].empty() ? s.type : labels[s.point];
    files.special_points_csv += fmt::format("{},{},{},{}\n", Row(b, s.point, label), s.type, s.test_function, s.located ? 1 : 0);
    ++counts[s.type];
  }
  std::string count_text;
  for (const auto& [type, count] : counts) count_text += fmt::format("{}\"{}\": {}", count_text.empty() ? "" : ", ", type, count);
  files.summary_json = fmt::format(
      "{{\n  \"run_file\": {},\n  \"stickslip_version\": {},\n  \"output\": {},\n  \"signature\": {},\n"
      "  \"parameter\": {},\n  \"shooting\": {},\n  \"points\": {},\n  \"special_points\": {{{}}},\n"
      "  \"termination\": {},\n  \"message\": {}\n}}\n",
      JsonString(run.path), JsonString(STICKSLIP_VERSION), JsonString(run.output),
      JsonString(b.orbits.front().signature.ToString()), JsonString(run.parameter), JsonString(ToString(b.shooting)),
      b.branch.points.size(), count_text, JsonString(ToString(b.branch.end)), JsonString(b.branch.end_message));
  return files;
}

void WriteRunFiles(const std::filesystem::path& results_root, const std::string& output, const RunFiles& files) {
  namespace fs = std::filesystem;
  fs::create_directories(results_root);
  const fs::path target = results_root / output;
  const fs::path temporary = results_root / fmt::format(".{}.tmp.{}", output, static_cast<long>(::getpid()));
  const fs::path old = results_root / fmt::format(".{}.old.{}", output, static_cast<long>(::getpid()));
  std::error_code ignored;
  fs::remove_all(temporary, ignored);
  fs::create_directories(temporary);
  try {
    WriteFileAtomically(temporary / "branch.csv", files.branch_csv);
    WriteFileAtomically(temporary / "special-points.csv", files.special_points_csv);
    WriteFileAtomically(temporary / "summary.json", files.summary_json);
    if (fs::exists(target)) fs::rename(target, old);
    fs::rename(temporary, target);
  } catch (...) {
    fs::remove_all(temporary, ignored);
    if (!fs::exists(target) && fs::exists(old)) fs::rename(old, target, ignored);
    throw;
  }
  fs::remove_all(old, ignored);
}

}  // namespace stickslip
