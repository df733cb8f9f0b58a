// The start of every computation on an orbit or a motion, assembled in one place from what a
// user gives: a paper preset or an orbit type, a labelled point of earlier results, model data,
// guesses and the choice of unknowns. Run files (io/run.hpp MakeSetup), the command line's
// solve, continue, simulate and sweep, and the Python bindings build their start here, so the
// same input gives the same start whichever way it arrives.
//
// Values are applied in this order, later ones winning: the preset's printed values, the
// restart point, set, guess, the values given with fix; then u_r = u_s when tied.
//
// Bad input throws InvalidInput. Its field is the StartInput member at fault ("preset",
// "signature", "restart", "set", "guess", "free", "fix", "paper_choice", "parameter", and
// "unknowns" for a choice that is not square) or the variable whose value is out of range ("u_r",
// "d2"), and the message starts with that field, so that a front end can name it its own way
// (InvalidInput::Renamed, Predicate). Nothing is printed.
//
//   StartInput input;
//   input.preset = "paper-5.2";
//   input.fix = {{"phi", std::numbers::pi / 2}};
//   input.free = {"u_r"};
//   const StartProblem start = BuildStartProblem(input);
//   const OrbitSolution s = SolveOrbit(start.orbit, start.free, start.unknowns.tie_static_friction);
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "stickslip/model/pascal_2014/flows.hpp"
#include "stickslip/model/pascal_2014/parameters.hpp"
#include "stickslip/named_values.hpp"
#include "stickslip/orbits/orbit.hpp"
#include "stickslip/orbits/orbit_solver.hpp"

namespace stickslip {

// A key of `set`: the model data and the start state, with the same meaning everywhere.
struct SetKey {
  std::string_view key;
  std::string_view meaning;
  std::string_view valid_range;
};
// chi, eta, omega, u_s, u_r, x10, x20, v10, v20, phi.
std::span<const SetKey> SetKeys();
// The valid range of a set key as messages print it ("0.01 <= chi <= 0.99"); "any finite number" for a
// name that is not a set key.
std::string_view SetKeyRange(std::string_view key);

// A labelled point of earlier results, as the io layer reads it (io/start_input.hpp): its orbit
// type and its columns by name; columns that name no orbit variable are ignored.
struct RestartPoint {
  std::string run;    // where it came from: results/<run>/, point <label>
  std::string label;
  std::string signature;
  NamedValues values;
  // What a restart that leaves the point's branch needs: the special point's type (LP, PD, SK, ...)
  // and test function ("margin:reversal:1"), for the branch leaving a PD or an SB and for the curve
  // of a change of type in two parameters.
  std::string type;
  std::string test_function;
};

// A variable held fixed: at its start value, or at `value`.
struct FixedVariable {
  std::string name;
  std::optional<double> value;
};

struct StartInput {
  std::string preset;     // a paper preset (PaperExampleNames), or empty
  std::string signature;  // an orbit type in text form (signature.hpp), or empty
  std::optional<RestartPoint> restart;
  NamedValues set;    // model data and start state: the keys of SetKeys()
  NamedValues guess;  // any orbit variable: x10 x20 v10 phi d1..dn chi eta omega u_s u_r
  std::vector<std::string> free;   // released variables
  std::vector<FixedVariable> fix;  // held variables; a later fix wins over an earlier free
  bool tie_u_r = false;            // u_r = u_s (abnormal stops need it, eq. 25)
  bool paper_choice = false;       // with a preset: the paper's own choice of unknowns
  std::optional<std::string> parameter;  // the continued variable; none for one orbit
};

// A start orbit and its unknowns: square at a fixed `parameter`.
struct StartProblem {
  Orbit orbit;
  UnknownChoice unknowns;
  std::vector<int> free;         // FreeIndices(orbit.signature, unknowns)
  std::optional<int> parameter;  // index of the continued variable, when one was given
};

// The rounding level of an orbit's durations, relative to its period T, stated once. A solved or
// located orbit has its durations to rounding: a zero-length segment (where a branch changes
// type) comes out as a few 1e-16 T of either sign (-4.7e-15 of T = 20.3, 2.3e-16 T, at a located
// T0 of results/paper-4.2-omega-trace/branch-3), the one segment of a one-segment orbit as T plus
// rounding. The start builder accepts such values, the result files' reader too, and storage
// (io/stored_run.hpp RecordRun) writes a negative one as the zero-length segment it stands for.
inline constexpr double kDurationRounding = 1e-12;
// Whether `d` is a duration of an orbit of period `period`: 0 <= d <= period, to kDurationRounding.
bool IsDurationOfPeriod(double d, double period);
// `d` with a rounding-level negative value (-kDurationRounding period <= d < 0) made 0; any other
// value as it is (a duration past a change of type, with continue_past_type_changes, stays).
double ZeroLengthToRounding(double d, double period);

// Needs exactly one orbit type: from the preset, the signature or the restart point (a
// signature or restart point beside a preset must agree with it). Every parameter must be
// given and valid (u_s <= 0 is refused as the end of the physical family), every duration given
// and within the period (IsDurationOfPeriod: a zero-length segment is where a branch switches
// type; a rounding-level negative one is taken as 0) but a restart point's own, which is taken as
// its run stored it (past a change of type, with continue_past_type_changes, a segment's length
// may be negative), v20 = 0 (an orbit starts at a stop). Throws InvalidInput.
StartProblem BuildStartProblem(const StartInput& input);

// The unknowns BuildStartProblem chooses: the preset's (its paper choice with paper_choice), then
// free, fix and tie_u_r. Reads no values. Throws InvalidInput (an unknown preset, a variable both
// free and fixed).
UnknownChoice StartUnknowns(const StartInput& input);

// The model data, initial state (x10, x20, x1'0, x2'0) and forcing phase a simulation starts
// from.
struct ModelStart {
  Parameters parameters;
  State initial_state = State::Zero();
  double phi = 0.0;
};

// From at most one of the preset and the restart point, and set; every parameter given and
// valid (Validate). The orbit members of `input` must be empty. Throws InvalidInput.
ModelStart BuildModelStart(const StartInput& input);

}  // namespace stickslip
