#include "stickslip/io/stored_run.hpp"

#include <algorithm>
#include <map>
#include <numbers>
#include <stdexcept>
#include <type_traits>

#include <fmt/format.h>

#include "stickslip/branches/orbit_continuation.hpp"
#include "stickslip/branches/orbit_monitor.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/model/linear_oscillator.hpp"
#include "stickslip/orbits/orbit_measures.hpp"
#include "stickslip/orbits/start_problem.hpp"
#include "stickslip/version.hpp"

namespace stickslip {

namespace ov = orbit_variables;

template <OscillatorModel Model>
NamedValues SolutionColumns(const Model& model, const BasicOrbit<Model>& orbit) {
  const OrbitLayout layout(model.Description(), orbit.signature.size());
  std::vector<int> order;
  for (int k = 0; k < model.Description().ParameterCount(); ++k) {
    // Without forcing its frequency plays no part (and StoredPeriod reads an orbit without it as autonomous).
    if (!(k == Model::kForcingFrequencyParameter && model.Autonomous())) order.push_back(layout.Parameter(k));
  }
  order.push_back(layout.Phi());
  for (int i = 0; i < layout.StartVariables(); ++i) order.push_back(i);
  for (int i = 0; i < orbit.signature.size(); ++i) order.push_back(layout.Duration(i));
  NamedValues columns;
  for (int index : order) columns.emplace_back(layout.Name(index), VariableOf(model, orbit, index));
  return columns;
}

NamedValues SolutionColumns(const Orbit& orbit) { return SolutionColumns(Pascal2014{}, orbit.OnModel()); }

double& Named(NamedValues& values, std::string_view name) {
  for (auto& [n, value] : values) {
    if (n == name) return value;
  }
  throw std::out_of_range(fmt::format("no value named '{}'", name));
}

double Named(const NamedValues& values, std::string_view name) { return Named(const_cast<NamedValues&>(values), name); }

template <OscillatorModel Model>
BasicOrbit<Model> OrbitOf(const Model& model, const typename Model::Parameters& held, const StoredRun& run,
                          const StoredPoint& point) {
  const Signature signature = Signature::Parse(run.summary.signature);
  const OrbitLayout layout(model.Description(), signature.size());
  BasicOrbit<Model> orbit{signature, held, Model::State::Zero(model.StateSize()), 0.0,
                          std::vector<double>(signature.size())};
  for (int index = 0; index < layout.Count(); ++index) {
    // An autonomous model's forcing frequency is no column (SolutionColumns): held.
    if (index == layout.Parameter(Model::kForcingFrequencyParameter) && model.Autonomous()) continue;
    const std::string name = layout.Name(index);
    const auto listed = std::find_if(point.solution.begin(), point.solution.end(), [&](const auto& v) { return v.first == name; });
    if (listed == point.solution.end()) {
      std::vector<std::string> variables;
      for (const auto& column : SolutionColumns(model, orbit)) variables.push_back(column.first);
      throw InvalidInput::WithMessage(
          "run", fmt::format("'{}' has no column '{}': valid a run of this model (its variables {})", run.summary.output,
                             name, fmt::join(variables, ", ")));
    }
    const double value = listed->second;
    if (index < layout.StartVariables()) {
      orbit.start(index) = value;
    } else if (index == layout.Phi()) {
      orbit.phi = value;
    } else if (index < layout.Parameter(0)) {
      orbit.durations[index - layout.Duration(0)] = value;
    } else {
      Model::ParameterAt(orbit.parameters, index - layout.Parameter(0)) = value;
    }
  }
  // The contact's velocity at the origin, no variable: the surface's (periodicity_equations.hpp).
  orbit.start(model.StateSize() - 1) = RestVelocity<Model>(orbit.parameters, 0.0);
  return orbit;
}

std::vector<std::string> StartStateNames(const NamedValues& solution) {
  std::vector<std::string> names;
  const auto phi = std::find_if(solution.begin(), solution.end(), [](const auto& v) { return v.first == "phi"; });
  for (auto v = phi + (phi != solution.end()); v != solution.end() && v->first != "d1"; ++v) names.push_back(v->first);
  return names;
}

double StoredPeriod(const Signature& signature, const StoredPoint& point) {
  for (const auto& [name, value] : point.solution) {
    if (name == "omega") return signature.period_multiple() * 2.0 * std::numbers::pi / value;
  }
  double listed = 0.0;
  for (int i = 0; i < signature.size(); ++i) listed += Named(point.solution, fmt::format("d{}", i + 1));
  return listed / signature.CoveredFraction();
}

Orbit OrbitOf(const StoredRun& run, const StoredPoint& point) {
  if (!run.summary.model.empty()) {
    throw InvalidInput::WithMessage(
        "model", fmt::format("'{}' is a run of a {} (a run file's [model]): valid here a run of the paper's oscillator",
                             run.summary.output, run.summary.model));
  }
  const Signature signature = Signature::Parse(run.summary.signature);
  const int n = signature.size();
  Eigen::VectorXd variables(ov::Count(n));
  for (int i = 0; i < ov::Count(n); ++i) variables(i) = Named(point.solution, ov::Name(n, i));
  return ov::Unpack(signature, variables);
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
template <OscillatorModel Model>
StoredPoint StoreZeroLengthSegments(const Model& model, OrbitOfModel<Model> orbit, StoredPoint point) {
  bool changed = false;
  const double period = PeriodOf(model, AsBasicOrbit(orbit));
  for (std::size_t i = 0; i < orbit.durations.size(); ++i) {
    const double d = ZeroLengthToRounding(orbit.durations[i], period);
    if (d == orbit.durations[i]) continue;
    orbit.durations[i] = d;
    changed = true;
    for (auto& [name, value] : point.margins) {
      if (name == fmt::format("duration:{}", i + 1)) value = d;
    }
  }
  if (!changed) return point;
  point.solution = SolutionColumns(model, AsBasicOrbit(orbit));
  const int contact = ContactCoordinate(model);
  const std::vector<double> measures = orbit_columns::MeasureValues(Measure(model, AsBasicOrbit(orbit)), contact);
  for (std::size_t k = 0; k < measures.size(); ++k) point.measures[k].second = measures[k];
  return point;
}

}  // namespace

template <OscillatorModel Model>
StoredRun RecordRun(const Model& model, const StoredSummary& identity, const BasicOrbitBranch<Model>& b) {
  const std::vector<std::string> measure_names = orbit_columns::MeasureNames(model.Description(), ContactCoordinate(model));
  // The monitor's columns by name: its margins, then what it records of the stability and the
  // orbit's measures.
  auto record = [&](int i, std::string label) {
    const BranchPoint& p = b.branch.points[i];
    StoredPoint point{.pt = i + 1, .label = std::move(label), .solution = SolutionColumns(model, AsBasicOrbit(b.orbits[i]))};
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
    for (const std::string& name : measure_names) point.measures.emplace_back(name, recorded.at(name));
    point.newton_iterations = p.newton_iterations;
    point.step_size = p.ds;
    return StoreZeroLengthSegments(model, b.orbits[i], std::move(point));
  };

  StoredRun stored;
  stored.summary = identity;
  stored.summary.model = std::is_same_v<Model, Pascal2014> ? "" : kLinearOscillatorModel;
  stored.summary.units = model.Description().units;
  stored.summary.stickslip_version = Version();
  stored.summary.signature = b.orbits.front().signature.ToString();
  stored.summary.shooting = ToString(b.shooting);
  stored.summary.termination = ToString(b.branch.end);
  stored.summary.message = b.branch.end_message;
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

StoredRun RecordRun(const RunFile& run, const OrbitBranch& branch) {
  return RecordRun(Pascal2014{}, StoredSummary{.run_file = run.path, .output = run.output, .parameter = run.parameter},
                   branch);
}

template NamedValues SolutionColumns(const Pascal2014&, const BasicOrbit<Pascal2014>&);
template NamedValues SolutionColumns(const DynamicLinearOscillator&, const BasicOrbit<DynamicLinearOscillator>&);
template BasicOrbit<Pascal2014> OrbitOf(const Pascal2014&, const Pascal2014::Parameters&, const StoredRun&,
                                        const StoredPoint&);
template BasicOrbit<DynamicLinearOscillator> OrbitOf(const DynamicLinearOscillator&,
                                                     const DynamicLinearOscillator::Parameters&, const StoredRun&,
                                                     const StoredPoint&);
template StoredRun RecordRun(const Pascal2014&, const StoredSummary&, const BasicOrbitBranch<Pascal2014>&);
template StoredRun RecordRun(const DynamicLinearOscillator&, const StoredSummary&, const BasicOrbitBranch<DynamicLinearOscillator>&);

}  // namespace stickslip
