// toml++ through toml_table.hpp, first: it undefines NDEBUG before anything includes <cassert>.
#include "toml_table.hpp"

#include "stickslip/io/run_file.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace stickslip {

using toml_reading::NumberValue;
using toml_reading::ParseToml;
using toml_reading::TableReader;
using toml_reading::Where;

namespace {

void ReadRestart(const toml::table& restart, std::string_view path, RunFile* run) {
  TableReader r(restart, "start.restart.", path, &run->locations);
  r.String("run", &run->restart_run, true);
  if (!IsRunName(run->restart_run)) {
    r.Fail(*r.Get("run"), "run", fmt::format("= '{}' is invalid: valid {}", run->restart_run, kRunNameRule));
  }
  r.String("label", &run->restart_label, true);
  r.Boolean("switch_branch", &run->restart_switch_branch);
  r.String("boundary", &run->restart_boundary);
  if (r.Get("boundary") && run->restart_boundary.empty()) {
    r.Fail(*r.Get("boundary"), "boundary", "= '' is invalid: valid the name of a second parameter to release");
  }
  r.RejectUnknown();
}

void ReadStart(const toml::table& start, std::string_view path, RunFile* run) {
  TableReader s(start, "start.", path, &run->locations);
  s.String("preset", &run->preset);
  s.String("signature", &run->signature);
  s.Values("set", &run->set);
  s.Values("guess", &run->guess);
  if (const toml::table* restart = s.Table("restart", false)) ReadRestart(*restart, path, run);
  s.RejectUnknown();  // first: a misspelt 'signature' is named as such, not as a start not given
  if (run->preset.empty() == run->signature.empty() && run->restart_run.empty()) {
    throw RunFileError(fmt::format("{}: key 'start.preset' or 'start.signature': give exactly one of them",
                                   Where(path, start)));
  }
}

void ReadUnknowns(const toml::table& unknowns, std::string_view path, RunFile* run) {
  TableReader u(unknowns, "unknowns.", path, &run->locations);
  u.Strings("free", &run->free);
  u.Strings("fix", &run->fix);
  u.Boolean("tie_u_r", &run->tie_u_r);
  u.RejectUnknown();
}

// The continued parameter, its direction (a trace goes both ways from its start: "both" or left
// out) and its range.
void ReadParameterAndRange(TableReader& c, bool trace, RunFile* run) {
  c.String("parameter", &run->parameter, true);
  std::string direction;
  c.String("direction", &direction, !trace);
  if (trace && c.Get("direction") && direction != "both") {
    c.Fail(*c.Get("direction"), "direction",
           fmt::format("= '{}' is invalid with a [trace] table: valid \"both\" or left out (a trace goes both ways)",
                       direction));
  }
  if (!trace && direction != "up" && direction != "down") {
    c.Fail(*c.Get("direction"), "direction", fmt::format("= '{}' is invalid: valid \"up\" or \"down\"", direction));
  }
  run->direction = direction == "down" ? -1 : 1;
  std::vector<double> range;
  c.Numbers("range", &range);
  if (!c.Get("range")) c.Missing("range", "give [min, max]");
  if (range.size() != 2) c.Fail(*c.Get("range"), "range", "must be [min, max] with min < max");
  run->range_min = range[0];
  run->range_max = range[1];
}

void ReadContinuationKeys(TableReader& c, std::string_view path, RunFile* run) {
  c.Number("ds", &run->steps.ds);
  c.Number("ds_min", &run->steps.ds_min);
  c.Number("ds_max", &run->steps.ds_max);
  c.Integer("max_points", &run->steps.max_points);
  c.String("shooting", &run->shooting);
  c.String("linear_solver", &run->linear_solver);
  c.Boolean("detect_folds", &run->detect_folds);
  c.Boolean("detect_branch_points", &run->detect_branch_points);
  c.Boolean("continue_past_type_changes", &run->continue_past_type_changes);
  c.Number("max_amplitude", &run->max_amplitude);
  c.Number("resonance_approach", &run->resonance_approach);
  std::vector<double> user_values;
  c.Numbers("user_values", &user_values);
  for (double v : user_values) run->user_values.emplace_back(run->parameter, v);
  if (const toml::table* others = c.Table("user_values_of", false)) {
    TableReader o(*others, "continuation.user_values_of.", path, &run->locations);
    for (const auto& [name, value] : *others) {
      std::vector<double> values;
      o.Numbers(name.str(), &values);
      for (double v : values) run->user_values.emplace_back(std::string(name.str()), v);
    }
  }
}

// A trace's bound on the amplitude is its own (trace.max_amplitude).
void RefuseBranchBoundInTrace(TableReader& c, bool trace) {
  if (trace && c.Get("max_amplitude")) {
    c.Fail(*c.Get("max_amplitude"), "max_amplitude",
           "is invalid with a [trace] table: valid left out (a trace's bound is trace.max_amplitude)");
  }
}

void CheckSolverChoices(TableReader& c, bool trace, const RunFile& run) {
  auto check_member = [&](std::string_view key, const std::string& value, std::vector<std::string> allowed) {
    if (std::find(allowed.begin(), allowed.end(), value) == allowed.end()) {
      c.Fail(*c.Get(key), key, fmt::format("= '{}' is invalid: valid {}", value, fmt::join(allowed, ", ")));
    }
  };
  check_member("shooting", run.shooting, {"auto", "single", "multiple"});
  check_member("linear_solver", run.linear_solver, {"klu", "umfpack", "dense"});
  if (run.shooting == "single" && c.Get("linear_solver")) {  // it would be silently ignored
    c.Fail(*c.Get("linear_solver"), "linear_solver",
           fmt::format("= '{}' is invalid with shooting = \"single\": valid only with shooting \"multiple\" or \"auto\"",
                       run.linear_solver));
  }
  if (trace && run.continue_past_type_changes) {
    c.Fail(*c.Get("continue_past_type_changes"), "continue_past_type_changes",
           "= true is invalid with a [trace] table: valid false (a trace switches at every change of type; "
           "trace.follow_past_unswitched follows a type past one)");
  }
}

void ReadContinuation(const toml::table& continuation, bool trace, std::string_view path, RunFile* run) {
  TableReader c(continuation, "continuation.", path, &run->locations);
  ReadParameterAndRange(c, trace, run);
  ReadContinuationKeys(c, path, run);
  RefuseBranchBoundInTrace(c, trace);
  CheckSolverChoices(c, trace, *run);
  c.RejectUnknown();
}

// A whole-number key of [trace] from `low` to kMaxTraceBranches.
void ReadTraceCount(TableReader& t, const char* key, int low, int* value) {
  if (const toml::node* n = t.Get(key)) {
    if (!n->is_integer() || n->as_integer()->get() < low || n->as_integer()->get() > kMaxTraceBranches) {
      t.Fail(*n, key, fmt::format("is invalid: valid {}", WholeNumberRange(key, low, kMaxTraceBranches)));
    }
    *value = static_cast<int>(n->as_integer()->get());
  }
}

TraceOptions ReadTrace(const toml::table& trace, std::string_view path, RunFile* run) {
  TableReader t(trace, "trace.", path, &run->locations);
  TraceOptions options;
  ReadTraceCount(t, "max_branches", 1, &options.max_branches);
  ReadTraceCount(t, "follow_bifurcations", 0, &options.follow_bifurcations);
  t.Number("max_amplitude", &options.max_amplitude);
  t.Number("loop_tolerance", &options.loop_tolerance);
  t.Boolean("follow_past_unswitched", &options.follow_past_unswitched);
  t.Boolean("allow_inadmissible", &options.allow_inadmissible);
  try {
    options.ValidateOwnFields();
  } catch (const InvalidInput& e) {
    if (const toml::node* n = t.Get(e.field())) t.Fail(*n, e.field(), e.Predicate());
    throw;
  }
  t.RejectUnknown();
  return options;
}

}  // namespace

