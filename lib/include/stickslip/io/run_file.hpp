// Run files: the declarative description of one continuation run, in TOML
// (continuation-scripts/*.toml). Every key is checked: unknown keys, missing keys and wrong
// types are errors naming the file, the line and the key.
//
//   output = "paper-5.1-omega-up"      # results/<output>/
//   [start]
//   preset = "paper-5.1"               # or signature = "slip- slip+ stick slip+"
//   set = { u_r = 0.5 }                # model data and start: chi eta omega u_s u_r x10 x20 v10 phi
//   guess = { d1 = 3.2 }               # any orbit variable
//   restart = { run = "paper-5.1-omega-up", label = "LP1" }   # start from a labelled point
//                                      # (switch_branch = true: the branch leaving a PD or SB;
//                                      #  boundary = "u_r": an SK or T0 boundary in two parameters)
//   [unknowns]
//   free = ["u_r"]                     # released variables
//   fix = ["phi"]                      # held variables
//   tie_u_r = false                    # u_r = u_s
//   [continuation]
//   parameter = "omega"
//   direction = "up"                   # or "down"
//   range = [0.3, 1.0]
//   ds = 0.01                          # optional: ds_min, ds_max, max_points, shooting,
//   user_values = [0.6]                # linear_solver, detect_folds, detect_branch_points,
//                                      # continue_past_type_changes, user_values_of,
//                                      # max_amplitude (not in a trace's file: trace.max_amplitude),
//                                      # resonance_approach (0 <= . < 1; 0: never)
//   [trace]                            # optional: a trace (branches/trace.hpp) instead of one
//   max_branches = 50                  # branch; then direction is "both" or left out, and
//   max_amplitude = 1e3                # continue_past_type_changes is refused. Keys left out
//   loop_tolerance = 1e-7              # take TraceOptions' defaults.
//   follow_past_unswitched = false
//   allow_inadmissible = false         # trace from a start that is not a motion
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "stickslip/branches/trace.hpp"
#include "stickslip/continuation/continuation.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/io/run_fields.hpp"
#include "stickslip/named_values.hpp"

namespace stickslip {

// Bad input at a run's key: a run file's message starts with "<path>:<line>:<column>:" and names
// the key, which is the field (or "run file" for what concerns the whole file); a run given by
// options (RunNaming::kOptions) names the option, which is the field.
class RunFileError : public InvalidInput {
 public:
  explicit RunFileError(std::string message, std::string key = "run file")
      : InvalidInput(WithMessage(std::move(key), std::move(message))) {}
};

// A branch's steps: the [continuation] keys ds, ds_min, ds_max and max_points (the options of
// those names of continue, trace and find --trace; Python's keywords). Keys left out take the
// engine's defaults, stated once in its option structs.
struct BranchSteps {
  double ds = StepSizeOptions{}.ds;
  double ds_min = StepSizeOptions{}.ds_min;
  double ds_max = StepSizeOptions{}.ds_max;
  int max_points = ContinuationOptions{}.max_points;  // 1 to kMaxRunPoints
  bool operator==(const BranchSteps&) const = default;
};

struct RunFile {
  std::string path;
  // How its messages name its fields: a run file's keys, or the options of a run given by them
  // (continue, trace, atlas, Python).
  RunNaming naming = RunNaming::kRunFileKeys;
  // "path:line:column" of every key present, by its dotted name ("start.preset").
  std::map<std::string, std::string> locations;
  std::string Location(const std::string& key) const {
    const auto it = locations.find(key);
    return it == locations.end() ? path : it->second;
  }
  std::string output;
  // [start]
  std::string preset;
  std::string signature;
  NamedValues set;
  NamedValues guess;
  std::string restart_run;
  std::string restart_label;
  // At a restart from a PD or an SB: the branch that leaves it, not the branch it lies on (AUTO's
  // ISW = -1; branches/bifurcation_branches.hpp), on the side `direction` names.
  bool restart_switch_branch = false;
  // At a restart from a located special point (a change of type: its margin = 0): the curve
  // continued in the plane of the parameter and this second one (branches/boundary_curve.hpp).
  std::string restart_boundary;
  // [unknowns]
  std::vector<std::string> free;
  std::vector<std::string> fix;
  bool tie_u_r = false;
  // [continuation]
  std::string parameter;
  int direction = 1;
  double range_min = 0.0;
  double range_max = 0.0;
  BranchSteps steps;
  std::string shooting = "auto";
  std::string linear_solver = "klu";
  bool detect_folds = ContinuationOptions{}.detect_folds;
  bool detect_branch_points = ContinuationOptions{}.detect_branch_points;
  bool continue_past_type_changes = ContinuationOptions{}.continue_past_terminal;
  double max_amplitude = kDefaultMaxAmplitude;  // a resonance ends the branch (OrbitContinuationSetup)
  double resonance_approach = kDefaultResonanceApproach;  // so does one approached (OrbitContinuationSetup)
  NamedValues user_values;  // (variable, value); the continuation parameter's from user_values
  // [trace]: present for a trace, with its keys (the rest of TraceOptions at its defaults).
  std::optional<TraceOptions> trace;
};

// A complaint about one of the run's keys in the words of the run's front end (RunNaming): a run
// file's "<file>:<line>:<column>: key '<key>' <what>", a run given by options' "<option> <what>".
RunFileError KeyError(const RunFile& run, const std::string& key, const std::string& what);
// The run as messages about its outcome name it: a run file by its path, a run given by options
// by its output ("error: x: the start point does not converge ...").
std::string RunInMessages(const RunFile& run);
// The run's range as its front end writes it: a run file's [0.3, 0.9], the command line's '0.3,0.9'.
std::string RangeIn(const RunFile& run);

// A run's name is the folder of its results under the results root: one path component, so
// not empty, not ".", without '/' and without ".."; without ':', which --point RUN:LABEL takes as
// the end of the name, so a run named "a:b" could never be restarted from; valid UTF-8, which
// summary.json (JSON text) stores as it is on disk; without control characters, which would
// break the one-line messages that name it; and at most kMaxRunNameLength bytes (a file system
// takes 255: the rest is room for "-down"/"-up" and the temporary names beside it, so that a long
// name is refused before the work, not after it).
inline constexpr std::size_t kMaxRunNameLength = 200;
bool IsRunName(std::string_view name);
// The rule, as error messages state the valid values.
inline constexpr std::string_view kRunNameRule =
    "a run name: 1 to 200 bytes of UTF-8, not '.', without '/', '..', ':' or control characters (newline, tab, DEL)";

// The most points a run may ask for (max_points), however it is given.
inline constexpr int kMaxRunPoints = 1000000;

// Largest run file accepted (a guard against feeding the parser arbitrary data).
inline constexpr std::size_t kMaxRunFileBytes = 64 * 1024;

// The values of a run, whichever front end gave them, each checked against its valid range, the
// faults in the words of that front end (KeyError): output a run name (IsRunName), the range
// finite with min < max, the steps (CheckStepValues), 0 < max_amplitude < inf and 0 <=
// resonance_approach < 1. The run-file reader calls it; so do the command line and Python for a
// run given by its options.
void CheckRunValues(const RunFile& run);
// 0 < ds_min <= ds <= ds_max and 1 <= max_points <= kMaxRunPoints, naming ds_min (not > 0), ds_max
// (below ds_min), ds or max_points.
void CheckStepValues(const RunFile& run);

// Throws RunFileError "<path>:<line>:<column>: <what>" on any problem.
RunFile ParseRunFile(std::string_view content, std::string_view path);
RunFile ReadRunFile(const std::filesystem::path& path);

}  // namespace stickslip
