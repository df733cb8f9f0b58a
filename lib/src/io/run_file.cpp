// The only translation unit that includes toml++, compiled header-only here (not Debian's shared
// library). Debian's toml++ 3.3.0 aborts on some malformed input through its internal asserts,
// and with NDEBUG turns them into optimiser assumptions (undefined behaviour); here they are
// no-ops, and the input is screened before parsing.
#ifdef NDEBUG
#undef NDEBUG
#endif
#define TOML_HEADER_ONLY 1
#define TOML_ASSERT(expr) static_cast<void>(0)
#include <toml++/toml.h>

#include "stickslip/io/run_file.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace stickslip {

namespace {

// Rejects what toml++ 3.3.0 mishandles: C0 control characters (but tab, newline, carriage
// return), DEL, non-ASCII bytes outside comments (its whitespace test reaches
// __builtin_unreachable on some, U+FEBF for one), and arrays nested deeper than two levels; and
// multi-line strings, so that the screen knows exactly where comments are.
void Screen(std::string_view content, std::string_view path) {
  if (content.size() > kMaxRunFileBytes) {
    throw RunFileError(fmt::format("{}: run file size = more than {} bytes is invalid: valid size <= {} bytes", path,
                                   kMaxRunFileBytes, kMaxRunFileBytes));
  }
  int line = 1, column = 0, depth = 0;
  bool comment = false, escaped = false;
  char quote = 0;
  for (std::size_t i = 0; i < content.size(); ++i) {
    const auto c = static_cast<unsigned char>(content[i]);
    ++column;
    if (c == '\n') {
      ++line;
      column = 0;
      comment = false;
      escaped = false;
      if (quote == '"' || quote == '\'') quote = 0;  // single-line strings end (toml++ reports)
      continue;
    }
    if ((c < 0x20 && c != '\t' && c != '\r') || c == 0x7f) {
      throw RunFileError(fmt::format("{}:{}:{}: control character 0x{:02x} is not allowed", path, line, column, c));
    }
    if (c >= 0x80 && !comment) {
      throw RunFileError(fmt::format("{}:{}:{}: non-ASCII byte 0x{:02x} outside a comment: valid only in comments",
                                     path, line, column, c));
    }
    if (comment) continue;
    if (quote != 0) {
      // The byte after a backslash is escaped but was checked above like any other.
      if (escaped) escaped = false;
      else if (c == '\\' && quote == '"') escaped = true;
      else if (c == static_cast<unsigned char>(quote)) quote = 0;
      continue;
    }
    if (c == '#') comment = true;
    else if (c == '"' || c == '\'') {
      // Multi-line strings would need the screen to follow toml++'s rules for runs of quotes;
      // a run file has no use for them, so they are refused.
      if (content.substr(i, 3) == std::string(3, static_cast<char>(c))) {
        throw RunFileError(fmt::format("{}:{}:{}: multi-line strings ({}) are not allowed: valid single-line strings",
                                       path, line, column, content.substr(i, 3)));
      }
      quote = static_cast<char>(c);
    }
    else if (c == '[') {
      // "[[" at the start of a line is an array-of-tables header, not nesting.
      if (++depth > 2 && !(column == 1 || (column == 2 && content[i - 1] == '['))) {
        throw RunFileError(fmt::format("{}:{}:{}: arrays nest at most two levels deep", path, line, column));
      }
    } else if (c == ']') {
      depth = std::max(0, depth - 1);
    }
  }
}

// A number node's value. toml++'s value<double>() is empty for an integer that a double cannot
// hold exactly (beyond 2^53), so integers are converted here, to the nearest double.
double NumberValue(const toml::node& node) {
  if (const auto* integer = node.as_integer()) return static_cast<double>(integer->get());
  return node.as_floating_point()->get();
}

std::string Where(std::string_view path, const toml::node& node) {
  const toml::source_position p = node.source().begin;
  return fmt::format("{}:{}:{}", path, p.line, p.column);
}

// Reads the keys of one table, checking each is known and of the right type.
class TableReader {
 public:
  TableReader(const toml::table& table, std::string prefix, std::string_view path, RunFile* run)
      : table_(table), prefix_(std::move(prefix)), path_(path), run_(run) {}

