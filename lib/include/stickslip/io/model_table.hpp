// A user's own oscillator, as a run file's [model] table describes it: a linear oscillator with one
// Coulomb contact (model/linear_oscillator_data.hpp), written as a chain of masses, springs and
// dampers (model/chain.hpp) or as matrices in Matrix Market files (io/matrix_market.hpp, what
// finite-element codes export), with the values of its parameters. Every key is checked as the
// run file's are (run_file.hpp): unknown, missing or mistyped keys name the file, line and key.
//
//   [model]
//   kind = "chain"
//   masses = [1.0, 1.0, 1.0]                           # kg; named m1, m2, m3 (or names = [...])
//   springs = [{ between = ["m1", "ground"], k = 1.0 }, { between = ["m1", "m2"], k = 1.0 },
//              { between = ["m2", "m3"], k = 1.0 }]    # N/m
//   dampers = [{ between = ["m3", "ground"], c = 0.05 }]  # N s/m (optional)
//   forcing = { m1 = 1.0 }                             # N: the amplitude of cos(omega t + phi) (optional)
//   contact = "m3"                                     # the mass the Coulomb contact is on
//   friction_slope = 0.0                               # N s/m: a slip's kinetic level F_k + alpha |s| (optional)
//   parameters = { omega = 0.8, F_k = 0.3, F_s = 0.4, v_b = 0.0 }   # rad/s, N, N, m/s
//   start = { m3_0 = 0.5, phi = 0.3 }                  # m, m/s, rad: where the motion starts (optional: rest)
//   units = { length = "m", time = "s", force = "N" }  # optional, each: what the numbers are in
//                                                      # (labels of files and figures; SI by default)
//
//   [model]
//   kind = "matrices"                                  # files relative to the run file's folder
//   mass = "M.mtx"
//   stiffness = "K.mtx"
//   damping = "C.mtx"                                  # optional
//   forcing = "g.mtx"                                  # optional: an n x 1 matrix
//   coordinates = ["x1", "x2", "x3"]                   # optional: x1 ... xn
//   contact = "x3"
//   parameters = { omega = 0.8, F_k = 0.3, F_s = 0.4 }
//
// Parameters left out: v_b = 0 (a fixed surface); omega is needed where the model is forced.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "stickslip/model/chain.hpp"
#include "stickslip/model/linear_oscillator.hpp"
#include "stickslip/named_values.hpp"

namespace stickslip {

// Matrix Market files of a model of kind "matrices", as written in the run file.
struct ModelMatrixFiles {
  std::string mass;
  std::string stiffness;
  std::string damping;  // empty: none
  std::string forcing;  // empty: none
  std::vector<std::string> coordinates;  // empty: x1 ... xn
  std::string contact;  // a coordinate's name
};

struct ModelTable {
  std::string path;      // the run file
  std::string location;  // "path:line:column" of the [model] table
  // "path:line:column" of every key present, by its dotted name ("model.springs[2].k").
  std::map<std::string, std::string> locations;
  std::string kind;      // "chain" or "matrices"
  Chain chain;           // kind "chain"
  ModelMatrixFiles matrices;  // kind "matrices"
  double friction_slope = 0.0;
  ModelUnits units = SiUnits();
  NamedValues parameters;  // as written, in the file's order
  NamedValues start;       // as written: start-state components by name (x1_0, v1_0, ...) and phi
};

// The [model] table of the run file at `path` (the rest of the file is left to ParseRunFile).
// Throws RunFileError "<path>:<line>:<column>: key 'model.<key>' ..." on any problem of the table,
// and when there is none.
ModelTable ReadModelTable(const std::filesystem::path& path);
ModelTable ParseModelTable(std::string_view content, std::string_view path);

// The oscillator the table describes, its matrices read from files relative to the run file's
// folder. Throws RunFileError "<path>:<line>:<column>: ..." naming the key ("model.springs[2]",
// "model.stiffness") for what the model refuses: a mass that is not positive, a stiffness that is not
// positive definite, files that are no Matrix Market matrices or do not fit together, ...
LinearOscillatorData ModelDataOf(const ModelTable& table);
DynamicLinearOscillator ModelOf(const ModelTable& table);  // of ModelDataOf

// Each parameter's value as the table gives it (nullopt where it does not), in the order of the
// model's description. Throws RunFileError for a name the model does not have.
std::vector<std::optional<double>> GivenParameters(const ModelDescription& description, const ModelTable& table);

// The parameters' values: the table's, then `set` over them (a command line's), each checked
// against the model's description; v_b = 0 where not given. Throws RunFileError naming
// "model.parameters.<name>" at its place in the file (InvalidInput naming the name, from `set`) for a name the model does not have (listing
// those it has), a missing F_k, F_s or, where forced, omega, and a value outside its range.
DynamicLinearOscillator::Parameters ParametersOf(const DynamicLinearOscillator& model, const ModelTable& table,
                                                 const NamedValues& set = {});

// The largest |value| of a start-state component or phase.
inline constexpr double kMaxModelStartValue = 1e9;

// Whether `name` is one of the start's: a state component's start name (ModelDescription::initial_state)
// or the forcing phase "phi".
bool IsStartName(const ModelDescription& description, std::string_view name);

// Where the motion starts: rest and phase 0, then the table's `start`, then `set`'s start entries
// (IsStartName; its other entries are ParametersOf's) over it. Throws RunFileError naming
// "model.start.<name>" at its place in the file, InvalidInput naming the name from `set`, for a name
// that is not the start's or a value beyond kMaxModelStartValue.
struct ModelStartState {
  Eigen::VectorXd state;
  double phi = 0.0;
};
ModelStartState StartOf(const DynamicLinearOscillator& model, const ModelTable& table, const NamedValues& set = {});

}  // namespace stickslip
