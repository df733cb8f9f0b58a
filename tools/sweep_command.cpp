// stickslip sweep: a brute-force bifurcation diagram by simulation, a parameter stepped up and
// then down from one or several starting states, the chains in parallel.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cli_common.hpp"
#include "commands.hpp"
#include "model_find.hpp"
#include "progress_line.hpp"
#include "start_options.hpp"
#include "stickslip/io/atomic_file.hpp"
#include "stickslip/io/command_options.hpp"
#include "stickslip/io/model_sweep.hpp"
#include "stickslip/io/output_marker.hpp"
#include "stickslip/analysis/sweep.hpp"
#include "stickslip/numerics/parallel_for.hpp"

namespace stickslip::cli {

namespace {

// The options as texts, with SweepCommand's defaults (which Python's sweep has too).
std::string Text(double value) { return fmt::format("{}", value); }
struct SweepArgs {
  StartFlags origin;
  std::string parameter = SweepCommand{}.parameter;
  std::string from, to;
  std::string steps = Text(SweepCommand{}.steps);
  std::string transients = Text(SweepCommand{}.transients);
  std::string periods = Text(SweepCommand{}.periods);
  std::string start = SweepCommand{}.start;
  std::string chains = Text(SweepCommand{}.chains);
  std::string scatter = Text(SweepCommand{}.scatter);
  std::string seed = Text(SweepCommand{}.seed);
  std::string threads = Text(SweepCommand{}.threads);
  std::string output;
  std::string model;  // --model FILE: a user's oscillator (io/model_sweep.hpp)
  bool force = false;
};

// The options as the library's command; their numbers checked by PlanSweep, as Python's are.
SweepCommand CommandOf(const SweepArgs& args, std::string_view from_to_range) {
  SweepCommand command;
  command.parameter = args.parameter;
  auto number = [](const char* field, const std::string& text) {
    return ParseNumber(field, text, SweepOptionRange(field));
  };
  command.from = ParseNumber("from", args.from, from_to_range);
  command.to = ParseNumber("to", args.to, from_to_range);
  command.steps = number("steps", args.steps);
  command.transients = number("transients", args.transients);
  command.periods = number("periods", args.periods);
  command.start = args.start;
  command.chains = number("chains", args.chains);
  command.scatter = number("scatter", args.scatter);
  command.seed = number("seed", args.seed);
  command.threads = number("threads", args.threads);
  return command;
}

void PrintSwept(const SweepArgs& args, const SweepOptions& options, int chains, int threads,
                const std::vector<SweepPoint>& points) {
  int periodic = 0;
  for (const SweepPoint& p : points) periodic += p.period > 0;
  fmt::print("sweep {} from {} to {}{} ({}), {} chain(s) on {} thread(s): {} points, {} periodic; written to {}\n",
             args.parameter, options.from, options.to, options.start == SweepStart::kChained ? " and back" : "",
             args.start, chains, threads, points.size(), periodic, args.output);
}

// sweep --model: from rest and states scattered around it; the paper's model's start options refused.
int RunModelSweep(const SweepArgs& args, const CLI::App& cmd) {
  RefuseWithModel(cmd, {"--preset", "--point", "--results"},
                  "the sweep starts from rest, or --set's start state (x1_0=..., phi=...), and --chains - 1 states "
                  "scattered around it; --set also sets the model's parameters");
  CheckReplaceableOutputFile(args.output, "output", {"stickslip sweep", IsSweepCsvHeader}, args.force);
  RefuseOutputOverModel(args.output, args.model, "output");
  const ModelFileStart start = ReadModelFileStart(args.model, ModelSetOf(args.origin.set));
  const ModelDescription& model = start.model.Description();
  const std::optional<int> k = model.ParameterIndex(args.parameter);
  const SweepCommand command = CommandOf(args, k ? model.parameters[*k].range : std::string("a finite number"));
  ProgressLine line("sweep");
  const ModelSweepRun run = SweepModel(start, command, line.Callback());
  line.Clear();
  WriteFileAtomically(args.output, ModelSweepCsv(run));
  PrintSwept(args, run.options, run.chains, run.threads, run.points);
  return kExitOk;
}

int RunSweep(const SweepArgs& args) {
  CheckReplaceableOutputFile(args.output, "output", {"stickslip sweep", IsSweepCsvHeader}, args.force);
  const ModelStart input = BuildModelStart(ToStartInput(args.origin));
  const SweepPlan plan = PlanSweep(CommandOf(args, SetKeyRange(args.parameter)), Pascal2014{}.Description());
  SweepOptions options = plan.options;
  ProgressLine line("sweep");
  options.progress = line.Callback();
  const std::vector<SweepPoint> points = Sweep(
      input.parameters, ScatteredStarts(input.initial_state, plan.scatter, plan.chains, plan.seed), input.phi, options);
  line.Clear();
  WriteFileAtomically(args.output, SweepCsv(Pascal2014{}, points, options.parameter, input.phi));
  const int items = options.start == SweepStart::kChained ? plan.chains : plan.chains * (options.steps + 1);
  PrintSwept(args, options, plan.chains, WorkerCount(options.threads, items), points);
  return kExitOk;
}

}  // namespace

Command AddSweepCommand(CLI::App& app) {
  auto args = std::make_shared<SweepArgs>();
  CLI::App* cmd = app.add_subcommand(
      "sweep",
      "Brute-force bifurcation diagram: step a parameter from --from to --to, simulate --transients "
      "forcing periods out and record the stroboscopic section (the state at forcing phase phi) over "
      "--periods periods, with stops and sticks per period and the period of the motion. With "
      "--start chained (the default) each point starts from the last state and the sweep comes back "
      "down from --to; with --start fixed every point starts from its chain's start, in one pass. "
      "--chains independent chains start from the preset's (or --set, or --point) state and from "
      "states scattered around it, and run in parallel; the output does not depend on --threads.");
  AddStartOptions(*cmd, &args->origin, StartOptions::kMotion);
  cmd->add_option("--results", args->origin.results, "where the runs of --point are stored")->capture_default_str();
  cmd->add_option("--parameter", args->parameter, "chi, eta, omega, u_s or u_r (with --model: one of the model's)")->capture_default_str();
  cmd->add_option("--from", args->from, "first value (the parameter's valid range)")->type_name("FLOAT")->required();
  cmd->add_option("--to", args->to, "last value of the up pass (of the only pass with --start fixed)")->type_name("FLOAT")->required();
  cmd->add_option("--steps", args->steps, "intervals between --from and --to (1 to 1e5)")->type_name("INT")->capture_default_str();
  cmd->add_option("--transients", args->transients, "forcing periods discarded per point (0 to 1e6)")
      ->type_name("INT")->capture_default_str();
  cmd->add_option("--periods", args->periods, "forcing periods recorded per point (1 to 1e5)")->type_name("INT")->capture_default_str();
  cmd->add_option("--start", args->start,
                  "chained: up then down, each point from the last state; fixed: every point from its "
                  "chain's start, one pass")
      ->capture_default_str();
  cmd->add_option("--chains", args->chains, "starting states, the first the given one (1 to 1e4)")
      ->type_name("INT")->capture_default_str();
  cmd->add_option("--scatter", args->scatter,
                  "half-width of the box around the given state that the other starts are drawn from (0 to 1e6)")
      ->type_name("FLOAT")->capture_default_str();
  cmd->add_option("--seed", args->seed, "seed of the scattered starts (0 to 1e9)")->type_name("INT")->capture_default_str();
  cmd->add_option("--threads", args->threads, "threads (0: every core; 0 to 1024)")->type_name("INT")->capture_default_str();
  cmd->add_option("--output", args->output,
                  "CSV file: chain,direction,step,<parameter>,section_phase,k,x1,x2,v1,v2,stops_per_period,sticks_per_period,period,amplitude:x2")
      ->required();
  cmd->add_flag("--force", args->force, kForceHelp);
  cmd->add_option("--model", args->model,
                  "sweep the oscillator in this run file's [model] (see describe) instead of the paper's: from rest "
                  "(or --set's start state by name and phase phi) and --chains - 1 states scattered around it, the "
                  "section at that forcing phase (0 by default), --parameter one of the model's (omega, F_k, F_s, "
                  "v_b; SI units), --set its parameters; the CSV's state columns are "
                  "the model's coordinates and velocities (v<k> for x<k>, v_q for any other q), the amplitude the "
                  "contact's coordinate's. A model without forcing (a belt) is read on its stick-entry section: the state at each "
                  "stick entry, the period in stick-slip cycles, stops and sticks per cycle, --transients and --periods in "
                  "units of its slowest free oscillation 2 pi/omega_1 (a steady slide: period 1, no stop)")
      ->type_name("FILE");
  return {cmd, [args, cmd] { return cmd->count("--model") == 0 ? RunSweep(*args) : RunModelSweep(*args, *cmd); }};
}

}  // namespace stickslip::cli
