// The stickslip command-line program: one subcommand per job (commands.hpp).
#include <exception>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "cli_common.hpp"
#include "commands.hpp"
#include "map_sweep_command.hpp"
#include "start_options.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/io/command_options.hpp"
#include "stickslip/version.hpp"

int main(int argc, char** argv) {
  using namespace stickslip::cli;
  CLI::App app(
      "stickslip: periodic orbits of dry-friction oscillators: the two-degree-of-freedom oscillator of "
      "M. Pascal, Nonlinear Dyn. 77 (2014) 267-276, and a linear oscillator of your own with a Coulomb contact "
      "(a run file's [model]: describe, find --model).\n"
      "Exit codes: 0 success (a trace that ran to its ends, whatever they were), 1 failure, 2 bad input (nothing "
      "written), 3 no convergence (a start; a branch whose corrector failed before its end: the points reached "
      "are written), 4 solve, find: the solution is not a motion of the system (a margin <= 0) or "
      "failed its verification; trace: its start is not a motion (nothing written), 5 find: the motion is not "
      "periodic within k <= --max-multiple forcing periods (or has no stop or stick exit).",
      "stickslip");
  app.set_version_flag("--version", fmt::format("stickslip {}", stickslip::Version()), "print the version and exit");
  app.require_subcommand(1);
  // A flag takes no value: CLI11 otherwise reads --allow-inadmissible=2 or =1e300 as true and =-1 as
  // false (a count), where bad input is wanted. Every subcommand copies this default.
  app.option_defaults()->disable_flag_override();
  const std::vector<Command> commands = {AddRunCommand(app), AddContinueCommand(app), AddTraceCommand(app), AddAtlasCommand(app), AddCheckCommand(app),
                                         AddSolveCommand(app), AddSimulateCommand(app), AddSweepCommand(app), AddMapSweepCommand(app), AddMapCommand(app),
                                         AddExportCommand(app), AddFindCommand(app), AddPlotCommand(app), AddDescribeCommand(app)};
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const stickslip::InvalidInput& e) {  // a number option read by ParseNumber or ParseCount
    fmt::print(stderr, "error: {}\n", stickslip::OnCommandLine(e).what());
    return kExitBadInput;
  } catch (const CLI::ParseError& e) {
    std::string message = e.what();
    if (message == "A subcommand is required" && argc > 1) {
      message = fmt::format("command '{}' is unknown: valid commands run, continue, trace, check, solve, simulate, sweep, map-sweep, map, export, find, plot, describe", argv[1]);
    }
    // "allow-inadmissible was given a disallowed flag override": the option, its value, the rule.
    constexpr std::string_view kOverride = " was given a disallowed flag override";
    if (message.ends_with(kOverride)) {
      const std::string flag = "--" + message.substr(0, message.size() - kOverride.size());
      std::string value;
      for (int k = 1; k < argc; ++k) {
        const std::string_view arg = argv[k];
        if (arg.starts_with(flag + "=")) value = std::string(arg.substr(flag.size() + 1));
      }
      message = stickslip::InvalidInput::WithMessage(
                    flag, fmt::format("{} = '{}' is invalid: valid no value ({} is a flag, on when given)", flag, value, flag))
                    .what();
    }
    fmt::print(stderr, "error: {}\n", message);
    return kExitBadInput;
  }
  try {
    for (const Command& command : commands) {
      if (command.subcommand->parsed()) return command.run();
    }
  } catch (const stickslip::InvalidInput& e) {
    fmt::print(stderr, "error: {}\n", stickslip::OnCommandLine(e).what());
    return kExitBadInput;
  } catch (const std::exception& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return kExitFailure;
  }
  return kExitFailure;
}
