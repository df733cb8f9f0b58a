#include "orbit_report.hpp"

#include <cmath>
#include <complex>

#include <fmt/format.h>

#include "cli_common.hpp"
#include "stickslip/branches/orbit_monitor.hpp"
#include "stickslip/orbits/orbit_measures.hpp"
#include "stickslip/orbits/stability.hpp"

namespace stickslip::cli {

std::string OrbitReport(const OrbitSolution& solution, const std::vector<int>& free, bool tie_static_friction,
                        std::string_view linear_solver, const std::vector<Margin>& margins,
                        const Verification& verification) {
  namespace ov = orbit_variables;
  const Orbit& orbit = solution.orbit;
  const int n = orbit.signature.size();
  std::string out = fmt::format("signature  {}\nparameters {}\n", orbit.signature.ToString(),
                                DescribeParameters(orbit.parameters));
  std::string unknowns;
  for (int index : free) unknowns += (unknowns.empty() ? "" : " ") + ov::Name(n, index);
  out += fmt::format("unknowns   {}{}\n", unknowns, tie_static_friction ? " (u_r = u_s)" : "");
  out += fmt::format("newton     {} ({} shooting, {})\n", solution.summary.BriefReport(), ToString(solution.shooting),
                     solution.shooting == Shooting::kMultiple ? linear_solver : "dense");
  out += fmt::format("solution   x10={} x20={} v10={} phi={}\n", orbit.x10, orbit.x20, orbit.v10, orbit.phi);
  for (int i = 0; i < n; ++i) {
    out += fmt::format("  d{} = {:<22} {}\n", i + 1, orbit.durations[i], ToString(orbit.signature.segments()[i]));
  }
  out += "margins (positive = admissible; the smallest is the distance to a change of type)\n";
  for (const Margin& m : margins) {
    out += fmt::format("  {:<16} {:>14.6g}  at t = {:.6g}\n", m.Name(), m.value, m.t);
  }
  const Margin smallest = SmallestMargin(margins);
  out += fmt::format("smallest   {} = {:.6g}: {}\n", smallest.Name(), smallest.value,
                     std::isnan(smallest.value) ? "not defined (its root search was cut short)"
                     : smallest.value > 0       ? "admissible"
                                                : "NOT a motion of the system");
  const Stability stability = StabilityOf(orbit);
  out += fmt::format("floquet multipliers (monodromy with saltation matrices){}:\n",
                     stability.one_sided ? ", one-sided at the abnormal stops" : "");
  for (const std::complex<double>& mu : stability.multipliers) {
    out += fmt::format("  {:>+14.8f} {:+.8f}i  |mu| = {:.8f}\n", mu.real(), mu.imag(), std::abs(mu));
  }
  out += fmt::format("stability  {}\n", stability.stable ? "stable" : "unstable");
  out += "measures over one period (exact: extrema of the closed forms)\n";
  const OrbitMeasures measures = Measure(orbit);
  orbit_columns::ForEachMeasure(measures, [&](const char* name, const auto& value) {
    out += fmt::format("  {:<16} {:>14.10g}\n", name, static_cast<double>(value));  // a count prints as one
  });
  out += fmt::format("verification {}\n{}", verification.Passed() ? "passed" : "FAILED", verification.Report());
  return out;
}

int SolvedOrbitOutcome(const std::vector<Margin>& margins, const Verification& verification) {
  const ExitWithReason outcome = SolvedOrbitExitCode(SmallestMargin(margins), verification);
  if (outcome.exit_code != kExitOk) fmt::print(stderr, "error: {}\n", outcome.reason);
  return outcome.exit_code;
}

}  // namespace stickslip::cli
