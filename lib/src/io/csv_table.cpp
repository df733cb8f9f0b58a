#include "csv_table.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

#include <fmt/format.h>

namespace stickslip::detail {

namespace {

std::vector<std::string> Split(std::string_view line) {
  std::vector<std::string> fields;
  std::size_t begin = 0;
  while (true) {
    const std::size_t comma = line.find(',', begin);
    fields.emplace_back(line.substr(begin, comma - begin));
    if (comma == std::string_view::npos) return fields;
    begin = comma + 1;
  }
}

// The whole text as a T; fmt writes doubles in a form from_chars reads back exactly.
template <typename T>
bool ParseWhole(const std::string& text, T* value) {
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), *value);
  return !text.empty() && error == std::errc() && end == text.data() + text.size();
}

}  // namespace

CsvTable::CsvTable(std::string_view text, std::filesystem::path file) : file_(std::move(file)) {
  int line = 0;
  std::size_t begin = 0;
  while (begin < text.size()) {
    std::size_t end = text.find('\n', begin);
    if (end == std::string_view::npos) end = text.size();
    std::string_view content = text.substr(begin, end - begin);
    if (content.ends_with('\r')) content.remove_suffix(1);  // a file saved with CRLF endings
    begin = end + 1;
    ++line;
    if (line == 1) {
      header_ = Split(content);
      continue;
    }
    if (content.empty()) continue;
    rows_.push_back({line, Split(content)});
    const Row& row = rows_.back();
    if (row.fields.size() != header_.size()) {
      throw Error(rows() - 1, fmt::format("the row has {} fields, the header {}: valid one field per column",
                                          row.fields.size(), header_.size()));
    }
  }
  if (line == 0) throw HeaderError("the header line is missing: valid a CSV file with a header");
}

int CsvTable::Find(std::string_view name) const {
  const auto it = std::find(header_.begin(), header_.end(), name);
  return it == header_.end() ? -1 : static_cast<int>(it - header_.begin());
}

int CsvTable::Column(std::string_view name) const {
  const int column = Find(name);
  if (column < 0) throw HeaderError(fmt::format("column '{}' is missing", name));
  return column;
}

double CsvTable::Number(int row, int column) const {
  double value = 0.0;
  if (!ParseWhole(Text(row, column), &value)) throw Error(row, column, "is not a number");
  return value;
}

double CsvTable::Value(int row, int column, const ValidValues& valid) const {
  const double value = Number(row, column);
  if (valid.Holds(value)) return value;
  const bool finite_only = !valid.inf && !valid.nan;
  if (finite_only && !std::isfinite(value)) throw Error(row, column, fmt::format("is not a finite number: valid {}", valid.text));
  throw Error(row, column, fmt::format("is invalid: valid {}", valid.text));
}

int CsvTable::Integer(int row, int column, int min, int max) const {
  const int value = Integer(row, column);
  if (value < min || value > max) {
    throw Error(row, column, max == std::numeric_limits<int>::max() ? fmt::format("is invalid: valid an integer >= {}", min)
                                                                   : fmt::format("is invalid: valid {} to {}", min, max));
  }
  return value;
}

int CsvTable::Integer(int row, int column) const {
  int value = 0;
  if (!ParseWhole(Text(row, column), &value)) throw Error(row, column, "is not an integer");
  return value;
}

bool CsvTable::Flag(int row, int column) const {
  const std::string& text = Text(row, column);
  if (text != "0" && text != "1") throw Error(row, column, "is invalid: valid 0 or 1");
  return text == "1";
}

InvalidInput CsvTable::Error(int row, int column, std::string_view what) const {
  // A field of a damaged file may be megabytes long: the message shows its start and its length.
  constexpr std::size_t kShown = 80;
  const std::string& text = Text(row, column);
  const std::string shown =
      text.size() <= kShown ? text : fmt::format("{}...' ({} characters", text.substr(0, kShown), text.size());
  return InvalidInput::WithMessage(
      header_[column], fmt::format("{}:{}: column '{}' = '{}{} {}", file_.string(), rows_[row].line, header_[column],
                                   shown, text.size() <= kShown ? "'" : ")", what));
}

InvalidInput CsvTable::Error(int row, std::string_view what) const {
  return InvalidInput::WithMessage(file_.string(), fmt::format("{}:{}: {}", file_.string(), rows_[row].line, what));
}

InvalidInput CsvTable::HeaderError(std::string_view what) const {
  return InvalidInput::WithMessage(file_.string(), fmt::format("{}:1: {}", file_.string(), what));
}

}  // namespace stickslip::detail
