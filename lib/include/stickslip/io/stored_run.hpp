// A continuation run as its result files store it (result_files.hpp reads and writes them): what
// each row of branch.csv and special-points.csv means, and what summary.json says. Plain values,
// so that a later run, `check` and the AUTO export use the stored branch without parsing text.
// Any model's run: the orbit's variables and measures are columns by name (the model is erased
// here, at the boundary of io, as Ceres erases a functor to a CostFunction); OrbitOf gives the
// paper's Orbit back.
//
//   StoredRun run = ReadRunFiles("results/paper-5.1-omega-up");
//   for (const StoredPoint& p : run.branch) if (!p.label.empty()) use(OrbitOf(run, p), p.multipliers);
#pragma once

#include <complex>
#include <string>
#include <utility>
#include <vector>

#include "stickslip/io/run_file.hpp"
#include "stickslip/named_values.hpp"
#include "stickslip/orbits/orbit.hpp"

namespace stickslip {

template <OscillatorModel Model>
struct BasicOrbitBranch;
using OrbitBranch = BasicOrbitBranch<Pascal2014>;

// One branch point, one CSV row. The columns are, in this order: pt, label, the orbit's
// variables (SolutionColumns), margin:<name> per margin, floquet:mu<k>_re and _im per multiplier,
// stable, floquet:det(M-I), floquet:det(M+I), floquet:torus, floquet:det(H+I), admissible, the measures
// (orbit_columns::MeasureNames: for the paper's model amplitude:x1, amplitude:x2, peak-to-peak:x2,
// stick-fraction, stops, sticks, friction-work, equivalent-damping), newton_iterations, step_size.
struct StoredPoint {
  int pt = 0;                  // 1-based position on the branch
  std::string label;           // AUTO-style type and running number ("LP2"); empty if regular
  NamedValues solution{};      // the orbit's variables by column name (SolutionColumns); its signature is the run's
  NamedValues margins{};       // (Margin::Name(), value); > 0 is admissible, inf where undefined
  std::vector<std::complex<double>> multipliers{};  // Floquet multipliers, in the eigensolver's order
  bool stable = false;         // every |multiplier| < 1
  double fold_test = 0.0;      // det(M - I)
  double flip_test = 0.0;      // det(M + I)
  double torus_test = 0.0;     // prod_{i<j} (mu_i mu_j - 1)
  double symmetry_test = 0.0;  // det(H + I) of an antisymmetric orbit; nan for the others
  bool admissible = true;      // every terminal margin positive
  NamedValues measures{};      // by column name: amplitudes, peak-to-peak, stick fraction, stops and sticks per period, ...
  int newton_iterations = 0;
  double step_size = 0.0;      // the step that reached it (0 at the start and at located points)
};

// One row of special-points.csv: the point's row, then type, test_function and located.
struct StoredSpecialPoint {
  StoredPoint point;           // its label, unique in the run: the point's, or a number of its own for a second special point there (the end at a located LP3 is EP4)
  std::string type;            // "LP", "BP", "UZ", "EP", "TR", "PD" or an orbit-type change code
  std::string test_function;   // which function changed sign, or why the branch ended
  bool located = true;         // false if the corrector failed inside the bracket
};

// summary.json, apart from the counts of points and special points by type, which the writer
// derives from the tables and the reader checks against them.
struct StoredSummary {
  // The run file the run was made from ("(command line)" for one made by flags); for a [model]'s
  // run the file holding its [model], which its restarts and exports read the model from.
  std::string run_file;
  std::string stickslip_version;
  std::string output;       // the run's folder under the results root
  std::string signature;    // Signature::ToString of the orbits
  std::string parameter;    // the continued variable (one of SolutionColumns' names)
  std::string shooting;     // "single" or "multiple"
  // The oscillator: "" for the paper's (summary.json then has no "model" key, as before models
  // existed), kLinearOscillatorModel for a run file's [model].
  std::string model;
  ModelUnits units;         // a [model]'s (SI in its runs made before they could be declared); empty
                            // for the paper's (scaled)
  std::string termination;  // why the branch ended: "max-points", "terminal-event", ...
  std::string message;
};

struct StoredRun {
  StoredSummary summary;
  std::vector<StoredPoint> branch;
  std::vector<StoredSpecialPoint> special_points;
  // The measure columns the files lack, written before those measures existed
  // (orbit_columns::AddedLater): read as nan, and not compared by `check`.
  std::vector<std::string> absent_measures;
};

// StoredSummary::model of a run file's [model] (model/linear_oscillator.hpp).
inline constexpr const char* kLinearOscillatorModel = "linear-oscillator";

// The orbit's variables as the files name and order them: the model's parameters (but the forcing
// frequency of an autonomous model, which plays no part), phi, its start state, d1..dn (for the
// paper's: chi, eta, omega, u_s, u_r, phi, x10, x20, v10, d1..dn).
template <OscillatorModel Model>
NamedValues SolutionColumns(const Model& model, const BasicOrbit<Model>& orbit);
NamedValues SolutionColumns(const Orbit& orbit);

// The value named `name` in `values` (a point's solution, margins or measures). Throws
// std::out_of_range naming it when there is none.
double& Named(NamedValues& values, std::string_view name);
double Named(const NamedValues& values, std::string_view name);

// The start state's names among a point's solution columns (SolutionColumns): those between phi
// and d1 (x10, x20, v10 for the paper's model; m1_0, ..., v_m1_0, ... for a [model]).
std::vector<std::string> StartStateNames(const NamedValues& solution);

// The time after which a stored point's orbit of `signature` repeats: its forcing periods where
// the model has a forcing frequency (the variable "omega", as Orbit::Period), else, for an
// autonomous model, its durations over the part of the period they cover.
double StoredPeriod(const Signature& signature, const StoredPoint& point);

// The paper's orbit of a point of `run` (whose signature it has). Throws InvalidInput naming
// "model" for a run of another model, and std::out_of_range for a point without the paper's
// variables.
Orbit OrbitOf(const StoredRun& run, const StoredPoint& point);
// Any model's orbit of a point of `run` (SolutionColumns' inverse): each variable by its name, an
// autonomous model's forcing frequency (no column) from `held`. Throws InvalidInput naming "run"
// for a point without one of the model's other variables (a run of another model). Compiled for
// the paper's model and DynamicLinearOscillator.
template <OscillatorModel Model>
BasicOrbit<Model> OrbitOf(const Model& model, const typename Model::Parameters& held, const StoredRun& run,
                          const StoredPoint& point);

// The AUTO-style labels of a branch's points: the type and a running number in branch order
// ("LP4"), empty for a regular point.
std::vector<std::string> PointLabels(const Branch& branch);

// The labels of a branch's special points, in order, as special-points.csv has them: the first at
// a point takes the point's label, a second one there (the branch's end at a located point: LP3,
// then the end's EP) the next number (EP4), so that no two share a label.
std::vector<std::string> SpecialPointLabels(const Branch& branch);

// The stored form of a branch just computed from `run`: the one place that reads the
// continuation engine's Branch, so that a change there changes only this function, and the one
// place where every run, trace branch and map curve is stored: a duration at rounding level below
// zero is stored as the zero-length segment it is, 0 (start_problem.hpp, kDurationRounding), with
// its margin duration:i and the row's measures taken of that orbit.
StoredRun RecordRun(const RunFile& run, const OrbitBranch& branch);
// Any model's: `identity` gives the summary's run_file, output and parameter; its model is the
// type's ("" for the paper's, kLinearOscillatorModel for any other).
// Compiled for the paper's model and DynamicLinearOscillator.
template <OscillatorModel Model>
StoredRun RecordRun(const Model& model, const StoredSummary& identity, const BasicOrbitBranch<Model>& branch);

}  // namespace stickslip
