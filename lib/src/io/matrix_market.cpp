#include "stickslip/io/matrix_market.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"

namespace stickslip {
namespace {

constexpr long long kLargestExactInteger = 1LL << 53;  // every integer up to it is a double
constexpr Eigen::Index kMostDimension = 100000;         // what any limits may allow
constexpr long long kMostEntries = 10000000;            // of the dense matrix: 80 MB

struct Line {
  int number = 0;  // 1-based
  std::vector<std::string_view> tokens;
};

std::vector<std::string_view> Tokens(std::string_view line) {
  std::vector<std::string_view> tokens;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    if (i > start) tokens.push_back(line.substr(start, i - start));
  }
  return tokens;
}

// A token as messages show it: at most 40 characters of it. Appended to, not string(...) + "...",
// where g++ 12 warns falsely (-Warray-bounds).
std::string Shown(std::string_view token) {
  std::string shown(token.substr(0, 40));
  if (token.size() > 40) shown += "...";
  return shown;
}

class Reader {
 public:
  Reader(const std::string& field, const std::string& source) : field_(field), source_(source) {}

  [[noreturn]] void Refuse(int line, const std::string& what, const std::string& valid) const {
    const std::string where = line > 0 ? fmt::format("line {}: ", line) : "";
    throw InvalidInput::WithMessage(
        field_, fmt::format("{} = '{}' is invalid: {}{}: valid {}", field_, source_, where, what, valid));
  }
  long long Integer(const Line& line, std::string_view token, long long lo, long long hi, const char* what) const {
    long long value = 0;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (error != std::errc() || end != token.data() + token.size() || value < lo || value > hi) {
      Refuse(line.number, fmt::format("{} '{}'", what, Shown(token)), fmt::format("an integer {} ... {}", lo, hi));
    }
    return value;
  }
  double Value(const Line& line, std::string_view token, bool integer) const {
    if (integer) return static_cast<double>(Integer(line, token, -kLargestExactInteger, kLargestExactInteger, "the value"));
    double value = 0.0;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (error != std::errc() || end != token.data() + token.size() || !std::isfinite(value)) {
      Refuse(line.number, fmt::format("the value '{}'", Shown(token)), "a finite number");
    }
    return value;
  }

 private:
  const std::string& field_;
  const std::string& source_;
};

std::string Lower(std::string_view s) {
  std::string lower(s);
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return lower;
}

struct Header {
  bool coordinate = true, symmetric = false, integer = false;
};

Header ParseBanner(const Reader& reader, std::string_view first) {
  const std::vector<std::string_view> t = Tokens(first);
  if (t.empty() || Lower(t[0]) != "%%matrixmarket") reader.Refuse(1, "no '%%MatrixMarket' banner", "a Matrix Market file");
  if (t.size() != 5) {
    reader.Refuse(1, fmt::format("a banner of {} words", t.size()), "%%MatrixMarket matrix <format> <field> <symmetry>");
  }
  if (Lower(t[1]) != "matrix") reader.Refuse(1, "the object " + Shown(t[1]), "matrix");
  const std::string format = Lower(t[2]), field = Lower(t[3]), symmetry = Lower(t[4]);
  if (format != "coordinate" && format != "array") reader.Refuse(1, "the format " + Shown(format), "coordinate or array");
  if (field != "real" && field != "double" && field != "integer") {
    reader.Refuse(1, "the field " + Shown(field), "real, double or integer");
  }
  if (symmetry != "general" && symmetry != "symmetric") reader.Refuse(1, "the symmetry " + Shown(symmetry), "general or symmetric");
  return {format == "coordinate", symmetry == "symmetric", field == "integer"};
}

// Places the entries of `data` lines (after the size line) into m.
void ReadCoordinates(const Reader& reader, const Header& header, const std::vector<Line>& data, Eigen::MatrixXd& m) {
  std::set<std::pair<Eigen::Index, Eigen::Index>> seen;
  for (const Line& line : data) {
    if (line.tokens.size() != 3) reader.Refuse(line.number, fmt::format("{} fields", line.tokens.size()), "3: row column value");
    const Eigen::Index i = reader.Integer(line, line.tokens[0], 1, m.rows(), "the row") - 1;
    const Eigen::Index j = reader.Integer(line, line.tokens[1], 1, m.cols(), "the column") - 1;
    const double value = reader.Value(line, line.tokens[2], header.integer);
    if (header.symmetric && i < j) {
      reader.Refuse(line.number, fmt::format("the entry ({}, {}) above the diagonal", i + 1, j + 1),
                    "the lower triangle only in a symmetric file");
    }
    if (!seen.insert({i, j}).second) reader.Refuse(line.number, fmt::format("the entry ({}, {}) again", i + 1, j + 1), "each entry once");
    m(i, j) = value;
    if (header.symmetric) m(j, i) = value;
  }
}

void ReadArray(const Reader& reader, const Header& header, const std::vector<Line>& data, Eigen::MatrixXd& m) {
  std::size_t k = 0;
  for (Eigen::Index j = 0; j < m.cols(); ++j) {
    for (Eigen::Index i = header.symmetric ? j : 0; i < m.rows(); ++i, ++k) {
      const Line& line = data[k];
      if (line.tokens.size() != 1) reader.Refuse(line.number, fmt::format("{} fields", line.tokens.size()), "1 value per line");
      m(i, j) = reader.Value(line, line.tokens[0], header.integer);
      if (header.symmetric) m(j, i) = m(i, j);
    }
  }
}

// The text's lines one by one, blank ones skipped; memory stays that of the lines kept.
class LineCursor {
 public:
  explicit LineCursor(std::string_view text) : text_(text) {}
  std::optional<Line> Next() {
    while (start_ <= text_.size()) {
      const std::size_t end = std::min(text_.find('\n', start_), text_.size());
      Line line{++number_, Tokens(text_.substr(start_, end - start_))};
      start_ = end + 1;
      if (!line.tokens.empty()) return line;
    }
    return std::nullopt;
  }

