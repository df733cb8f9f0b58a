// find --model: the periodic orbit a user's own oscillator (a run file's [model]) settles on, from
// rest, at the file's parameters and those of --set (analysis/model_orbit_finder.hpp), and with
// --trace the chain of its branches in one of its parameters (io/model_trace.hpp); printed as text
// or as one JSON object.
#pragma once

#include <filesystem>

#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

#include "stickslip/io/run_file.hpp"
#include "stickslip/orbits/orbit_solver.hpp"

#include "stickslip/named_values.hpp"

namespace stickslip::cli {

struct ModelFindArgs {
  std::string file;              // the run file with the [model]
  std::vector<std::string> set;  // NAME=VALUE: parameters over the file's
  std::string transients;        // periods simulated before the orbit is read
  std::string max_multiple;      // the longest period read, in forcing periods
  bool json = false;
  std::string trace;             // "LO,HI": trace from the orbit found; empty: none
  std::string trace_parameter;   // the traced parameter; empty: omega, or v_b without forcing
  std::string output;            // with --trace: the trace's directory under `results`; empty: printed only
  std::string results = "results";
  BranchSteps steps;             // each branch's, with --trace
};

// --set NAME=VALUE ... (parameters, start-state components by name, phi) as named values, each a finite number (the model's reader checks the names
// and ranges). Throws InvalidInput naming "set" or the name.
NamedValues ModelSetOf(const std::vector<std::string>& set);

// Throws InvalidInput naming the first of `options` given on `cmd` ("X is not taken with --model: "
// followed by `instead`, what gives the oscillator and its start with --model).
void RefuseWithModel(const CLI::App& cmd, std::initializer_list<const char*> options, std::string_view instead);

// Throws InvalidInput naming `field` when `output` is the run file `model` itself (by any path),
// which no output replaces, --force or not.
void RefuseOutputOverModel(const std::string& output, const std::string& model, const char* field);

// solve --point RUN:LABEL at a [model]'s label (io/model_restart.hpp): the label's orbit solved at
// its parameters (`solver`: shooting and linear solver), checked and printed as find --model checks
// and prints the orbit it finds (text or JSON). Exit codes as solve's: 0 a motion, verified; 3
// Newton did not converge; 4 no motion (a margin <= 0) or not verified. Throws InvalidInput naming
// "point" when the label cannot be read.
int RunModelSolve(const std::filesystem::path& results, const std::string& point, const OrbitSolverOptions& solver,
                  bool json);

// The exit code as find's: 0 found and verified (and the trace ran to its ends), 3 Newton failed (or
// a branch of the trace), 4 no motion or not verified, 5 no orbit type read off the motion (it never
// stops, or has not settled), 1 the simulation stopped early. With `output`, the trace is written
// to results/<output>/ as stickslip trace writes one (io/trace_files.hpp), its directory checked
// before the work. Throws InvalidInput for bad input.
int RunModelFind(const ModelFindArgs& args);

}  // namespace stickslip::cli
