#include "toml_table.hpp"

namespace stickslip::toml_reading {

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

}  // namespace

toml::table ParseToml(std::string_view content, std::string_view path) {
  Screen(content, path);
  try {
    return toml::parse(content, path);
  } catch (const toml::parse_error& e) {
    const auto& p = e.source().begin;
    throw RunFileError(fmt::format("{}:{}:{}: {}", path, p.line, p.column, e.description()));
  }
}

}  // namespace stickslip::toml_reading
