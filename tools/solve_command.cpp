// stickslip solve: one periodic orbit from the periodicity equations, with its Newton summary,
// admissibility margins and independent verification.
#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cli_common.hpp"
#include "commands.hpp"
#include "start_options.hpp"
#include "stickslip/orbits/margins.hpp"
#include "stickslip/orbits/orbit_solver.hpp"
#include "stickslip/orbits/paper_presets.hpp"
#include "stickslip/orbits/stability.hpp"
#include "stickslip/orbits/verification.hpp"

namespace stickslip::cli {

namespace {

namespace ov = orbit_variables;

struct SolveArgs {
  StartFlags start;
  bool paper_choice = false;
  std::string shooting = "auto";
  std::string linear_solver = "klu";
  bool json = false;
  bool compare_paper = false;
};

std::string MultipliersJson(const Stability& stability) {
  std::string out;
  for (const std::complex<double>& mu : stability.multipliers) {
    out += fmt::format("{}[{}, {}]", out.empty() ? "" : ", ", mu.real(), mu.imag());
  }
  return fmt::format("\"multipliers\": [{}], \"stable\": {}, \"multipliers_one_sided\": {}", out,
                     stability.stable, stability.one_sided);
}

std::string Json(const Orbit& o, const OrbitSolution& s, const std::vector<Margin>& margins,
                 const Verification& v) {
  std::string out = fmt::format("{{\"signature\": \"{}\", \"parameters\": {{", o.signature.ToString());
  for (ParameterId id : kAllParameters) {
    out += fmt::format("{}\"{}\": {}", id == ParameterId::kChi ? "" : ", ", ToString(id), o.parameters[id]);
  }
  out += fmt::format("}}, \"phi\": {}, \"x10\": {}, \"x20\": {}, \"v10\": {}, \"segments\": [", o.phi,
                     o.x10, o.x20, o.v10);
  for (int i = 0; i < o.signature.size(); ++i) {
    out += fmt::format("{}{{\"mode\": \"{}\", \"duration\": {}}}", i ? ", " : "",
                       ToString(o.signature.segments()[i]), o.durations[i]);
  }
  out += fmt::format("], \"converged\": {}, \"termination\": \"{}\", \"iterations\": {}, "
                     "\"residual_norm\": {}, \"condition_number\": {}, \"shooting\": \"{}\", "
                     "\"margins\": {{",
                     s.summary.Converged(), ToString(s.summary.termination), s.summary.iterations,
                     s.summary.residual_norms.back(), s.summary.condition_number,
                     ToString(s.shooting));
  for (std::size_t i = 0; i < margins.size(); ++i) {
    const double value = margins[i].value;
    out += fmt::format("{}\"{}\": {}", i ? ", " : "", margins[i].Name(),
                       std::isfinite(value) ? fmt::format("{}", value) : std::string("null"));
  }
  auto sequence = [](const std::vector<Mode>& modes) {
    std::string text;
    for (Mode m : modes) text += fmt::format("{}\"{}\"", text.empty() ? "" : ", ", ToString(m));
    return "[" + text + "]";
  };
  out += fmt::format("}}, {}", MultipliersJson(StabilityOf(o)));
  out += fmt::format(
      ", \"verification\": {{\"passed\": {}, \"expected\": {}, \"exact\": {{\"events\": {}, "
      "\"sequence_matches\": {}, \"max_mismatch\": {}, \"max_event_time_difference\": {}}}, "
      "\"odeint\": {{\"events\": {}, \"sequence_matches\": {}, \"max_mismatch\": {}, "
      "\"max_event_time_difference\": {}}}}}}}\n",
      v.Passed(), sequence(v.expected), sequence(v.exact.modes), v.exact.sequence_matches,
      v.exact.periodicity_mismatch, v.exact.max_event_time_difference, sequence(v.odeint.modes),
      v.odeint.sequence_matches, v.odeint.periodicity_mismatch, v.odeint.max_event_time_difference);
  return out;
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
  const int n = start.orbit.signature.size();

  OrbitSolverOptions options;
  if (args.shooting == "single") options.shooting = ShootingChoice::kSingle;
  if (args.shooting == "multiple") options.shooting = ShootingChoice::kMultiple;
  options.sparse_solver = *LinearSolverFromString(args.linear_solver);
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
    return kExitOk;
  }
  if (args.compare_paper) {
    fmt::print("{}", PaperComparison(*preset, orbit, args.paper_choice ? std::string(preset->paper_choice_note) : "paper's data held"));
    return kExitOk;
  }
  fmt::print("signature  {}\nparameters {}\n", orbit.signature.ToString(), DescribeParameters(orbit.parameters));
  std::string unknowns;
  for (int index : start.free) unknowns += (unknowns.empty() ? "" : " ") + ov::Name(n, index);
  fmt::print("unknowns   {}{}\n", unknowns, start.unknowns.tie_static_friction ? " (u_r = u_s)" : "");
  fmt::print("newton     {} ({} shooting, {})\n", solution.summary.BriefReport(), ToString(solution.shooting),
             solution.shooting == Shooting::kMultiple ? args.linear_solver : "dense");
  fmt::print("solution   x10={} x20={} v10={} phi={}\n", orbit.x10, orbit.x20, orbit.v10, orbit.phi);
  for (int i = 0; i < n; ++i) {
    fmt::print("  d{} = {:<22} {}\n", i + 1, orbit.durations[i], ToString(orbit.signature.segments()[i]));
  }
  fmt::print("margins (positive = admissible; the smallest is the distance to a change of type)\n");
  for (const Margin& m : margins) {
    fmt::print("  {:<16} {:>14.6g}  at t = {:.6g}\n", m.Name(), m.value, m.t);
  }
  const Margin smallest = SmallestMargin(margins);
  fmt::print("smallest   {} = {:.6g}: {}\n", smallest.Name(), smallest.value,
             smallest.value > 0 ? "admissible" : "NOT a motion of the system");
  const Stability stability = StabilityOf(orbit);
  fmt::print("floquet multipliers (monodromy with saltation matrices){}:\n",
             stability.one_sided ? ", one-sided at the abnormal stops" : "");
  for (const std::complex<double>& mu : stability.multipliers) {
    fmt::print("  {:>+14.8f} {:+.8f}i  |mu| = {:.8f}\n", mu.real(), mu.imag(), std::abs(mu));
  }
  fmt::print("stability  {}\n", stability.stable ? "stable" : "unstable");
  fmt::print("verification {}\n{}", verification.Passed() ? "passed" : "FAILED", verification.Report());
  return kExitOk;
}

}  // namespace

