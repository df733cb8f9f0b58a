// stickslip solve: one periodic orbit from the periodicity equations, with its Newton summary,
// admissibility margins and independent verification.
#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli_common.hpp"
#include "commands.hpp"
#include "orbit_report.hpp"
#include "start_options.hpp"
#include "stickslip/branches/orbit_monitor.hpp"
#include "stickslip/io/command_options.hpp"
#include "stickslip/orbits/margins.hpp"
#include "stickslip/orbits/orbit_measures.hpp"
#include "stickslip/orbits/orbit_solver.hpp"
#include "stickslip/orbits/paper_presets.hpp"
#include "stickslip/orbits/stability.hpp"
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

// The solution as one JSON object (the keys --help lists); non-finite numbers are null.
std::string Json(const Orbit& o, const OrbitSolution& s, const std::vector<Margin>& margins,
                 const Verification& v) {
  using Json = nlohmann::ordered_json;
  auto number = [](double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); };
  auto modes = [](const std::vector<Mode>& sequence) {
    Json list = Json::array();
    for (Mode m : sequence) list.push_back(ToString(m));
    return list;
  };
  auto check = [&](const SimulatorCheck& c) {
    const bool simulated = v.not_simulated.empty();
    return Json{{"events", modes(c.modes)},
                {"sequence_matches", c.sequence_matches},
                {"max_mismatch", simulated ? number(c.periodicity_mismatch) : Json(nullptr)},
                {"max_event_time_difference", simulated ? number(c.max_event_time_difference) : Json(nullptr)}};
  };
  Json out{{"signature", o.signature.ToString()}};
  for (ParameterId id : kAllParameters) out["parameters"][ToString(id)] = o.parameters[id];
  out.update(Json{{"phi", o.phi}, {"x10", o.x10}, {"x20", o.x20}, {"v10", o.v10}});
  out["segments"] = Json::array();
  for (int i = 0; i < o.signature.size(); ++i) {
    out["segments"].push_back({{"mode", ToString(o.signature.segments()[i])}, {"duration", o.durations[i]}});
  }
  out.update(Json{{"converged", s.summary.Converged()},
                  {"termination", ToString(s.summary.termination)},
                  {"iterations", s.summary.iterations},
                  {"residual_norm", number(s.summary.residual_norms.back())},
                  {"condition_number", number(s.summary.condition_number)},
                  {"shooting", ToString(s.shooting)}});
  out["margins"] = Json::object();
  for (const Margin& m : margins) out["margins"][m.Name()] = number(m.value);
  const Stability stability = StabilityOf(o);
  out["multipliers"] = Json::array();
  for (const std::complex<double>& mu : stability.multipliers) {
    out["multipliers"].push_back({number(mu.real()), number(mu.imag())});
  }
  out.update(Json{{"stable", stability.stable}, {"multipliers_one_sided", stability.one_sided}});
  out["measures"] = Json::object();
  const OrbitMeasures measures = Measure(o);
  orbit_columns::ForEachMeasure(measures, [&](const char* name, const auto& value) {
    out["measures"][name] = std::isfinite(static_cast<double>(value)) ? Json(value) : Json(nullptr);  // counts stay integers
  });
  out["verification"] = {{"passed", v.Passed()},
                         {"not_simulated", v.not_simulated.empty() ? Json(nullptr) : Json(v.not_simulated)},
                         {"expected", modes(v.expected)},
                         {"exact", check(v.exact)},
                         {"odeint", check(v.odeint)}};
  return out.dump() + "\n";
}


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

int RunSolve(const SolveArgs& args) {
  if (args.compare_paper && args.start.preset.empty()) {
    throw InvalidInput::WithMessage("compare-paper", "compare-paper needs --preset");
  }
  StartInput input = ToStartInput(args.start);
  input.paper_choice = args.paper_choice;
  const StartProblem start = BuildStartProblem(input);
  const PaperPreset* preset = FindPaperPreset(args.start.preset);

  OrbitSolverOptions options;
  options.shooting = *ShootingChoiceFromString(args.shooting);  // CLI11 checked the choice
  // A sparse solver means something only where multiple shooting may be chosen: given with single
  // shooting it would be silently ignored, so the contradiction is refused.
  CheckLinearSolverIsUsed(args.linear_solver, args.shooting);
  options.sparse_solver = *LinearSolverFromString(args.linear_solver.empty() ? "klu" : args.linear_solver);
  const OrbitSolution solution = SolveOrbit(start.orbit, start.free, start.unknowns.tie_static_friction, options);
  const Orbit& orbit = solution.orbit;
  if (!solution.summary.Converged()) {
    fmt::print(stderr, "error: Newton did not converge: {}\n", solution.summary.BriefReport());
    return kExitNoConvergence;
  }
  const std::vector<Margin> margins = AdmissibilityMargins(orbit);
  const Verification verification = VerifyOrbit(orbit);
  if (args.json) {
    fmt::print("{}", Json(orbit, solution, margins, verification));
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
                "print one JSON object: signature, parameters, phi, x10, x20, v10, segments, "
                "converged, residual_norm, margins, multipliers, stable, measures (amplitude:x1, "
                "amplitude:x2, peak-to-peak:x2, stick-fraction, stops, sticks), verification");
  cmd->add_flag("--compare-paper", args->compare_paper,
                "with --preset: print a Markdown table of the paper's printed values beside "
                "stickslip's");
  return {cmd, [args] { return RunSolve(*args); }};
}

}  // namespace stickslip::cli
