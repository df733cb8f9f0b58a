// The subcommands of the stickslip program. Each Add* function declares a subcommand's options
// on `app` and returns it with the action to run when it was given; the action returns the
// process exit code (cli_common.hpp) and throws InvalidInput for bad input.
#pragma once

#include <functional>
#include <string>

#include <CLI/CLI.hpp>

namespace stickslip::cli {

struct Command {
  CLI::App* subcommand = nullptr;
  std::function<int()> run;
};

Command AddSimulateCommand(CLI::App& app);
Command AddSolveCommand(CLI::App& app);
Command AddRunCommand(CLI::App& app);
Command AddContinueCommand(CLI::App& app);
Command AddCheckCommand(CLI::App& app);
Command AddSweepCommand(CLI::App& app);
Command AddExportCommand(CLI::App& app);
Command AddFindCommand(CLI::App& app);
Command AddPlotCommand(CLI::App& app);
Command AddTraceCommand(CLI::App& app);
Command AddAtlasCommand(CLI::App& app);
Command AddMapCommand(CLI::App& app);
Command AddDescribeCommand(CLI::App& app);
// map_sweep_command.hpp: Command AddMapSweepCommand(CLI::App& app, ...).

}  // namespace stickslip::cli