Command AddSolveCommand(CLI::App& app) {
  auto args = std::make_shared<SolveArgs>();
  CLI::App* cmd = app.add_subcommand(
      "solve",
      "Solve the periodicity equations of an orbit type for one periodic orbit; print the "
      "unknowns, the Newton summary, the admissibility margins and a verification by the exact "
      "and the Odeint simulators. Exit code 3 if Newton does not converge.");
  AddStartOptions(*cmd, &args->start, StartOptions::kOrbit);
  cmd->add_option("--results", args->start.results, "where the runs of --point are stored")->capture_default_str();
  cmd->add_flag("--paper-choice", args->paper_choice,
                "with --preset: the paper's own choice where a round printed value looks held "
                "fixed (see README, errata)");
  cmd->add_option("--shooting", args->shooting,
                  "single (dense), multiple (block-sparse, SuiteSparse), or auto (single up to 6 "
                  "listed segments)")
      ->check(CLI::IsMember({"auto", "single", "multiple"}))
      ->capture_default_str();
  cmd->add_option("--linear-solver", args->linear_solver, "sparse solver for multiple shooting")
      ->check(CLI::IsMember({"klu", "umfpack", "dense"}))
      ->capture_default_str();
  cmd->add_flag("--json", args->json,
                "print one JSON object: signature, parameters, phi, x10, x20, v10, segments, "
                "converged, residual_norm, margins, verification");
  cmd->add_flag("--compare-paper", args->compare_paper,
                "with --preset: print a Markdown table of the paper's printed values beside "
                "stickslip's");
  return {cmd, [args] { return RunSolve(*args); }};
}

}  // namespace stickslip::cli
