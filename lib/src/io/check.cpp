#include "stickslip/io/check.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <string_view>
#include <utility>
#include <set>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace stickslip {

namespace {

// Columns that make up the solution (the orbit's variables).
bool IsSolutionColumn(const std::string& c) {
  static const std::set<std::string> fixed = {"chi", "eta", "omega", "u_s", "u_r", "phi", "x10", "x20", "v10"};
  return fixed.count(c) || (c.size() > 1 && c[0] == 'd' && std::all_of(c.begin() + 1, c.end(), ::isdigit));
}

bool StartsWith(const std::string& text, std::string_view prefix) { return text.rfind(prefix, 0) == 0; }

// The Floquet multipliers of a row, in the file's order (the eigensolver's).
std::vector<std::complex<double>> Multipliers(const std::vector<std::string>& header, const std::vector<std::string>& row) {
  std::vector<std::complex<double>> mu;
  for (std::size_t k = 0; k + 1 < header.size(); ++k) {
    if (StartsWith(header[k], "floquet:mu") && header[k].ends_with("_re")) {
      mu.emplace_back(std::stod(row[k]), std::stod(row[k + 1]));
    }
  }
  return mu;
}

// Two NaNs agree: a value that could not be computed in both runs is no difference.
double Distance(std::complex<double> a, std::complex<double> b) {
  const bool nan_a = std::isnan(a.real()) || std::isnan(a.imag());
  const bool nan_b = std::isnan(b.real()) || std::isnan(b.imag());
  if (nan_a || nan_b) return nan_a && nan_b ? 0.0 : std::numeric_limits<double>::infinity();
  return std::abs(a - b);
}

// `fresh` reordered so that each multiplier of `stored` faces the nearest one not yet taken:
// the eigensolver's order need not survive a change of build, and sorting would pair the wrong
// members of a conjugate pair whose real parts differ by rounding.
std::vector<std::complex<double>> Matched(const std::vector<std::complex<double>>& stored,
                                          std::vector<std::complex<double>> fresh) {
  std::vector<std::complex<double>> matched;
  for (std::complex<double> m : stored) {
    if (fresh.empty()) break;
    const auto nearest = std::min_element(fresh.begin(), fresh.end(),
                                          [&](auto a, auto b) { return Distance(m, a) < Distance(m, b); });
    matched.push_back(*nearest);
    fresh.erase(nearest);
  }
  return matched;
}

// A flag is compared only where the stored row is clearly on one side of its boundary: at a
// grazing or a fold the flag of the located point itself is decided by rounding.
bool MarginsClearOfZero(const std::vector<std::string>& header, const std::vector<std::string>& row, double clearance) {
  for (std::size_t k = 0; k < header.size(); ++k) {
    if (StartsWith(header[k], "margin:") && !(std::abs(std::stod(row[k])) > clearance)) return false;
  }
  return true;
}
bool MultipliersClearOfUnitCircle(const std::vector<std::complex<double>>& mu, double clearance) {
  return std::all_of(mu.begin(), mu.end(), [&](auto m) { return std::abs(std::abs(m) - 1.0) > clearance; });
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
  const std::vector<std::string>& header = stored.header;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
    const auto& r = *a[i];
    const auto& s = *b[i];
    const std::string where = r[1].empty() ? fmt::format("row {}", i + 1) : r[1];
    const std::vector<std::complex<double>> mu = Multipliers(header, r);
    const std::vector<std::complex<double>> fresh_mu = Matched(mu, Multipliers(header, s));
    for (std::size_t k = 0; k < mu.size(); ++k) {
      if (!(Distance(mu[k], fresh_mu[k]) <= tol.multiplier * std::max(1.0, std::abs(mu[k])))) {
        auto text = [](std::complex<double> m) { return fmt::format("{}{:+}i", m.real(), m.imag()); };
        out->push_back({file, where, fmt::format("multiplier {}", k + 1), text(mu[k]), text(fresh_mu[k])});
      }
    }
    for (std::size_t k = 0; k < r.size(); ++k) {
      const std::string& column = header[k];
      const bool compared_exactly =
          column == "label" || column == "type" || column == "test_function" || column == "located" ||
          (column == "admissible" && MarginsClearOfZero(header, r, tol.flag_clearance)) ||
          (column == "stable" && MultipliersClearOfUnitCircle(mu, tol.flag_clearance));
      if (compared_exactly) {
        if (r[k] != s[k]) out->push_back({file, where, column, r[k], s[k]});
        continue;
      }
      if (!IsSolutionColumn(column)) continue;
      const double x = std::stod(r[k]);
      const double y = std::stod(s[k]);
      const double limit = column == parameter ? tol.parameter_relative * std::max(std::abs(x), 1e-300)
                                               : tol.solution * std::max(1.0, std::abs(x));
      if (!(Distance(x, y) <= limit)) out->push_back({file, where, column, r[k], s[k]});
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
