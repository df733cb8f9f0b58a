// The start problem's input (orbits/start_problem.hpp) as the io layer supplies it: a labelled
// point of stored results read into a restart point, a run file's [start] and [unknowns] tables
// and its continuation parameter, and the builder's errors placed at the run file's keys.
#pragma once

#include <filesystem>
#include <string>

#include "stickslip/io/run_file.hpp"
#include "stickslip/orbits/start_problem.hpp"

namespace stickslip {

// The point `label` of results_root/<run>/ (special-points.csv and summary.json). Throws
// InvalidInput "restart = 'RUN:LABEL' cannot be used: <why>" when the run or the label is not
// there or the run name is invalid.
RestartPoint ReadRestartPoint(const std::filesystem::path& results_root, const std::string& run,
                              const std::string& label);

// The run file's start, unknowns and continuation parameter, with its restart point read from
// results_root. Throws InvalidInput (ReadRestartPoint).
StartInput StartInputOf(const RunFile& run, const std::filesystem::path& results_root);

// A StartInput field's error at the run's field, in its front end's words (KeyError): a run file's
// "<file>:<line>:<column>: key 'start.preset' = 'paper-9' is unknown: ...", the command line's
// "preset = 'paper-9' is unknown: ...". A variable out of range is a run file's key 'start' and
// the command line's variable.
InvalidInput AtRunField(const RunFile& run, const InvalidInput& error);

}  // namespace stickslip
