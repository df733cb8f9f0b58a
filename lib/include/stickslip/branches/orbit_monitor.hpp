// What the continuation engine watches and records along a branch of periodic orbits.
//
// Monitored (test functions, whose sign changes are special points): the admissibility margins
// (orbits/margins.hpp), terminal, whose sign change is a change of orbit type:
//   GR  a stick constraint G or G1 grazing zero inside a stick (G:i, G1:i), or born at the stick
//       exit (exit-slope:i)
//   T0  a stick phase shrinking to zero (duration:i of a stick)
//   S0  a slip phase shrinking to zero (duration:i of a slip)
//   NS  x2' touching zero inside a slip (velocity:i), or at its end (stop-slope:i): a new stop
//   SK  the force condition at a stop crossing its threshold (reversal:i, stick-entry:i,
//       abnormal-stop:i)
//   EP  the sliding friction level u_s reaching zero: the end of the physical family
// and det(M + I) (PD, a multiplier through -1), the torus test (TR, a complex pair on the unit
// circle) and, for an antisymmetric orbit, det(H + I) (SB, a multiplier -1 of the half-period map
// with the mirror: a symmetry-breaking pitchfork, orbits/stability.hpp). All may jump through a pole rather than pass through zero: the saltation
// matrices blow up where an event becomes tangent, and a margin jumps where an interior minimum
// appears or leaves (to or from +inf).
//
// Recorded with each point: the Floquet multipliers, whether the orbit is stable, det(M - I)
// (zero at a fold), whether it is admissible (every defined margin positive, but those a curve's
// condition holds at zero, the unwatched ones) and the orbit's
// measures (orbits/orbit_measures.hpp: amplitudes, peak-to-peak, stick fraction, stops, sticks).
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "stickslip/continuation/continuation.hpp"
#include "stickslip/orbits/margins.hpp"
#include "stickslip/orbits/orbit_measures.hpp"
#include "stickslip/orbits/orbit_problem.hpp"
#include "stickslip/orbits/stability.hpp"

