// stickslip describe: a run file's [model] (io/model_table.hpp) as the program reads it: its
// coordinates, contact and forcing, every parameter with its unit, valid range and value, the
// natural frequencies of its slip and of its stick, and the names of its start-state columns.
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "cli_common.hpp"
#include "commands.hpp"
#include "stickslip/io/model_summary.hpp"

namespace stickslip::cli {

namespace {

std::string OscillationsText(const std::vector<FreeOscillation>& modes) {
  if (modes.empty()) return " none (the contact holds the only coordinate)";
  std::string out;
  for (const FreeOscillation& m : modes) {
    out += m.oscillates ? fmt::format(" {:.6g} (zeta {:.3g})", m.frequency, m.damping_ratio)
                        : fmt::format(" {:.6g} (real: {})", m.frequency, m.damping_ratio > 0.0 ? "a decay" : "a growth");  // K > 0: never 0
  }
  return out;
}

std::string Forcing(const ModelSummary& m) {
  std::vector<std::string> forced;
  for (Eigen::Index j = 0; j < m.data.forcing.size(); ++j) {
    if (m.data.forcing(j) != 0.0) forced.push_back(fmt::format("{} {:.6g} {}", m.description.coordinates[j], m.data.forcing(j), m.description.units.force));
  }
  return forced.empty() ? "none: autonomous (self-excited on a belt, v_b != 0)"
                        : fmt::format("{} times cos(omega t + phi)", fmt::join(forced, ", "));
}

std::string Text(const ModelSummary& m) {
  const ModelDescription& d = m.description;
  std::string out = fmt::format("model      {} of {} coordinate(s) {} ({})\n", m.table.kind, d.coordinates.size(),
                                fmt::join(d.coordinates, " "), m.table.path);
  out += fmt::format("contact    on {} (Coulomb: kinetic F_k{}, static F_s >= F_k; on a surface moving at v_b)\n",
                     d.coordinates.back(),
                     m.data.friction_slope != 0.0 ? fmt::format(" + {:.6g} |slip speed|", m.data.friction_slope) : "");
  out += fmt::format("forcing    {}\n", Forcing(m));
  out += "parameters\n";
  for (std::size_t k = 0; k < d.parameters.size(); ++k) {
    const ParameterDescription& p = d.parameters[k];
    const std::string value = m.values[k]                       ? fmt::format("{:.10g}", *m.values[k])
                              : p.name == "v_b"                  ? "0 (default)"
                              : k == 0 && m.Autonomous()          ? "- (no forcing)"
                                                                  : "- (not given)";
    out += fmt::format("  {:<6} {:>14} {:<6} {}; {}\n", p.name, value, p.unit, p.meaning, p.range);
  }
  out += fmt::format("free oscillations ({}, damping ratio)\n  slip:{}\n  stick ({} held):{}\n", d.units.Frequency(),
                     OscillationsText(m.slip), d.coordinates.back(), OscillationsText(m.stick));
  out += fmt::format("start state {}\n", fmt::join(d.initial_state, " "));
  return out;
}

struct DescribeArgs {
  std::string file;
  bool json = false;
};

}  // namespace

Command AddDescribeCommand(CLI::App& app) {
  auto args = std::make_shared<DescribeArgs>();
  CLI::App* cmd = app.add_subcommand(
      "describe",
      "Describe the oscillator of a run file's [model] table (a chain of masses, springs and dampers, or Matrix Market "
      "matrices; see the README): its coordinates, contact and forcing, each parameter with its unit (SI, or the "
      "[model]'s units), valid range and the file's value, the free oscillations of its slip and of its stick "
      "(frequency in rad per time unit, damping ratio) and its start-state names. Exit 2, with the file, line and key, for a [model] that is not valid.");
  cmd->add_option("file", args->file, "a run file with a [model] table")->required();
  cmd->add_flag("--json", args->json,
                "print one JSON object: model, kind, coordinates, contact, forcing (force per coordinate), friction_slope, units "
                "(length, time, force), "
                "parameters (name, meaning, unit, minimum, maximum, range, value or null), free_oscillations (slip, "
                "stick: frequency, damping_ratio, oscillates) and start_state");
  return {cmd, [args] {
            const ModelSummary m = SummarizeModel(args->file);
            fmt::print("{}", args->json ? ModelSummaryJson(m) + "\n" : Text(m));
            return kExitOk;
          }};
}

}  // namespace stickslip::cli
