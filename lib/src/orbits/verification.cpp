#include "stickslip/orbits/verification.hpp"

#include <fmt/format.h>

#include "stickslip/model/exact_simulator.hpp"
#include "stickslip/model/odeint_simulation.hpp"

namespace stickslip {

namespace {

std::string ModeList(const std::vector<Mode>& modes) {
  std::string text;
  for (Mode m : modes) text += fmt::format("{}{}", text.empty() ? "" : " ", ToString(m));
  return text;
}

}  // namespace

std::vector<Mode> MergedModes(const std::vector<Mode>& modes) {
  std::vector<Mode> merged;
  for (Mode m : modes) {
    if (merged.empty() || merged.back() != m) merged.push_back(m);
  }
  return merged;
}

bool Verification::Passed() const {
  return not_simulated.empty() && exact.sequence_matches && odeint.sequence_matches &&
         exact.periodicity_mismatch <= kExactTolerance * scale &&
         odeint.periodicity_mismatch <= kOdeintTolerance * scale;
}

std::string Verification::Report() const {
  if (!not_simulated.empty()) return fmt::format("expected [{}]\nnot simulated: {}\n", ModeList(expected), not_simulated);
  auto line = [&](const char* name, const SimulatorCheck& c, double tolerance) {
    return fmt::format("{:<7} events [{}] {}; periodicity mismatch {:.2e} (<= {:.3g}: {}); event "
                       "times within {:.2e}\n",
                       name, ModeList(c.modes), c.sequence_matches ? "match" : "DIFFER",
                       c.periodicity_mismatch, tolerance,
                       c.periodicity_mismatch <= tolerance ? "ok" : "FAIL",
                       c.max_event_time_difference);
  };
  return fmt::format("expected [{}]\n", ModeList(expected)) +
         line("exact", exact, kExactTolerance * scale) + line("odeint", odeint, kOdeintTolerance * scale);
}

Verification VerifyOrbit(const Orbit& orbit) {
  return VerifyOrbit(
      Pascal2014{}, orbit.OnModel(),
      [](const Pascal2014& m, const Parameters& p, const State& x0, double phi, const SimulationOptions& options) {
        return SimulateExact(m, p, x0, phi, options);
      },
      [](const Pascal2014& m, const Parameters& p, const State& x0, double phi, const SimulationOptions& options) {
        return SimulateOdeint(m, p, x0, phi, options);
      });
}

}  // namespace stickslip