 private:
  std::string_view text_;
  std::size_t start_ = 0;
  int number_ = 0;
};

// The lines after the size line: exactly `expected` of them, no comments among them.
std::vector<Line> DataLines(const Reader& reader, LineCursor& cursor, long long expected) {
  std::vector<Line> data;
  while (std::optional<Line> line = cursor.Next()) {
    if (line->tokens[0].starts_with("%")) reader.Refuse(line->number, "a comment after the size line", "comments before it");
    if (static_cast<long long>(data.size()) == expected) {
      reader.Refuse(line->number, "more entries than the header's " + std::to_string(expected), "exactly that many");
    }
    data.push_back(*line);
  }
  if (static_cast<long long>(data.size()) < expected) {
    reader.Refuse(0, fmt::format("truncated: {} of the header's {} entries", data.size(), expected), "all of them");
  }
  return data;
}

}  // namespace

Eigen::MatrixXd ParseMatrixMarket(std::string_view text, const std::string& field, const std::string& source,
                                  const MatrixMarketLimits& limits) {
  const Reader reader(field, source);
  if (text.size() > limits.max_bytes) {
    reader.Refuse(0, fmt::format("{} bytes", text.size()), fmt::format("at most {} bytes", limits.max_bytes));
  }
  if (limits.max_dimension < 1 || limits.max_dimension > kMostDimension) {
    throw InvalidInput("max_dimension", static_cast<double>(limits.max_dimension), fmt::format("1 ... {}", kMostDimension));
  }
  LineCursor cursor(text);
  const std::size_t first_end = std::min(text.find('\n'), text.size());
  const Header header = ParseBanner(reader, text.substr(0, first_end));
  cursor.Next();  // the banner
  // Comments before the size line.
  std::optional<Line> size = cursor.Next();
  while (size && size->tokens[0].starts_with("%")) size = cursor.Next();
  if (!size) reader.Refuse(0, "no size line", "a line with the rows, columns (and entries)");
  if (size->tokens.size() != (header.coordinate ? 3u : 2u)) {
    reader.Refuse(size->number, fmt::format("{} fields on the size line", size->tokens.size()),
                  header.coordinate ? "3: rows columns entries" : "2: rows columns");
  }
  const Eigen::Index rows = reader.Integer(*size, size->tokens[0], 1, limits.max_dimension, "the row count");
  const Eigen::Index cols = reader.Integer(*size, size->tokens[1], 1, limits.max_dimension, "the column count");
  if (header.symmetric && rows != cols) reader.Refuse(size->number, fmt::format("{}x{}", rows, cols), "a square matrix in a symmetric file");
  if (static_cast<long long>(rows) * cols > kMostEntries) {
    reader.Refuse(size->number, fmt::format("{}x{}", rows, cols), fmt::format("at most {} entries", kMostEntries));
  }
  const long long stored = header.symmetric ? rows * (rows + 1) / 2 : rows * cols;
  const long long expected = header.coordinate ? reader.Integer(*size, size->tokens[2], 0, stored, "the entry count") : stored;
  const std::vector<Line> data = DataLines(reader, cursor, expected);
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(rows, cols);
  if (header.coordinate) {
    ReadCoordinates(reader, header, data, m);
  } else {
    ReadArray(reader, header, data, m);
  }
  return m;
}

Eigen::MatrixXd ReadMatrixMarket(const std::filesystem::path& file, const std::string& field, const MatrixMarketLimits& limits) {
  const std::string source = file.string();
  const Reader reader(field, source);
  std::error_code error;
  const std::uintmax_t bytes = std::filesystem::file_size(file, error);
  if (error) reader.Refuse(0, fmt::format("cannot be read ({})", error.message()), "a readable file");
  if (bytes > limits.max_bytes) reader.Refuse(0, fmt::format("{} bytes", bytes), fmt::format("at most {} bytes", limits.max_bytes));
  // At most one byte past the limit, should the file grow after its size was taken.
  std::ifstream in(file, std::ios::binary);
  std::string text(static_cast<std::size_t>(bytes) + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  if (in.bad()) reader.Refuse(0, "cannot be read", "a readable file");
  text.resize(static_cast<std::size_t>(in.gcount()));
  return ParseMatrixMarket(text, field, source, limits);
}

}  // namespace stickslip
