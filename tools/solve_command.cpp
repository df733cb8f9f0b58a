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
#include "stickslip/orbits/margins.hpp"
#include "stickslip/orbits/orbit_solver.hpp"
#include "stickslip/orbits/paper_presets.hpp"
#include "stickslip/orbits/stability.hpp"
#include "stickslip/orbits/verification.hpp"

namespace stickslip::cli {

namespace {

namespace ov = orbit_variables;

struct SolveArgs {
  std::string preset;
  std::string signature;
  std::vector<std::string> assignments;
  std::vector<std::string> guesses;
  std::vector<std::string> release;
  std::vector<std::string> fixes;
  bool tie = false;
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
  if (args.preset.empty() == args.signature.empty()) {
    throw InputError("signature/preset: give exactly one of --preset NAME or --signature TEXT");
  }
  const PaperPreset* preset = args.preset.empty() ? nullptr : FindPaperPreset(args.preset);
  if (!args.preset.empty() && preset == nullptr) {
    throw InputError(fmt::format("preset = '{}' is unknown: valid presets paper-4.1, paper-4.2, "
                                 "paper-5.1, paper-5.2, paper-6", args.preset));
  }
  Orbit guess = [&] {
    if (preset != nullptr) return preset->Guess();
    std::string error;
    const std::optional<Signature> signature = Signature::Parse(args.signature, &error);
    if (!signature) throw InputError(error);
    return Orbit{*signature, {}, 0.0, 0.0, 0.0, 0.0, std::vector<double>(signature->size(), 0.0)};
  }();
  UnknownChoice choice;
  if (preset != nullptr) choice = args.paper_choice ? preset->paper_choice : preset->unknowns;
  // --set: the model data and start; --guess: any orbit variable (d1..dn too).
  const ModelInput input = ResolveModelInput(args.preset, args.assignments);
  guess.parameters = input.parameters;
  guess.x10 = input.initial_state(0);
  guess.x20 = input.initial_state(1);
  guess.v10 = input.initial_state(2);
  guess.phi = input.phi;
  if (input.initial_state(3) != 0.0) {
    throw InputError(fmt::format("v20 = {} is invalid: valid range v20 = 0 (an orbit starts at a stop)",
                                 input.initial_state(3)));
  }
  const int n = guess.signature.size();
  Eigen::VectorXd variables = ov::Pack(guess);
  auto assign = [&](const std::string& text, const char* option) {
    const auto equals = text.find('=');
    const std::string name = text.substr(0, equals);
    const std::optional<int> index = ov::IndexOf(n, name);
    if (equals == std::string::npos || !index) {
      std::string names;
      for (int i = 0; i < ov::Count(n); ++i) names += (i ? ", " : "") + ov::Name(n, i);
      throw InputError(fmt::format("{} '{}' is not NAME=VALUE with a variable: valid {}", option, text, names));
    }
    variables(*index) = ParseNumber(name, text.substr(equals + 1), "any finite number");
    return name;
  };
  for (const std::string& g : args.guesses) assign(g, "--guess");
  for (const std::string& f : args.fixes) {
    choice.fix.push_back(f.find('=') == std::string::npos ? f : assign(f, "--fix"));
  }
  for (const std::string& r : args.release) choice.release.push_back(r);
  if (args.tie) choice.tie_static_friction = true;
  guess = ov::Unpack(guess.signature, variables);
  if (choice.tie_static_friction) guess.parameters.u_r = guess.parameters.u_s;
  for (int i = 0; i < n; ++i) {
    if (guess.durations[i] <= 0.0) {
      throw InputError(fmt::format("d{} = {} is invalid: valid range d{} > 0 (give --guess d{}=VALUE)",
                                   i + 1, guess.durations[i], i + 1, i + 1));
    }
  }
  if (const auto invalid = Validate(guess.parameters)) throw InputError(invalid->what());
  const FreeVariables free = ResolveUnknowns(guess.signature, choice);
  if (!free.error.empty()) throw InputError(free.error);

  OrbitSolverOptions options;
  if (args.shooting == "single") options.shooting = ShootingChoice::kSingle;
  if (args.shooting == "multiple") options.shooting = ShootingChoice::kMultiple;
  options.sparse_solver = *LinearSolverFromString(args.linear_solver);
  const OrbitSolution solution = SolveOrbit(guess, free.indices, choice.tie_static_friction, options);
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
    if (preset == nullptr) throw InputError("compare-paper: needs --preset");
    fmt::print("{}", PaperComparison(*preset, orbit, args.paper_choice ? std::string(preset->paper_choice_note) : "paper's data held"));
    return kExitOk;
  }
  fmt::print("signature  {}\nparameters {}\n", orbit.signature.ToString(), DescribeParameters(orbit.parameters));
  std::string unknowns;
  for (int index : free.indices) unknowns += (unknowns.empty() ? "" : " ") + ov::Name(n, index);
  fmt::print("unknowns   {}{}\n", unknowns, choice.tie_static_friction ? " (u_r = u_s)" : "");
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
  cmd->add_option("--preset", args->preset,
                  "a paper orbit: paper-4.1, paper-4.2, paper-5.1, paper-5.2, paper-6 (data, "
                  "signature and printed values as guess)");
  cmd->add_option("--signature", args->signature,
                  "orbit type, e.g. \"slip- slip+ stick slip+\" or \"slip- stick slip- / "
                  "antisymmetric\" (options after '/': antisymmetric, period K)");
  cmd->add_option("--set", args->assignments, SetKeysHelp())->type_name("KEY=VALUE");
  cmd->add_option("--guess", args->guesses,
                  "starting value of any orbit variable: x10, x20, v10, phi, d1..dn (durations, "
                  "scaled time, > 0), chi, eta, omega, u_s, u_r")
      ->type_name("NAME=VALUE");
  cmd->add_option("--free", args->release,
                  "release a variable (usually a parameter: chi, eta, omega, u_s, u_r) as an unknown")
      ->type_name("NAME");
  cmd->add_option("--fix", args->fixes,
                  "hold a variable (phi, d1..dn, x10, ...) at its guess, or at VALUE")
      ->type_name("NAME[=VALUE]");
  cmd->add_flag("--tie-u_r", args->tie, "hold u_r = u_s (abnormal stops need it, eq. 25)");
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
