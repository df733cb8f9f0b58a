#include "stickslip/io/check.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <utility>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "stickslip/branches/orbit_monitor.hpp"
#include "stickslip/io/result_files.hpp"

namespace stickslip {

namespace {

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

// A flag is compared only where the stored point is clearly on one side of its boundary: at a
// grazing or a fold the flag of the located point itself is decided by rounding.
bool MarginsClearOfZero(const StoredPoint& p, double clearance) {
  return std::all_of(p.margins.begin(), p.margins.end(), [&](const auto& m) { return std::abs(m.second) > clearance; });
}
bool MultipliersClearOfUnitCircle(const std::vector<std::complex<double>>& mu, double clearance) {
  return std::all_of(mu.begin(), mu.end(), [&](auto m) { return std::abs(std::abs(m) - 1.0) > clearance; });
}

std::string Text(double v) { return fmt::format("{}", v); }
std::string Text(bool flag) { return flag ? "1" : "0"; }

// Appends the differences of one point, `where` naming it (its label, or "row N").
// `absent`: the measures the stored files lack (StoredRun::absent_measures), not compared.
void ComparePoints(const std::string& file, const std::string& where, const StoredPoint& r, const StoredPoint& s,
                   const std::string& parameter, const CheckTolerances& tol, const std::vector<std::string>& absent,
                   std::vector<Difference>* out) {
  const std::vector<std::complex<double>> fresh_mu = Matched(r.multipliers, s.multipliers);
  for (std::size_t k = 0; k < fresh_mu.size(); ++k) {
    const std::complex<double> mu = r.multipliers[k];
    if (!(Distance(mu, fresh_mu[k]) <= tol.multiplier * std::max(1.0, std::abs(mu)))) {
      auto text = [](std::complex<double> m) { return fmt::format("{}{:+}i", m.real(), m.imag()); };
      out->push_back({file, where, fmt::format("multiplier {}", k + 1), text(mu), text(fresh_mu[k])});
    }
  }
  if (r.label != s.label) out->push_back({file, where, "label", r.label, s.label});
  for (std::size_t k = 0; k < r.solution.size(); ++k) {
    const auto& [column, x] = r.solution[k];
    const double y = s.solution[k].second;
    const double limit = column == parameter ? tol.parameter_relative * std::max(std::abs(x), 1e-300)
                                             : tol.solution * std::max(1.0, std::abs(x));
    if (!(Distance(x, y) <= limit)) out->push_back({file, where, column, Text(x), Text(y)});
  }
  // The measures follow from the solution: to the same tolerance, the counts exactly.
  for (std::size_t k = 0; k < r.measures.size(); ++k) {
    const auto& [column, x] = r.measures[k];
    const double y = s.measures[k].second;
    if (std::find(absent.begin(), absent.end(), column) != absent.end()) continue;
    if (!(Distance(x, y) <= tol.solution * std::max(1.0, std::abs(x)))) out->push_back({file, where, column, Text(x), Text(y)});
  }
  if (MultipliersClearOfUnitCircle(r.multipliers, tol.flag_clearance) && r.stable != s.stable) {
    out->push_back({file, where, "stable", Text(r.stable), Text(s.stable)});
  }
  if (MarginsClearOfZero(r, tol.flag_clearance) && r.admissible != s.admissible) {
    out->push_back({file, where, "admissible", Text(r.admissible), Text(s.admissible)});
  }
}

std::vector<const StoredPoint*> Labelled(const std::vector<StoredPoint>& branch) {
  std::vector<const StoredPoint*> labelled;
  for (const StoredPoint& p : branch) {
    if (!p.label.empty()) labelled.push_back(&p);
  }
  return labelled;
}

}  // namespace

std::vector<Difference> CompareWithStored(const StoredRun& fresh, const StoredRun& stored,
                                          const CheckTolerances& tolerances) {
  const std::string special_file = "special-points.csv";
  const std::string branch_file = "branch.csv";
  std::vector<Difference> out;
  const std::vector<std::string> stored_header = ColumnNames(stored.branch.front());
  const std::vector<std::string> fresh_header = ColumnNames(fresh.branch.front());
  if (stored_header != fresh_header) {
    for (const std::string& file : {special_file, branch_file}) {
      out.push_back({file, "header", "", fmt::format("{}", fmt::join(stored_header, ",")),
                     fmt::format("{}", fmt::join(fresh_header, ","))});
    }
    return out;
  }
  const std::string& parameter = fresh.summary.parameter;
  auto count = [&](const std::string& file, std::size_t a, std::size_t b) {
    if (a != b) out.push_back({file, "rows", "count", std::to_string(a), std::to_string(b)});
    return std::min(a, b);
  };

  // Special points in order, all of them.
  for (std::size_t i = 0; i < count(special_file, stored.special_points.size(), fresh.special_points.size()); ++i) {
    const StoredSpecialPoint& r = stored.special_points[i];
    const StoredSpecialPoint& s = fresh.special_points[i];
    const std::string where = r.point.label.empty() ? fmt::format("row {}", i + 1) : r.point.label;
    ComparePoints(special_file, where, r.point, s.point, parameter, tolerances, stored.absent_measures, &out);
    if (r.type != s.type) out.push_back({special_file, where, "type", r.type, s.type});
    if (r.test_function != s.test_function) {
      out.push_back({special_file, where, "test_function", r.test_function, s.test_function});
    }
    if (r.located != s.located) out.push_back({special_file, where, "located", Text(r.located), Text(s.located)});
  }
  // The labelled branch points in order.
  const std::vector<const StoredPoint*> a = Labelled(stored.branch);
  const std::vector<const StoredPoint*> b = Labelled(fresh.branch);
  for (std::size_t i = 0; i < count(branch_file, a.size(), b.size()); ++i) {
    ComparePoints(branch_file, a[i]->label, *a[i], *b[i], parameter, tolerances, stored.absent_measures, &out);
  }
  return out;
}

}  // namespace stickslip
