// What every stickslip subcommand shares: exit codes, strict number parsing, the help text of
// --set, the parameters in one line.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include <CLI/CLI.hpp>

#include "number_text.hpp"
#include "stickslip/analysis/orbit_finder.hpp"
#include "stickslip/model/pascal_2014/parameters.hpp"
#include "stickslip/orbits/margins.hpp"
#include "stickslip/orbits/verification.hpp"

namespace stickslip::cli {

// Stable exit codes (documented in tools/README.md and in --help). Bad input is InvalidInput, which
// the program maps to kExitBadInput.
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;     // an internal or I/O failure
inline constexpr int kExitBadInput = 2;    // invalid options or values; nothing was written
inline constexpr int kExitNoConvergence = 3;
// solve: the orbit was solved but is no motion of the system (a margin <= 0) or failed its
// verification by simulation; the output is printed all the same.
inline constexpr int kExitNotAMotion = 4;
// find: the motion is not periodic within k <= --max-multiple forcing periods, or its period has
// no stop or stick exit (a permanent stick), so there is no orbit type to solve.
inline constexpr int kExitNotPeriodic = 5;
// (6 was a trace's end at a change of type that switched nowhere, until issue 25: a trace that ran to
// its ends exits 0 whatever they were; they are written and printed.)

// find's exit code for its outcome (the paper's model's and --model's): kExitOk found and verified,
// kExitNotPeriodic, kExitFailure (the simulation stopped early), kExitNoConvergence, kExitNotAMotion.
int FindExitCode(FindOrbitStatus status);

// solve's exit code for a converged orbit with this smallest margin and verification:
// kExitNotAMotion, with its reason, if the margin is not positive or the verification failed;
// kExitOk (and no reason) otherwise.
struct ExitWithReason {
  int exit_code = kExitOk;
  std::string reason;
};
ExitWithReason SolvedOrbitExitCode(const Margin& smallest, const Verification& verification);

// Numeric options read by ParseNumber and ParseCount instead of CLI11's conversion, so that
// "--max-points 2.5" gets the one-line form naming the option, the value and the valid range
// (InvalidInput, thrown while the command line is parsed) rather than "Could not convert"; --help
// shows FLOAT or INT and the default.
CLI::Option* AddNumberOption(CLI::App& cmd, const std::string& name, double* value, const std::string& valid_range,
                             const std::string& help);
CLI::Option* AddCountOption(CLI::App& cmd, const std::string& name, int* value, int low, int high,
                            const std::string& help);

// The help text of --force, the flag of every command that writes a file (io/output_marker.hpp).
inline constexpr const char* kForceHelp =
    "replace the file even if another command or the user wrote it (without it, only a file whose first line shows "
    "that this command wrote it is replaced)";

// What a run's directory holds, for the messages of the commands that read one.
inline constexpr std::string_view kRunDirectory =
    "a run's directory (results/<run>/, holding branch.csv, special-points.csv and summary.json)";

// Throws InvalidInput naming `field` when `directory` holds no run (no branch.csv there), saying why
// (it does not exist, it is a trace's directory, it holds no branch.csv) and what the command
// reads, `valid`; a damaged run is left to the reader, whose message names the file and line.
void CheckHoldsRun(const std::filesystem::path& directory, const std::string& field, std::string_view valid);

// The help text of --set, listing every key with its meaning and valid range (SetKeys).
std::string SetKeysHelp();

// "chi=0.3 eta=4 omega=0.6 u_s=0.1 u_r=0.2996", numbers in shortest round-trip form.
std::string DescribeParameters(const Parameters& p);

}  // namespace stickslip::cli
