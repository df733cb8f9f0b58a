#include "stickslip/io/check.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include <fmt/format.h>

namespace stickslip {

namespace {

// Columns that make up the solution (the orbit's variables).
bool IsSolutionColumn(const std::string& c) {
  static const std::set<std::string> fixed = {"chi", "eta", "omega", "u_s", "u_r", "phi", "x10", "x20", "v10"};
  return fixed.count(c) || (c.size() > 1 && c[0] == 'd' && std::all_of(c.begin() + 1, c.end(), ::isdigit));
}

void CompareTables(const std::string& file, const CsvTable& stored, const CsvTable& fresh, bool labelled_only,
                   const std::string& parameter, const CheckTolerances& tol, std::vector<Difference>* out) {
  if (stored.header != fresh.header) {
    out->push_back({file, "header", "", fmt::format("{}", fmt::join(stored.header, ",")),
                    fmt::format("{}", fmt::join(fresh.header, ","))});
    return;
  }
  auto select = [&](const CsvTable& t) {
    std::vector<const std::vector<std::string>*> rows;
    for (const auto& r : t.rows) {
      if (r.size() == t.header.size() && (!labelled_only || !r[1].empty())) rows.push_back(&r);
    }
    return rows;
  };
  const auto a = select(stored);
  const auto b = select(fresh);
  if (a.size() != b.size()) {
    out->push_back({file, "rows", "count", std::to_string(a.size()), std::to_string(b.size())});
  }
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
    const auto& r = *a[i];
    const auto& s = *b[i];
    const std::string where = r[1].empty() ? fmt::format("row {}", i + 1) : r[1];
    for (std::size_t k = 0; k < r.size(); ++k) {
      const std::string& column = stored.header[k];
      if (column == "label" || column == "type" || column == "test_function") {
        if (r[k] != s[k]) out->push_back({file, where, column, r[k], s[k]});
        continue;
      }
      if (!IsSolutionColumn(column)) continue;
      const double x = std::stod(r[k]);
      const double y = std::stod(s[k]);
      const double limit = column == parameter ? tol.parameter_relative * std::max(std::abs(x), 1e-300)
                                               : tol.solution * std::max(1.0, std::abs(x));
      if (!(std::abs(x - y) <= limit)) out->push_back({file, where, column, r[k], s[k]});
    }
  }
}

}  // namespace

std::vector<Difference> CompareWithStored(const RunFiles& fresh, const std::filesystem::path& stored_dir,
                                          const std::string& parameter, const CheckTolerances& tolerances) {
  std::vector<Difference> differences;
  CompareTables("special-points.csv", ParseCsv(ReadTextFile(stored_dir / "special-points.csv")),
                ParseCsv(fresh.special_points_csv), false, parameter, tolerances, &differences);
  CompareTables("branch.csv", ParseCsv(ReadTextFile(stored_dir / "branch.csv")), ParseCsv(fresh.branch_csv), true,
                parameter, tolerances, &differences);
  return differences;
}

}  // namespace stickslip
