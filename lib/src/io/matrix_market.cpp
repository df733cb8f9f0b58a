#include "stickslip/io/matrix_market.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"

namespace stickslip {
namespace {

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
      Refuse(line.number, fmt::format("{} '{}'", what, token), fmt::format("an integer {} ... {}", lo, hi));
    }
    return value;
  }
  double Value(const Line& line, std::string_view token, bool integer) const {
    double value = 0.0;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (error != std::errc() || end != token.data() + token.size() || !std::isfinite(value) ||
        (integer && value != std::trunc(value))) {
      Refuse(line.number, fmt::format("the value '{}'", token), integer ? "a finite integer" : "a finite number");
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
  if (t.size() != 5 || Lower(t[0]) != "%%matrixmarket" || Lower(t[1]) != "matrix") {
    reader.Refuse(1, "no '%%MatrixMarket matrix' banner", "a Matrix Market file");
  }
  const std::string format = Lower(t[2]), field = Lower(t[3]), symmetry = Lower(t[4]);
  if (format != "coordinate" && format != "array") reader.Refuse(1, "the format " + format, "coordinate or array");
  if (field != "real" && field != "double" && field != "integer") {
    reader.Refuse(1, "the field " + field, "real, double or integer");
  }
  if (symmetry != "general" && symmetry != "symmetric") reader.Refuse(1, "the symmetry " + symmetry, "general or symmetric");
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

// The non-blank lines from `first` on: exactly `expected` of them, no comments among them.
std::vector<Line> DataLines(const Reader& reader, const std::vector<Line>& lines, std::size_t first, long long expected) {
  std::vector<Line> data;
  for (std::size_t k = first; k < lines.size(); ++k) {
    if (lines[k].tokens.empty()) continue;
    if (lines[k].tokens[0].starts_with("%")) reader.Refuse(lines[k].number, "a comment after the size line", "comments before it");
    if (static_cast<long long>(data.size()) == expected) {
      reader.Refuse(lines[k].number, "more entries than the header's " + std::to_string(expected), "exactly that many");
    }
    data.push_back(lines[k]);
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
  std::vector<Line> lines;
  for (std::size_t start = 0, number = 1; start <= text.size(); ++number) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    lines.push_back({static_cast<int>(number), Tokens(text.substr(start, end - start))});
    start = end + 1;
  }
  const std::size_t first_end = std::min(text.find('\n'), text.size());
  const Header header = ParseBanner(reader, text.substr(0, first_end));
  // Comments and blank lines before the size line; blank lines only after it.
  std::size_t k = 1;
  while (k < lines.size() && (lines[k].tokens.empty() || lines[k].tokens[0].starts_with("%"))) ++k;
  if (k == lines.size()) reader.Refuse(0, "no size line", "a line with the rows, columns (and entries)");
  const Line& size = lines[k];
  if (size.tokens.size() != (header.coordinate ? 3u : 2u)) {
    reader.Refuse(size.number, fmt::format("{} fields on the size line", size.tokens.size()),
                  header.coordinate ? "3: rows columns entries" : "2: rows columns");
  }
  const Eigen::Index rows = reader.Integer(size, size.tokens[0], 1, limits.max_dimension, "the row count");
  const Eigen::Index cols = reader.Integer(size, size.tokens[1], 1, limits.max_dimension, "the column count");
  if (header.symmetric && rows != cols) reader.Refuse(size.number, fmt::format("{}x{}", rows, cols), "a square matrix in a symmetric file");
  const long long stored = header.symmetric ? rows * (rows + 1) / 2 : rows * cols;
  const long long expected = header.coordinate ? reader.Integer(size, size.tokens[2], 0, stored, "the entry count") : stored;
  const std::vector<Line> data = DataLines(reader, lines, k + 1, expected);
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
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in && !in.eof()) reader.Refuse(0, "cannot be read", "a readable file");
  return ParseMatrixMarket(text.str(), field, source, limits);
}

}  // namespace stickslip
