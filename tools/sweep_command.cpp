// stickslip sweep: a brute-force bifurcation diagram by simulation, a parameter stepped up and
// then down.
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cli_common.hpp"
#include "commands.hpp"
#include "stickslip/io/atomic_file.hpp"
#include "stickslip/model/sweep.hpp"

namespace stickslip::cli {

namespace {

struct SweepArgs {
  std::string preset;
  std::vector<std::string> assignments;
  std::string parameter = "omega";
  std::string from, to;
  std::string steps = "40";
  std::string transients = "500";
  std::string periods = "20";
  std::string output;
};

int Count(const char* field, const std::string& text, int low, int high) {
  const double value = ParseNumber(field, text, fmt::format("{} <= {} <= {}", low, field, high));
  if (!(value >= low && value <= high) || value != static_cast<int>(value)) {
    throw InputError(fmt::format("{} = {} is invalid: valid range whole numbers {} <= {} <= {}", field, text, low,
                                 field, high));
  }
  return static_cast<int>(value);
}

int RunSweep(const SweepArgs& args) {
  const ModelInput input = ResolveModelInput(args.preset, args.assignments);
  const std::optional<ParameterId> parameter = ParameterFromString(args.parameter);
  if (!parameter) {
    throw InputError(fmt::format("parameter = '{}' is unknown: valid chi, eta, omega, u_s, u_r", args.parameter));
  }
  SweepOptions options;
  options.parameter = *parameter;
  options.from = ParseNumber("from", args.from, "a valid value of the parameter");
  options.to = ParseNumber("to", args.to, "a valid value of the parameter");
  options.steps = Count("steps", args.steps, 1, 100000);
  options.transient_periods = Count("transients", args.transients, 0, 1000000);
  options.recorded_periods = Count("periods", args.periods, 1, 100000);
  for (double value : {options.from, options.to}) {
    Parameters p = input.parameters;
    p[*parameter] = value;
    if (const auto invalid = Validate(p)) throw InputError(invalid->Message());
  }
  const std::vector<SweepPoint> points = Sweep(input.parameters, input.initial_state, input.phi, options);
  WriteFileAtomically(args.output, SweepCsv(points, *parameter, input.phi));
  int periodic = 0;
  for (const SweepPoint& p : points) periodic += p.period > 0;
  fmt::print("sweep {} from {} to {} and back: {} points, {} periodic; written to {}\n", args.parameter,
             options.from, options.to, points.size(), periodic, args.output);
  return kExitOk;
}

}  // namespace

Command AddSweepCommand(CLI::App& app) {
  auto args = std::make_shared<SweepArgs>();
  CLI::App* cmd = app.add_subcommand(
      "sweep",
      "Brute-force bifurcation diagram: step a parameter from --from to --to and back, each point "
      "starting from the last state, simulate --transients forcing periods out and record the "
      "stroboscopic section (the state at forcing phase phi) over --periods periods, with stops and "
      "sticks per period and the period of the motion.");
  cmd->add_option("--preset", args->preset, "paper example for the data and the first start");
  cmd->add_option("--set", args->assignments, SetKeysHelp())->type_name("KEY=VALUE");
  cmd->add_option("--parameter", args->parameter, "chi, eta, omega, u_s or u_r")->capture_default_str();
  cmd->add_option("--from", args->from, "first value (the parameter's valid range)")->required();
  cmd->add_option("--to", args->to, "last value of the upward sweep")->required();
  cmd->add_option("--steps", args->steps, "intervals between --from and --to (1 to 1e5)")->capture_default_str();
  cmd->add_option("--transients", args->transients, "forcing periods discarded per point (0 to 1e6)")
      ->capture_default_str();
  cmd->add_option("--periods", args->periods, "forcing periods recorded per point (1 to 1e5)")->capture_default_str();
  cmd->add_option("--output", args->output,
                  "CSV file: direction,step,<parameter>,section_phase,k,x1,x2,v1,v2,stops_per_period,sticks_per_period,period")
      ->required();
  return {cmd, [args] { return RunSweep(*args); }};
}

}  // namespace stickslip::cli
