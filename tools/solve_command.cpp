// stickslip solve: one periodic orbit from the periodicity equations, with its Newton summary,
// admissibility margins and independent verification.
#include <cmath>
#include <memory>
#include <numbers>
#include <optional>
#include <utility>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>  // dump()

#include "cli_common.hpp"
#include "commands.hpp"
#include "orbit_json.hpp"
#include "model_find.hpp"
#include "orbit_report.hpp"
#include "start_options.hpp"
#include "stickslip/io/command_options.hpp"
#include "stickslip/io/model_restart.hpp"
#include "stickslip/orbits/margins.hpp"
#include "stickslip/orbits/orbit_solver.hpp"
#include "stickslip/orbits/paper_presets.hpp"
#include "stickslip/orbits/verification.hpp"

namespace stickslip::cli {

namespace {

struct SolveArgs {
  StartFlags start;
  bool paper_choice = false;
  std::string shooting = "auto";
  std::string linear_solver;  // empty: not given (klu where multiple shooting is used)
  bool json = false;
  bool compare_paper = false;
};

std::string PaperComparison(const PaperPreset& preset, const Orbit& o, const std::string& choice) {
  std::string out = fmt::format("#### {} ({}, {}): {}\n\n| paper | printed | stickslip | difference |\n|---|---|---|---|\n",
                                preset.example->name, preset.example->equation, choice,
                                o.signature.ToString());
  for (const PrintedValue& v : preset.printed) {
    const double printed = std::stod(std::string(v.text));
    const double computed = PrintedQuantity(o, v.variable);
    out += fmt::format("| {} | {} | {:.6f} | {:+.1e} |\n", v.paper_name, v.text, computed, computed - printed);
  }
  return out;
}

// A [model]'s label: its orbit solved and checked as find --model's (RunModelSolve); the options of
// the paper's start refused.
std::optional<int> SolveIfModelLabel(const SolveArgs& args, const OrbitSolverOptions& solver) {
  if (!ModelPointOf(args.start.results, args.start.point)) return std::nullopt;
  const StartFlags& s = args.start;
  for (const auto& [option, given] : {std::pair{"preset", !s.preset.empty()}, {"signature", !s.signature.empty()},
                                      {"set", !s.set.empty()}, {"guess", !s.guess.empty()}, {"free", !s.free.empty()},
                                      {"fix", !s.fix.empty()}, {"tie-u_r", s.tie_u_r},
                                      {"paper-choice", args.paper_choice}, {"compare-paper", args.compare_paper}}) {
    if (!given) continue;
    throw InvalidInput::WithMessage(option, fmt::format("--{} is not taken at a [model]'s label ('{}'): the label gives "
                                                        "the model, its orbit and its unknowns",
                                                        option, s.point));
  }
  return RunModelSolve(s.results, s.point, solver, args.json);
}

int RunSolve(const SolveArgs& args) {
  const OrbitSolverOptions options = SolverOptionsOf(args.shooting, args.linear_solver);
  if (const std::optional<int> code = SolveIfModelLabel(args, options)) return *code;
  if (args.compare_paper && args.start.preset.empty()) {
    throw InvalidInput::WithMessage("compare-paper", "compare-paper needs --preset");
  }
  StartInput input = ToStartInput(args.start);
  input.paper_choice = args.paper_choice;
  const StartProblem start = BuildStartProblem(input);
  const PaperPreset* preset = FindPaperPreset(args.start.preset);
  const OrbitSolution solution = SolveOrbit(start.orbit, start.free, start.unknowns.tie_static_friction, options);
  const Orbit& orbit = solution.orbit;
  if (!solution.summary.Converged()) {
    fmt::print(stderr, "error: Newton did not converge: {}\n", solution.summary.BriefReport());
    return kExitNoConvergence;
  }
  const std::vector<Margin> margins = AdmissibilityMargins(orbit);
  const Verification verification = VerifyOrbit(orbit);
  if (args.json) {
    fmt::print("{}\n", OrbitJson(solution, start.free, start.unknowns.tie_static_friction, margins, verification).dump());
    return SolvedOrbitOutcome(margins, verification);
  }
  if (args.compare_paper) {
    fmt::print("{}", PaperComparison(*preset, orbit, args.paper_choice ? std::string(preset->paper_choice_note) : "paper's data held"));
    return SolvedOrbitOutcome(margins, verification);
  }
  fmt::print("{}", OrbitReport(solution, start.free, start.unknowns.tie_static_friction, ToString(options.sparse_solver), margins,
                               verification));
  return SolvedOrbitOutcome(margins, verification);
}

}  // namespace

Command AddSolveCommand(CLI::App& app) {
  auto args = std::make_shared<SolveArgs>();
  CLI::App* cmd = app.add_subcommand(
      "solve",
      "Solve the periodicity equations of an orbit type for one periodic orbit; print the "
      "unknowns, the Newton summary, the admissibility margins and a verification by the exact "
      "and the Odeint simulators. Exit code 3 if Newton does not converge, 4 if the solution is not a "
      "motion of the system (a margin <= 0) or fails its verification (the output is printed all the same).");
  AddStartOptions(*cmd, &args->start, StartOptions::kOrbit);
  cmd->add_option("--results", args->start.results, "where the runs of --point are stored")->capture_default_str();
  cmd->add_flag("--paper-choice", args->paper_choice,
                "with --preset: the paper's own choice where a round printed value looks held "
                "fixed (see results/README.md, errata)");
  cmd->add_option("--shooting", args->shooting,
                  "single (dense), multiple (block-sparse, SuiteSparse), or auto (single up to 6 "
                  "listed segments)")
      ->check(CLI::IsMember({"auto", "single", "multiple"}))
      ->capture_default_str();
  cmd->add_option("--linear-solver", args->linear_solver,
                  "sparse solver for multiple shooting (with --shooting multiple or auto; refused with single)")
      ->check(CLI::IsMember({"klu", "umfpack", "dense"}))
      ->default_str("klu");
  cmd->add_flag("--json", args->json,
                "print one JSON object: signature, parameters, phi, x10, x20, v10, segments, unknowns (the "
                "solved variables by name), tie_u_r, converged, residual_norm, margins, admissible, multipliers, "
                "stable, measures (amplitude:x1, amplitude:x2, peak-to-peak:x2, stick-fraction, stops, sticks, friction-work, equivalent-damping), "
                "verification");
  cmd->add_flag("--compare-paper", args->compare_paper,
                "with --preset: print a Markdown table of the paper's printed values beside "
                "stickslip's");
  return {cmd, [args] { return RunSolve(*args); }};
}

}  // namespace stickslip::cli
