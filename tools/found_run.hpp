// The run find makes of the orbit it found: its start (StartInputOf), continued in omega over a
// range, as a trace (find --trace, and --write-run --as trace) or as one branch upwards (--write-run,
// to edit). One RunFile, traced at once or written as the text of a run file that `stickslip run`
// reads back as the same run.
#pragma once

#include <string>
#include <string_view>

#include "stickslip/io/run_file.hpp"
#include "stickslip/orbits/start_problem.hpp"

namespace stickslip::cli {

// The first line of a run file find writes: the mark of a file that find may replace (a committed
// run file, the user's, has none).
inline constexpr std::string_view kFoundRunFileMarker = "# written by stickslip find: the orbit it found, as a start";

struct OmegaRange {
  double low = 0.0;
  double high = 0.0;
};

// "LO,HI": two finite numbers, kMinOmega <= LO < HI <= kMaxOmega. Throws InvalidInput naming `field`
// with the text and the valid range.
OmegaRange ParseOmegaRange(const char* field, const std::string& text);

// 10% either side of `omega`, within [kMinOmega, kMaxOmega], to six significant digits: a range to edit.
OmegaRange RangeAround(double omega);

// The run from `start` in omega over `range`, into results/<output>/: a trace when `trace`, else
// one branch upwards; its branches stepping as `steps`.
RunFile FoundRun(const StartInput& start, OmegaRange range, const std::string& output, bool trace, const BranchSteps& steps);

// `run` (a FoundRun) as the text of a run file, after kFoundRunFileMarker; its steps where they
// are not the defaults.
std::string RunFileText(const RunFile& run);

// A number as TOML and a command line take it back exactly: the shortest round-trip form, with
// ".0" where it would read as an integer.
std::string ExactNumber(double x);

}  // namespace stickslip::cli
