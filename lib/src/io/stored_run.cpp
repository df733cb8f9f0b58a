#include "stickslip/io/stored_run.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <type_traits>

#include <fmt/format.h>

#include "stickslip/branches/orbit_continuation.hpp"
#include "stickslip/orbits/start_problem.hpp"
#include "stickslip/version.hpp"

namespace stickslip {

namespace ov = orbit_variables;

NamedValues SolutionColumns(const Orbit& orbit) {
  const int n = orbit.signature.size();
  const Eigen::VectorXd variables = ov::Pack(orbit);
  std::vector<int> order;
  for (ParameterId id : kAllParameters) order.push_back(ov::Parameter(n, id));
  order.insert(order.end(), {ov::kPhi, ov::kX10, ov::kX20, ov::kV10});
  for (int i = 0; i < n; ++i) order.push_back(ov::Duration(i));
  NamedValues columns;
  for (int index : order) columns.emplace_back(ov::Name(n, index), variables(index));
  return columns;
}

std::vector<std::string> PointLabels(const Branch& branch) {
  std::vector<std::string> labels(branch.points.size());
  int counter = 0;
  for (std::size_t i = 0; i < branch.points.size(); ++i) {
    if (!branch.points[i].label.empty()) labels[i] = fmt::format("{}{}", branch.points[i].label, ++counter);
  }
  return labels;
}

std::vector<std::string> SpecialPointLabels(const Branch& branch) {
  const std::vector<std::string> labels = PointLabels(branch);
  int counter = static_cast<int>(std::count_if(labels.begin(), labels.end(), [](const std::string& l) { return !l.empty(); }));
  std::vector<bool> taken(branch.points.size(), false);
  std::vector<std::string> special;
  for (const SpecialPoint& s : branch.special_points) {
    std::string label = labels[s.point];
    if (label.empty() || taken[s.point]) label = fmt::format("{}{}", s.type, ++counter);
    taken[s.point] = true;
    special.push_back(std::move(label));
  }
  return special;
}

namespace {

// The point as stored: a duration at rounding level below zero is the zero-length segment it
// stands for (start_problem.hpp, ZeroLengthToRounding), so no stored duration is negative but one
// past a change of type. Its margin duration:i, d_i itself, follows; so do the measures, which a
// row holds of its own stored orbit.
void StoreZeroLengthSegments(StoredPoint* point) {
  Orbit& orbit = point->orbit;
  bool changed = false;
  for (std::size_t i = 0; i < orbit.durations.size(); ++i) {
    const double d = ZeroLengthToRounding(orbit.durations[i], orbit.Period());
    if (d == orbit.durations[i]) continue;
    orbit.durations[i] = d;
    changed = true;
    for (auto& [name, value] : point->margins) {
      if (name == fmt::format("duration:{}", i + 1)) value = d;
    }
  }
  if (changed) point->measures = Measure(orbit);
}

}  // namespace

StoredRun RecordRun(const RunFile& run, const OrbitBranch& b) {
  // The monitor's columns by name: its margins, then what it records of the stability and the
  // orbit's measures.
  auto record = [&](int i, std::string label) {
    const BranchPoint& p = b.branch.points[i];
    StoredPoint point{.pt = i + 1, .label = std::move(label), .orbit = b.orbits[i]};
    std::map<std::string, double> recorded;
    const std::vector<double> values = ColumnValues(b.columns, p);
    for (std::size_t k = 0; k < b.columns.size(); ++k) {
      const std::string& name = b.columns[k].name;
      if (name.starts_with(orbit_columns::kMarginPrefix)) {
        point.margins.emplace_back(name.substr(orbit_columns::kMarginPrefix.size()), values[k]);
      } else {
        recorded[name] = values[k];
      }
    }
    for (int k = 1; recorded.count(orbit_columns::Multiplier(k, "re")) != 0; ++k) {
      point.multipliers.emplace_back(recorded.at(orbit_columns::Multiplier(k, "re")),
                                     recorded.at(orbit_columns::Multiplier(k, "im")));
    }
    point.stable = recorded.at(orbit_columns::kStable) != 0.0;
    point.fold_test = recorded.at(orbit_columns::kFoldTest);
    point.flip_test = recorded.at(orbit_columns::kFlipTest);
    point.torus_test = recorded.at(orbit_columns::kTorusTest);
    point.symmetry_test = recorded.at(orbit_columns::kSymmetryTest);
    point.admissible = recorded.at(orbit_columns::kAdmissible) != 0.0;
    orbit_columns::ForEachMeasure(point.measures, [&](const char* name, auto& field) {
      field = static_cast<std::remove_reference_t<decltype(field)>>(recorded.at(name));
    });
    point.newton_iterations = p.newton_iterations;
    point.step_size = p.ds;
    StoreZeroLengthSegments(&point);
    return point;
  };

  StoredRun stored;
  stored.summary = {run.path, Version(), run.output, b.orbits.front().signature.ToString(), run.parameter,
                    ToString(b.shooting), ToString(b.branch.end), b.branch.end_message};
  const std::vector<std::string> labels = PointLabels(b.branch);
  for (std::size_t i = 0; i < b.branch.points.size(); ++i) stored.branch.push_back(record(static_cast<int>(i), labels[i]));
  // Every special point has a label of its own (SpecialPointLabels).
  const std::vector<std::string> special = SpecialPointLabels(b.branch);
  for (std::size_t k = 0; k < special.size(); ++k) {
    const SpecialPoint& s = b.branch.special_points[k];
    stored.special_points.push_back({record(s.point, special[k]), s.type, s.test_function, s.located});
  }
  return stored;
}

}  // namespace stickslip
