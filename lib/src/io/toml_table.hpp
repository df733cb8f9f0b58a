// The io layer's TOML reading, shared by the run file (run_file.cpp) and its [model] table
// (model_table.cpp): toml++ compiled header-only with its asserts neutralised, the screen that
// keeps from it what it mishandles, and the reader that checks each key of a table. Debian's
// toml++ 3.3.0 aborts on some malformed input through its internal asserts, and with NDEBUG turns
// them into optimiser assumptions (undefined behaviour); here they are no-ops, and the input is
// screened before parsing. Include it first (its translation units skip the precompiled headers),
// and only from lib/src/io.
#pragma once

#ifdef NDEBUG
#undef NDEBUG
#endif
#define TOML_HEADER_ONLY 1
#define TOML_ASSERT(expr) static_cast<void>(0)
#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "stickslip/io/run_file.hpp"

namespace stickslip::toml_reading {

// The document in `content` (a run file's text), screened first. Throws RunFileError
// "<path>:<line>:<column>: <what>".
toml::table ParseToml(std::string_view content, std::string_view path);

// A number node's value. toml++'s value<double>() is empty for an integer that a double cannot
// hold exactly (beyond 2^53), so integers are converted here, to the nearest double.
inline double NumberValue(const toml::node& node) {
  if (const auto* integer = node.as_integer()) return static_cast<double>(integer->get());
  return node.as_floating_point()->get();
}

inline std::string Where(std::string_view path, const toml::node& node) {
  const toml::source_position p = node.source().begin;
  return fmt::format("{}:{}:{}", path, p.line, p.column);
}

// Reads the keys of one table, checking each is known and of the right type.
class TableReader {
 public:
  TableReader(const toml::table& table, std::string prefix, std::string_view path,
              std::map<std::string, std::string>* locations)
      : table_(table), prefix_(std::move(prefix)), path_(path), locations_(locations) {}

  const toml::node* Get(std::string_view key) {
    known_.insert(std::string(key));
    const toml::node* node = table_.get(key);
    if (node) (*locations_)[prefix_ + std::string(key)] = Where(path_, *node);
    return node;
  }
  [[noreturn]] void Fail(const toml::node& node, std::string_view key, std::string_view what) const {
    throw RunFileError(fmt::format("{}: key '{}{}' {}", Where(path_, node), prefix_, key, what), prefix_ + std::string(key));
  }
  // A required key that is absent. The table's nearest key within two edits of it (and not read as
  // itself) is named as the likely misspelling; a valid key read after this one would be too, and
  // a question mark says so (no table's keys are that close to its required ones today).
  [[noreturn]] void Missing(std::string_view key, std::string_view what) const {
    std::vector<std::string> unread;
    for (const auto& [name, value] : table_) {
      if (!known_.count(std::string(name.str()))) unread.emplace_back(name.str());
    }
    const std::string written = Nearest(std::string(key), unread);
    const std::string hint =
        written.empty() ? ""
                        : fmt::format(" ('{}{}' at {}: a misspelling?)", prefix_, written, Where(path_, *table_.get(written)));
    throw RunFileError(fmt::format("{}: key '{}{}' is missing: {}{}", Where(path_, table_), prefix_, key, what, hint),
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
      const std::string suggestion = Nearest(name, known_);
      Fail(value, name, suggestion.empty() ? std::string("is unknown")
                                           : fmt::format("is unknown: did you mean '{}{}'?", prefix_, suggestion));
    }
  }

 private:
  // The one of `candidates` nearest to `name` within two edits (the first of equals), or "".
  template <typename Names>
  static std::string Nearest(const std::string& name, const Names& candidates) {
    std::string nearest;
    std::size_t best = 3;
    for (const std::string& candidate : candidates) {
      const std::size_t d = Distance(name, candidate);
      if (d < best) best = d, nearest = candidate;
    }
    return nearest;
  }
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
  std::map<std::string, std::string>* locations_;
  std::set<std::string> known_;
};

}  // namespace stickslip::toml_reading