  const toml::node* Get(std::string_view key) {
    known_.insert(std::string(key));
    const toml::node* node = table_.get(key);
    if (node) run_->locations[prefix_ + std::string(key)] = Where(path_, *node);
    return node;
  }
  [[noreturn]] void Fail(const toml::node& node, std::string_view key, std::string_view what) const {
    throw RunFileError(fmt::format("{}: key '{}{}' {}", Where(path_, node), prefix_, key, what), prefix_ + std::string(key));
  }
  [[noreturn]] void Missing(std::string_view key, std::string_view what) const {
    throw RunFileError(fmt::format("{}: key '{}{}' is missing: {}", Where(path_, table_), prefix_, key, what),
                       prefix_ + std::string(key));
  }

  void String(std::string_view key, std::string* out, bool required = false) {
    const toml::node* n = Get(key);
    if (!n) {
      if (required) Missing(key, "give a string");
      return;
    }
    if (!n->is_string()) Fail(*n, key, fmt::format("must be a string, got {}", toml::impl::node_type_friendly_names[static_cast<int>(n->type())]));
    *out = n->as_string()->get();
  }
  void Number(std::string_view key, double* out, bool required = false) {
    const toml::node* n = Get(key);
    if (!n) {
      if (required) Missing(key, "give a number");
      return;
    }
    if (!n->is_number()) Fail(*n, key, fmt::format("must be a number, got {}", toml::impl::node_type_friendly_names[static_cast<int>(n->type())]));
    *out = NumberValue(*n);
    if (!std::isfinite(*out)) Fail(*n, key, "must be finite");
  }
  void Integer(std::string_view key, int* out) {
    const toml::node* n = Get(key);
    if (!n) return;
    if (!n->is_integer()) Fail(*n, key, "must be an integer");
    const std::int64_t v = n->as_integer()->get();
    if (v < 1 || v > kMaxRunPoints) Fail(*n, key, fmt::format("= {} is invalid: valid range 1 to {}", v, kMaxRunPoints));
    *out = static_cast<int>(v);
  }
  void Boolean(std::string_view key, bool* out) {
    const toml::node* n = Get(key);
    if (!n) return;
    if (!n->is_boolean()) {
      // The value as written (a string, 1e300, an array): short ones shown, every one's type named.
      std::ostringstream shown;
      n->visit([&shown](const auto& v) { shown << v; });
      std::string value = shown.str();
      if (value.size() > 40) value = value.substr(0, 40) + "...";
      Fail(*n, key, fmt::format("= {} is invalid: valid true or false (a boolean; its type is {})", value,
                                toml::impl::node_type_friendly_names[static_cast<int>(n->type())]));
    }
    *out = n->as_boolean()->get();
  }
  void Strings(std::string_view key, std::vector<std::string>* out) {
    const toml::node* n = Get(key);
    if (!n) return;
    if (!n->is_array()) Fail(*n, key, "must be an array of strings");
    for (const toml::node& e : *n->as_array()) {
      if (!e.is_string()) Fail(e, key, "must be an array of strings");
      out->push_back(e.as_string()->get());
    }
  }
  void Numbers(std::string_view key, std::vector<double>* out) {
    const toml::node* n = Get(key);
    if (!n) return;
    if (!n->is_array()) Fail(*n, key, "must be an array of numbers");
    for (const toml::node& e : *n->as_array()) {
      if (!e.is_number()) Fail(e, key, "must be an array of numbers");
      out->push_back(NumberValue(e));
      if (!std::isfinite(out->back())) Fail(e, key, "must hold finite numbers");
    }
  }
  // A table of name = number.
  void Values(std::string_view key, NamedValues* out) {
    const toml::node* n = Get(key);
    if (!n) return;
    if (!n->is_table()) Fail(*n, key, "must be a table of name = number");
    for (const auto& [name, value] : *n->as_table()) {
      if (!value.is_number()) Fail(value, fmt::format("{}.{}", key, name.str()), "must be a number");
      out->emplace_back(std::string(name.str()), NumberValue(value));
      if (!std::isfinite(out->back().second)) Fail(value, fmt::format("{}.{}", key, name.str()), "must be finite");
    }
  }
  const toml::table* Table(std::string_view key, bool required) {
    const toml::node* n = Get(key);
    if (!n) {
      if (required) Missing(key, "give a table");
      return nullptr;
    }
    if (!n->is_table()) Fail(*n, key, "must be a table");
    return n->as_table();
  }
  // Unknown keys, with the nearest known one suggested.
  void RejectUnknown() const {
    for (const auto& [key, value] : table_) {
      const std::string name(key.str());
      if (known_.count(name)) continue;
      std::string suggestion;
      std::size_t best = 3;
      for (const std::string& k : known_) {
        const std::size_t d = Distance(name, k);
        if (d < best) best = d, suggestion = k;
      }
      Fail(value, name, suggestion.empty() ? std::string("is unknown")
                                           : fmt::format("is unknown: did you mean '{}{}'?", prefix_, suggestion));
    }
  }

