// Internal to io/: a CSV file read for typed access by the result-file reader. Every failure is an
// InvalidInput naming the file, the line and the column, so that a damaged or hand-edited file
// gives one line on the command line rather than a crash.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "column_kinds.hpp"
#include "stickslip/invalid_input.hpp"

namespace stickslip::detail {

class CsvTable {
 public:
  // Header on the first line, then one row per non-empty line; fields split at ',' (stickslip's
  // files need no quoting). Throws InvalidInput if the header is missing or a row has more or
  // fewer fields than the header.
  CsvTable(std::string_view text, std::filesystem::path file);

  const std::vector<std::string>& header() const { return header_; }
  int rows() const { return static_cast<int>(rows_.size()); }
  // The index of `name` in the header; throws InvalidInput if it is missing.
  int Column(std::string_view name) const;
  // The index of `name`, or -1.
  int Find(std::string_view name) const;

  const std::string& Text(int row, int column) const { return rows_[row].fields[column]; }
  // Number, one of the column kind's valid values (column_kinds.hpp): the one check of every
  // numeric column of a kind, "<file>:<line>: column '<name>' = '<text>' is invalid: valid ...".
  double Value(int row, int column, const ValidValues& valid) const;
  int Integer(int row, int column) const;
  // Integer, min <= value <= max.
  int Integer(int row, int column, int min, int max) const;
  bool Flag(int row, int column) const;  // "1" or "0"

  // "<file>:<line>: column '<name>' = '<text>' <what>".
  InvalidInput Error(int row, int column, std::string_view what) const;
  // "<file>:<line>: <what>", for a row as a whole (line 1 is the header).
  InvalidInput Error(int row, std::string_view what) const;
  InvalidInput HeaderError(std::string_view what) const;

 private:
  // The whole field as a double in the form fmt writes ("0.5", "1e-08", "inf", "-inf", "nan"); a
  // reader takes it as Value, checked by its kind.
  double Number(int row, int column) const;

  struct Row {
    int line = 0;  // 1-based line in the file
    std::vector<std::string> fields;
  };
  std::filesystem::path file_;
  std::vector<std::string> header_;
  std::vector<Row> rows_;
};

}  // namespace stickslip::detail
