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
#include "stickslip/io/start_input.hpp"

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
    return RunFileError(fmt::format("{}: key '{}' {}", run.Location(key), key, what), key);
  };
  const StartProblem start = [&] {
    try {
      return BuildStartProblem(StartInputOf(run, results_root));
    } catch (const InvalidInput& e) {
      throw AtRunFileKey(run, e);
    }
  }();
  const UnknownChoice& unknowns = start.unknowns;
  const std::vector<int>& free = start.free;
  const int parameter = *start.parameter;
  OrbitContinuationSetup setup{start.orbit, unknowns, run.parameter, ShootingChoice::kAuto, LinearSolverType::kKlu, {}, {}};
  const double lambda = ov::Pack(start.orbit)(parameter);
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
  std::vector<int> order = free;
  order.push_back(parameter);
  for (const auto& [name, value] : run.user_values) {
    const std::optional<int> index = ov::IndexOf(start.orbit.signature.size(), name);
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
  for (const TestFunctionInfo& t : b.branch.test_functions) columns.push_back(t.name);
  columns.insert(columns.end(), {"admissible", "newton_iterations", "step_size"});
  return columns;
}

std::string Row(const OrbitBranch& b, int i, const std::string& label) {
  const BranchPoint& p = b.branch.points[i];
  const Orbit& o = b.orbits[i];
  std::vector<std::string> fields = {std::to_string(i + 1), label};
  for (ParameterId id : kAllParameters) fields.push_back(Number(o.parameters[id]));
  for (double v : {o.phi, o.x10, o.x20, o.v10}) fields.push_back(Number(v));
  for (double d : o.durations) fields.push_back(Number(d));
  for (int k = 0; k < p.tests.size(); ++k) fields.push_back(Number(p.tests(k)));
  fields.push_back(p.admissible ? "1" : "0");
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