 private:
  static std::size_t Distance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
      std::size_t diagonal = row[0];
      row[0] = i;
      for (std::size_t j = 1; j <= b.size(); ++j) {
        const std::size_t up = row[j];
        row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
        diagonal = up;
      }
    }
    return row[b.size()];
  }

  const toml::table& table_;
  std::string prefix_;
  std::string_view path_;
  RunFile* run_;
  std::set<std::string> known_;
};

// Whether `text` is valid UTF-8: no stray continuation byte, no truncated sequence, no overlong
// form, no surrogate, nothing above U+10FFFF.
bool IsUtf8(std::string_view text) {
  for (std::size_t i = 0; i < text.size();) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned char lead = byte(i);
    const int length = lead < 0x80 ? 1 : lead >= 0xc2 && lead <= 0xdf ? 2 : lead >= 0xe0 && lead <= 0xef ? 3
                                                                             : lead >= 0xf0 && lead <= 0xf4 ? 4 : 0;
    if (length == 0 || i + length > text.size()) return false;
    for (int k = 1; k < length; ++k) {
      if ((byte(i + k) & 0xc0) != 0x80) return false;
    }
    // The second byte's range where the lead alone does not exclude overlong forms, surrogates
    // and code points past U+10FFFF.
    const unsigned char second = length > 1 ? byte(i + 1) : 0x80;
    if ((lead == 0xe0 && second < 0xa0) || (lead == 0xed && second > 0x9f) || (lead == 0xf0 && second < 0x90) ||
        (lead == 0xf4 && second > 0x8f)) {
      return false;
    }
    i += static_cast<std::size_t>(length);
  }
  return true;
}

}  // namespace

bool IsRunName(std::string_view name) {
  // A control character would break the one-line messages and listings that name the run.
  const bool control = std::any_of(name.begin(), name.end(), [](char c) {
    const auto u = static_cast<unsigned char>(c);
    return u < 0x20 || u == 0x7f;
  });
  return !name.empty() && name.size() <= kMaxRunNameLength && name != "." && !control && name.find('/') == std::string_view::npos &&
         name.find("..") == std::string_view::npos && name.find(':') == std::string_view::npos && IsUtf8(name);
}

namespace {

toml::table ParseToml(std::string_view content, std::string_view path) {
  Screen(content, path);
  try {
    return toml::parse(content, path);
  } catch (const toml::parse_error& e) {
    const auto& p = e.source().begin;
    throw RunFileError(fmt::format("{}:{}:{}: {}", path, p.line, p.column, e.description()));
  }
}

void ReadRestart(const toml::table& restart, const toml::table& root, std::string_view path, RunFile* run) {
  TableReader r(restart, "start.restart.", path, run);
  r.String("run", &run->restart_run, true);
  if (!IsRunName(run->restart_run)) {
    r.Fail(*r.Get("run"), "run", fmt::format("= '{}' is invalid: valid {}", run->restart_run, kRunNameRule));
  }
  r.String("label", &run->restart_label, true);
  r.Boolean("switch_branch", &run->restart_switch_branch);
  r.String("boundary", &run->restart_boundary);
  // The branch that leaves a bifurcation leaves it on the side `direction` names; a trace has
  // none (both ways from its start would go out along one side and back along the other).
  if (run->restart_switch_branch && root.contains("trace")) {
    r.Fail(*r.Get("switch_branch"), "switch_branch",
           "= true is invalid with a [trace] table: valid false (the branch that leaves a bifurcation leaves it on "
           "one side, continuation.direction; a trace can start from a point of that run)");
  }
  r.RejectUnknown();
}

void ReadStart(const toml::table& start, const toml::table& root, std::string_view path, RunFile* run) {
  TableReader s(start, "start.", path, run);
  s.String("preset", &run->preset);
  s.String("signature", &run->signature);
  s.Values("set", &run->set);
  s.Values("guess", &run->guess);
  if (const toml::table* restart = s.Table("restart", false)) ReadRestart(*restart, root, path, run);
  if (run->preset.empty() == run->signature.empty() && run->restart_run.empty()) {
    throw RunFileError(fmt::format("{}: key 'start.preset' or 'start.signature': give exactly one of them",
                                   Where(path, start)));
  }
  s.RejectUnknown();
}

void ReadUnknowns(const toml::table& unknowns, std::string_view path, RunFile* run) {
  TableReader u(unknowns, "unknowns.", path, run);
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
  if (range.size() != 2 || !(range[0] < range[1])) {
    c.Fail(*c.Get("range"), "range", "must be [min, max] with min < max");
  }
  run->range_min = range[0];
  run->range_max = range[1];
}

void ReadContinuationKeys(TableReader& c, std::string_view path, RunFile* run) {
  c.Number("ds", &run->ds);
  c.Number("ds_min", &run->ds_min);
  c.Number("ds_max", &run->ds_max);
  c.Integer("max_points", &run->max_points);
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
    TableReader o(*others, "continuation.user_values_of.", path, run);
    for (const auto& [name, value] : *others) {
      std::vector<double> values;
      o.Numbers(name.str(), &values);
      for (double v : values) run->user_values.emplace_back(std::string(name.str()), v);
    }
  }
}

