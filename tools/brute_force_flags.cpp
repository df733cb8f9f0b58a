#include "brute_force_flags.hpp"

#include <fmt/format.h>

#include "cli_common.hpp"
#include "stickslip/io/command_options.hpp"
#include "stickslip/model/transient.hpp"

namespace stickslip::cli {

void AddBruteForceFlags(CLI::App& cmd, BruteForceFlags* flags, const std::string& per) {
  AddCountOption(cmd, "--transients", &flags->transients, 0, kMaxTransientPeriods,
                 "forcing periods discarded per run (0 to 1e6)");
  AddCountOption(cmd, "--periods", &flags->periods, 2, BruteForceMapOptions::kMaxRecordedPeriods,
                 "forcing periods recorded per run (2 to 1e5): periods up to half of it are detected, a signature "
                 "needs about 2k + 1 for period k");
  AddCountOption(cmd, "--starts", &flags->starts, 0, BruteForceMapOptions::kMaxScatteredStarts,
                 fmt::format("starts per {} besides rest and the neighbour: the given state (--preset's, --set x10=...; "
                             "rest if none) and states scattered around it (0 to 1000)",
                             per));
  AddNumberOption(cmd, "--scatter", &flags->scatter, "0 <= scatter <= 1e6",
                  "half-width of the box around the given state the scattered starts are drawn from (0 to 1e6)");
  AddCountOption(cmd, "--seed", &flags->seed, 0, 1000000000, "seed of the scattered starts (0 to 1e9)");
  AddNumberOption(cmd, "--tolerance", &flags->tolerance, MapSweepOptionRange("tolerance"),
                  "section points repeat, and two runs' orbits agree, within this (absolute, max norm; 1e-14 to 1e-2)");
  AddCountOption(cmd, "--threads", &flags->threads, 0, 1024, "threads (0: every core; 0 to 1024)");
}

}  // namespace stickslip::cli
