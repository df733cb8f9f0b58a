#include "stickslip/branches/orbit_monitor.hpp"

#include <algorithm>

#include <cmath>
#include <complex>

#include <fmt/format.h>

#include "stickslip/orbits/stability.hpp"

namespace stickslip {

std::string OrbitTypeChangeCode(const Margin& margin, Mode segment_mode) {
  switch (margin.kind) {
    case MarginKind::kDuration: return segment_mode == Mode::kStick ? "T0" : "S0";
    case MarginKind::kSlipVelocity:
    case MarginKind::kStopSlope: return "NS";
    case MarginKind::kStopForce: return "SK";
    case MarginKind::kFrictionLevel: return "EP";
    case MarginKind::kStickConstraint:
    case MarginKind::kExitSlope: break;
  }
  return "GR";
}

std::string orbit_columns::Multiplier(int k, const char* part) { return fmt::format("floquet:mu{}_{}", k, part); }

std::vector<double> ColumnValues(const std::vector<PointColumn>& columns, const BranchPoint& point) {
  std::vector<double> values;
  values.reserve(columns.size());
  for (const PointColumn& c : columns) values.push_back(c.monitored ? point.tests(c.index) : point.recorded(c.index));
  return values;
}

struct OrbitMonitor::Evaluated {
  std::vector<Margin> margins;
  OrbitStability stability;
  std::vector<double> measures;  // in column order, only where the recorded values are asked for
};

std::vector<std::string> orbit_columns::MeasureNames(const ModelDescription& model, int contact) {
  std::vector<std::string> names;
  for (const std::string& coordinate : model.coordinates) names.push_back(AmplitudeOf(coordinate));
  names.push_back("peak-to-peak:" + model.coordinates[contact]);
  for (const char* name : {kStickFraction, kStops, kSticks, kFrictionWork, kEquivalentDamping}) names.push_back(name);
  return names;
}

std::vector<double> orbit_columns::MeasureValues(const BasicOrbitMeasures& measures, int contact) {
  std::vector<double> values;
  for (const CoordinateRange& range : measures.coordinates) values.push_back(range.Amplitude());
  values.push_back(measures.coordinates[contact].PeakToPeak());
  for (double value : {measures.stick_fraction, static_cast<double>(measures.stops),
                       static_cast<double>(measures.sticks), measures.friction_work, measures.equivalent_damping}) {
    values.push_back(value);
  }
  return values;
}

void OrbitMonitor::AddTestFunction(TestFunctionInfo info, Value value) {
  if (Unwatched(info.name)) {
    AddRecorded(std::move(info.name), std::move(value));
    return;
  }
  if (const WatchedColumn* watched = Watched(info.name)) info.type = watched->type;
  columns_.push_back({info.name, true, static_cast<int>(info_.size())});
  info_.push_back(std::move(info));
  values_.push_back(std::move(value));
}

void OrbitMonitor::AddRecorded(std::string name, Value value) {
  if (const WatchedColumn* watched = Watched(name); watched && !Unwatched(name)) {
    AddTestFunction({.name = std::move(name), .type = watched->type, .may_have_poles = true}, std::move(value));
    return;
  }
  columns_.push_back({name, false, static_cast<int>(recorded_.size())});
  recorded_.push_back(std::move(name));
  values_.push_back(std::move(value));
}

bool OrbitMonitor::Unwatched(const std::string& column) const {
  return std::find(unwatched_.begin(), unwatched_.end(), column) != unwatched_.end();
}

const WatchedColumn* OrbitMonitor::Watched(const std::string& column) const {
  const auto w = std::find_if(watched_.begin(), watched_.end(), [&](const WatchedColumn& c) { return c.column == column; });
  return w == watched_.end() ? nullptr : &*w;
}

OrbitMonitor::OrbitMonitor(const OrbitProblem& problem, const Eigen::VectorXd& start,
                           std::vector<std::string> unwatched, std::vector<WatchedColumn> watched)
    : problem_(problem), unwatched_(std::move(unwatched)), watched_(std::move(watched)) {
  const std::vector<Margin> margins = problem.Margins(start);
  const Signature& signature = problem.signature();
  // The margins a curve's condition holds at zero (the unwatched ones) say nothing of whether its
  // orbits are motions: they are on the boundary by definition, at +-rounding.
  std::vector<bool> counted;
  for (const Margin& m : margins) counted.push_back(!Unwatched(std::string(orbit_columns::kMarginPrefix) + m.Name()));
  for (int k = 0; k < static_cast<int>(margins.size()); ++k) {
    const Margin& m = margins[k];
    const Mode mode = m.segment < 0 ? Mode::kStick : signature.segments()[m.segment];
    // u_s reaching zero ends the physical family (eq. 4), past type changes too.
    AddTestFunction({.name = std::string(orbit_columns::kMarginPrefix) + m.Name(),
                     .type = OrbitTypeChangeCode(m, mode),
                     .terminal = true,
                     .domain_boundary = m.kind == MarginKind::kFrictionLevel,
                     .may_have_poles = true,
                     .positive_side = "admissible"},
                    [k](const Evaluated& e) { return e.margins[k].value; });
  }
  for (int k = 0; k < problem.description().StateSize(); ++k) {
    AddRecorded(orbit_columns::Multiplier(k + 1, "re"),
                [k](const Evaluated& e) { return e.stability.multipliers[k].real(); });
    AddRecorded(orbit_columns::Multiplier(k + 1, "im"),
                [k](const Evaluated& e) { return e.stability.multipliers[k].imag(); });
  }
  AddRecorded(orbit_columns::kStable, [](const Evaluated& e) { return e.stability.stable ? 1.0 : 0.0; });
  AddRecorded(orbit_columns::kFoldTest, [](const Evaluated& e) { return e.stability.fold_test; });
  AddTestFunction({.name = orbit_columns::kFlipTest, .type = "PD", .may_have_poles = true},
                  [](const Evaluated& e) { return e.stability.flip_test; });
  AddTestFunction({.name = orbit_columns::kTorusTest, .type = "TR", .may_have_poles = true},
                  [](const Evaluated& e) { return e.stability.torus_test; });
  auto symmetry_test = [](const Evaluated& e) { return e.stability.symmetry_test; };
  if (signature.antisymmetric()) {
    AddTestFunction({.name = orbit_columns::kSymmetryTest, .type = "SB", .may_have_poles = true}, symmetry_test);
  } else {
    AddRecorded(orbit_columns::kSymmetryTest, symmetry_test);
  }
  AddRecorded(orbit_columns::kAdmissible, [counted](const Evaluated& e) {
    for (std::size_t k = 0; k < e.margins.size(); ++k) {
      const double value = e.margins[k].value;
      if (counted[k] && std::isfinite(value) && value <= 0.0) return 0.0;  // non-finite: not defined here
    }
    return 1.0;
  });
  const std::vector<std::string> measures = orbit_columns::MeasureNames(problem.description(), problem.ContactCoordinate());
  for (std::size_t k = 0; k < measures.size(); ++k) {
    AddRecorded(measures[k], [k](const Evaluated& e) { return e.measures[k]; });
  }
  for (const WatchedColumn& w : watched_) {
    if (!w.value) continue;
    AddTestFunction({.name = w.column, .type = w.type, .may_have_poles = true},
                    [value = w.value](const Evaluated& e) { return value(e.stability); });
  }
}

void OrbitMonitor::Evaluate(const Eigen::VectorXd& u, Eigen::VectorXd* tests, Eigen::VectorXd* recorded) const {
  const Evaluated evaluated{
      problem_.Margins(u), problem_.Stability(u),
      recorded ? orbit_columns::MeasureValues(problem_.Measures(u), problem_.ContactCoordinate()) : std::vector<double>{}};
  tests->resize(static_cast<int>(info_.size()));
  if (recorded) recorded->resize(static_cast<int>(recorded_.size()));
  for (std::size_t c = 0; c < columns_.size(); ++c) {
    const PointColumn& column = columns_[c];
    if (column.monitored) {
      (*tests)(column.index) = values_[c](evaluated);
    } else if (recorded) {
      (*recorded)(column.index) = values_[c](evaluated);
    }
  }
}

}  // namespace stickslip