void CheckBounds(TableReader& c, bool trace, const RunFile& run) {
  if (c.Get("max_amplitude") && !(run.max_amplitude > 0.0 && std::isfinite(run.max_amplitude))) {
    c.Fail(*c.Get("max_amplitude"), "max_amplitude",
           fmt::format("= {} is invalid: valid a finite max_amplitude > 0", run.max_amplitude));
  }
  if (c.Get("resonance_approach") && !(run.resonance_approach >= 0.0 && run.resonance_approach < 1.0)) {
    c.Fail(*c.Get("resonance_approach"), "resonance_approach",
           fmt::format("= {} is invalid: valid 0 <= resonance_approach < 1 (0: never)", run.resonance_approach));
  }
  if (trace && c.Get("max_amplitude")) {
    c.Fail(*c.Get("max_amplitude"), "max_amplitude",
           "is invalid with a [trace] table: valid left out (a trace's bound is trace.max_amplitude)");
  }
}

void CheckSteps(TableReader& c, const toml::table& continuation, std::string_view path, const RunFile& run) {
  auto check_positive = [&](std::string_view key, double v) {
    if (!(v > 0.0)) c.Fail(*c.Get(key), key, fmt::format("= {} is invalid: valid range > 0", v));
  };
  if (c.Get("ds")) check_positive("ds", run.ds);
  if (c.Get("ds_min")) check_positive("ds_min", run.ds_min);
  if (c.Get("ds_max")) check_positive("ds_max", run.ds_max);
  if (!(run.ds_min <= run.ds && run.ds <= run.ds_max)) {
    throw RunFileError(fmt::format("{}: keys 'continuation.ds_min' <= 'continuation.ds' <= 'continuation.ds_max' "
                                   "must hold: got {} <= {} <= {}", Where(path, continuation), run.ds_min, run.ds, run.ds_max));
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
  TableReader c(continuation, "continuation.", path, run);
  ReadParameterAndRange(c, trace, run);
  ReadContinuationKeys(c, path, run);
  CheckBounds(c, trace, *run);
  CheckSteps(c, continuation, path, *run);
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
  TableReader t(trace, "trace.", path, run);
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
  TableReader top(root, "", path, &run);
  top.String("output", &run.output, true);
  if (!IsRunName(run.output)) {
    top.Fail(*top.Get("output"), "output", fmt::format("= '{}' is invalid: valid {}", run.output, kRunNameRule));
  }
  ReadStart(*top.Table("start", true), root, path, &run);
  if (const toml::table* unknowns = top.Table("unknowns", false)) ReadUnknowns(*unknowns, path, &run);
  const toml::table* continuation = top.Table("continuation", true);
  const toml::table* trace = top.Table("trace", false);
  ReadContinuation(*continuation, trace != nullptr, path, &run);
  if (trace != nullptr) run.trace = ReadTrace(*trace, path, &run);
  top.RejectUnknown();
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