RunFile ParseRunFile(std::string_view content, std::string_view path) {
  const toml::table root = ParseToml(content, path);
  RunFile run;
  run.path = std::string(path);
  TableReader top(root, "", path, &run.locations);
  // A user's own oscillator (model_table.hpp): read by the commands that take one.
  if (const toml::node* model = top.Get("model")) {
    top.Fail(*model, "model",
             "is not run by `stickslip run` or `continue` in this version, which continue the paper's model; "
             "`stickslip describe` and `stickslip find --model` take a [model]");
  }
  top.String("output", &run.output, true);
  const toml::table* start = top.Table("start", true);
  const toml::table* unknowns = top.Table("unknowns", false);
  const toml::table* continuation = top.Table("continuation", true);
  const toml::table* trace = top.Table("trace", false);
  top.RejectUnknown();  // first: a misspelt [trace] is named as such, not by what a trace lets out
  ReadStart(*start, path, &run);
  if (unknowns != nullptr) ReadUnknowns(*unknowns, path, &run);
  ReadContinuation(*continuation, trace != nullptr, path, &run);
  if (trace != nullptr) run.trace = ReadTrace(*trace, path, &run);
  CheckRunValues(run);
  return run;
}

RunFile ReadRunFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw RunFileError(fmt::format("{}: cannot read the run file", path.string()));
  // The size of the whole file, not of what was read of it before stopping (a 10 MB file read
  // up to the limit was reported as 69632 bytes); a pipe, whose size is unknown, is read up to
  // the limit and reported as larger than it.
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (!error && size > kMaxRunFileBytes) {
    throw RunFileError(fmt::format("{}: run file size = {} bytes is invalid: valid size <= {} bytes", path.string(),
                                   size, kMaxRunFileBytes));
  }
  std::string content;
  char buffer[4096];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    content.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (content.size() > kMaxRunFileBytes) break;
  }
  return ParseRunFile(content, path.string());
}

}  // namespace stickslip