namespace stickslip {

// The names of an orbit branch's per-point columns, stated once for the monitor, the stored
// record (io/stored_run.hpp) and the result files' reader and writer.
namespace orbit_columns {
inline constexpr std::string_view kMarginPrefix = "margin:";  // then Margin::Name()
inline constexpr const char* kStable = "stable";
inline constexpr const char* kFoldTest = "floquet:det(M-I)";
inline constexpr const char* kFlipTest = "floquet:det(M+I)";
inline constexpr const char* kTorusTest = "floquet:torus";
// det(H + I) of an antisymmetric orbit (orbits/stability.hpp): a test function there (SB), nan
// for the others.
inline constexpr const char* kSymmetryTest = "floquet:det(H+I)";
inline constexpr const char* kAdmissible = "admissible";
// "floquet:mu<k>_re" or "_im", k from 1.
std::string Multiplier(int k, const char* part);
// The orbit's measures (orbits/orbit_measures.hpp), after `admissible`.
inline constexpr const char* kAmplitudeX1 = "amplitude:x1";
inline constexpr const char* kAmplitudeX2 = "amplitude:x2";
inline constexpr const char* kPeakToPeakX2 = "peak-to-peak:x2";
inline constexpr const char* kStickFraction = "stick-fraction";
inline constexpr const char* kStops = "stops";
inline constexpr const char* kSticks = "sticks";
inline constexpr const char* kFrictionWork = "friction-work";
inline constexpr const char* kEquivalentDamping = "equivalent-damping";
// Calls visit(name, field) for each measure in column order, with `measures` an OrbitMeasures,
// const or not: the field is a double&, or an int& for the counts (stops, sticks). The one list of
// which column holds which measure, for the monitor, the result files and the front ends.
template <typename Measures, typename Visit>
void ForEachMeasure(Measures& measures, Visit&& visit) {
  visit(kAmplitudeX1, measures.amplitude_x1);
  visit(kAmplitudeX2, measures.amplitude_x2);
  visit(kPeakToPeakX2, measures.peak_to_peak_x2);
  visit(kStickFraction, measures.stick_fraction);
  visit(kStops, measures.stops);
  visit(kSticks, measures.sticks);
  visit(kFrictionWork, measures.friction_work);
  visit(kEquivalentDamping, measures.equivalent_damping);
}
// The amplitude column of a model's coordinate: "amplitude:x1".
inline std::string AmplitudeOf(std::string_view coordinate) { return "amplitude:" + std::string(coordinate); }
// The measure columns of a model's orbits: the amplitude of each coordinate, the peak-to-peak of
// the one the contact holds (`contact`), then the stick fraction, stops, sticks, friction work and
// equivalent damping; for the paper's model ForEachMeasure's names, and their values.
std::vector<std::string> MeasureNames(const ModelDescription& model, int contact);
std::vector<double> MeasureValues(const BasicOrbitMeasures& measures, int contact);
// The measures added after the first result files: a file written before them lacks their
// columns, and its readers take them as nan.
inline bool AddedLater(std::string_view measure) { return measure == kFrictionWork || measure == kEquivalentDamping; }
}  // namespace orbit_columns

// The special-point code of a margin's sign change.
std::string OrbitTypeChangeCode(const Margin& margin, Mode segment_mode);

// One per-point column of an orbit branch, as the result files have it.
struct PointColumn {
  std::string name;        // e.g. "margin:G:3", "floquet:mu1_re", "admissible"
  bool monitored = false;  // a test function (BranchPoint::tests), else a recorded value
  int index = 0;           // in BranchPoint::tests or BranchPoint::recorded
};
// The columns' values at a branch point.
std::vector<double> ColumnValues(const std::vector<PointColumn>& columns, const BranchPoint& point);

// A column watched with a type of its own: along a curve in two parameters (branches/
// boundary_curve.hpp) a sign change of another Floquet test is a codimension-two point (LPPD, ...).
struct WatchedColumn {
  std::string column;  // "floquet:det(M-I)", ...: watched even where it is otherwise recorded only
  std::string type;    // the special-point code of its sign change
  // A column of its own, after the others, where given (the monitor has no such column).
  std::function<double(const OrbitStability&)> value;
};

class OrbitMonitor final : public Monitor {
 public:
  // An orbit problem of any model (orbits/orbit_problem.hpp); `start` any unknowns of it (the
  // names depend on the signature only). The test functions named in `unwatched` (column names:
  // "margin:G:2", "floquet:torus") are recorded, not watched (those that sit on zero or mean
  // nothing along a type boundary: branches/margin_condition.hpp). Those in `watched` are test
  // functions of the type given there.
  OrbitMonitor(const OrbitProblem& problem, const Eigen::VectorXd& start, std::vector<std::string> unwatched = {},
               std::vector<WatchedColumn> watched = {});
  std::vector<TestFunctionInfo> TestFunctions() const override { return info_; }
  std::vector<std::string> RecordedNames() const override { return recorded_; }
  void Evaluate(const Eigen::VectorXd& u, Eigen::VectorXd* tests, Eigen::VectorXd* recorded) const override;
  // Every column, monitored and recorded, in the order of the result files: the margins, the
  // multipliers, stable, det(M - I), det(M + I), the torus test, admissible, the measures.
  const std::vector<PointColumn>& Columns() const { return columns_; }

 private:
  struct Evaluated;  // what the columns are computed from, at one point
  using Value = std::function<double(const Evaluated&)>;
  // Each adds the next column.
  void AddTestFunction(TestFunctionInfo info, Value value);
  void AddRecorded(std::string name, Value value);
  bool Unwatched(const std::string& column) const;
  const WatchedColumn* Watched(const std::string& column) const;  // null if not watched with a type of its own

  const OrbitProblem& problem_;
  std::vector<std::string> unwatched_;
  std::vector<WatchedColumn> watched_;
  std::vector<TestFunctionInfo> info_;
  std::vector<std::string> recorded_;
  std::vector<PointColumn> columns_;
  std::vector<Value> values_;  // one per column
};

}  // namespace stickslip
