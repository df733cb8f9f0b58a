// The brute force's options, declared once for the commands that run one (map-sweep, atlas): the
// transient and the record of every run, the scattered starts, the periodicity tolerance and the
// threads, with the library's defaults (BruteForceMapOptions).
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "stickslip/analysis/brute_force_map.hpp"

namespace stickslip::cli {

struct BruteForceFlags {
  int transients = BruteForceMapOptions{}.transient_periods;
  int periods = BruteForceMapOptions{}.recorded_periods;
  int starts = BruteForceMapOptions{}.scattered_starts;
  double scatter = BruteForceMapOptions{}.scatter;
  int seed = static_cast<int>(BruteForceMapOptions{}.seed);
  double tolerance = BruteForceMapOptions{}.periodicity_tolerance;
  int threads = BruteForceMapOptions{}.threads;
};

// --transients, --periods, --starts, --scatter, --seed, --tolerance and --threads on `cmd`; `per`
// names what the starts are per ("cell", "grid value").
void AddBruteForceFlags(CLI::App& cmd, BruteForceFlags* flags, const std::string& per);

// `command` (MapSweepCommand, AtlasCommand: io/command_options.hpp) with the flags' values.
template <typename Command>
Command WithBruteForceFlags(Command command, const BruteForceFlags& flags) {
  command.transients = flags.transients;
  command.periods = flags.periods;
  command.starts = flags.starts;
  command.scatter = flags.scatter;
  command.seed = flags.seed;
  command.tolerance = flags.tolerance;
  command.threads = flags.threads;
  return command;
}

}  // namespace stickslip::cli
