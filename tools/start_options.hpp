// The options a subcommand starts from, declared once: --preset, --point, --signature, --set,
// --guess, --free, --fix, --tie-u_r; and their conversion into the library's one start-problem
// input (stickslip/orbits/start_problem.hpp), which checks them. Each command declares its own
// --results (where --point reads from), since continue also writes there.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "stickslip/invalid_input.hpp"
#include "stickslip/io/run_file.hpp"
#include "stickslip/orbits/start_problem.hpp"

namespace stickslip::cli {

struct StartFlags {
  std::string preset;
  std::string point;  // RUN:LABEL
  std::string results = "results";  // bound to the command's --results
  std::string signature;
  std::vector<std::string> set;    // KEY=VALUE
  std::vector<std::string> guess;  // NAME=VALUE
  std::vector<std::string> free;
  std::vector<std::string> fix;  // NAME or NAME=VALUE
  bool tie_u_r = false;
};

enum class StartOptions {
  kMotion,  // simulate, sweep: --preset, --point, --set
  kOrbit,   // solve, continue: those and --signature, --guess, --free, --fix, --tie-u_r
};
void AddStartOptions(CLI::App& cmd, StartFlags* flags, StartOptions which);

// Parses the texts (numbers strictly, ParseNumber) and reads the --point from --results.
// Throws InvalidInput.
StartInput ToStartInput(const StartFlags& flags);


}  // namespace stickslip::cli
