#include "stickslip/orbits/verification.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "stickslip/model/odeint_simulator.hpp"
#include "stickslip/model/simulation.hpp"
#include "stickslip/orbits/segment_walk.hpp"

namespace stickslip {

namespace {

std::string ModeList(const std::vector<Mode>& modes) {
  std::string text;
  for (Mode m : modes) text += fmt::format("{}{}", text.empty() ? "" : " ", ToString(m));
  return text;
}

// Consecutive equal modes merged: the sequence as a simulator that sees only crossings of
// x2' = 0 reports it (an abnormal stop is a tangency, invisible to sign changes).
std::vector<Mode> Merged(const std::vector<Mode>& modes) {
  std::vector<Mode> merged;
  for (Mode m : modes) {
    if (merged.empty() || merged.back() != m) merged.push_back(m);
  }
  return merged;
}

SimulatorCheck Check(const SimulationResult& r, const Orbit& orbit, std::vector<Mode> expected,
                     std::vector<double> event_times, bool sees_tangencies) {
  if (!sees_tangencies) {
    std::vector<double> crossing_times;
    for (std::size_t i = 0; i + 1 < expected.size(); ++i) {
      if (expected[i] != expected[i + 1]) crossing_times.push_back(event_times[i]);
    }
    event_times = crossing_times;
    expected = Merged(expected);
  }
  SimulatorCheck check;
  // A stop that falls a rounding error before the period's end opens a last sliver of segment;
  // it belongs to the next period.
  const double period = orbit.Period();
  for (const Segment& s : r.segments) {
    if (s.t_start < period - 1e-7) check.modes.push_back(s.mode);
  }
  if (!sees_tangencies) check.modes = Merged(check.modes);
  check.sequence_matches = check.modes == expected;
  const Segment& last = r.segments.back();
  State end = last.end;
  if (last.t_start >= period - 1e-7 && r.segments.size() > 1) {
    end = r.segments[r.segments.size() - 2].end;
  }
  check.periodicity_mismatch = (end - orbit.InitialState()).lpNorm<Eigen::Infinity>();
  if (check.sequence_matches) {
    std::size_t k = 0;
    for (const Event& e : r.events) {
      if (k + 1 >= expected.size() || k >= event_times.size()) break;
      if (!sees_tangencies && e.IsAbnormalStop()) continue;
      check.max_event_time_difference =
          std::max(check.max_event_time_difference, std::abs(e.t - event_times[k++]));
    }
  }
  return check;
}

}  // namespace

bool Verification::Passed() const {
  return not_simulated.empty() && exact.sequence_matches && odeint.sequence_matches &&
         exact.periodicity_mismatch <= kExactTolerance &&
         odeint.periodicity_mismatch <= kOdeintTolerance;
}

std::string Verification::Report() const {
  if (!not_simulated.empty()) return fmt::format("expected [{}]\nnot simulated: {}\n", ModeList(expected), not_simulated);
  auto line = [&](const char* name, const SimulatorCheck& c, double tolerance) {
    return fmt::format("{:<7} events [{}] {}; periodicity mismatch {:.2e} (<= {:.0e}: {}); event "
                       "times within {:.2e}\n",
                       name, ModeList(c.modes), c.sequence_matches ? "match" : "DIFFER",
                       c.periodicity_mismatch, tolerance,
                       c.periodicity_mismatch <= tolerance ? "ok" : "FAIL",
                       c.max_event_time_difference);
  };
  return fmt::format("expected [{}]\n", ModeList(expected)) +
         line("exact", exact, kExactTolerance) + line("odeint", odeint, kOdeintTolerance);
}

Verification VerifyOrbit(const Orbit& orbit) {
  Verification v;
  // The full period: the listed segments, mirrored when antisymmetric.
  v.expected = orbit.signature.FullPeriod();
  std::vector<double> event_times;
  WalkSegments(orbit, Extent::kFullPeriod, PhaseRule::kAccumulated,
               [&](const SegmentVisit<double>& s) { event_times.push_back(s.t0 + s.duration); });
  if (const auto invalid = Validate(orbit.parameters)) {
    v.not_simulated = fmt::format("the orbit is not a motion of the system: {}", invalid->what());
    return v;
  }
  SimulationOptions options;
  options.duration = orbit.Period();
  const SimulationResult exact = SimulateExact(orbit.parameters, orbit.InitialState(), orbit.phi, options);
  const SimulationResult odeint = SimulateOdeint(orbit.parameters, orbit.InitialState(), orbit.phi, options);
  for (const auto& [name, r] : {std::pair{"exact", &exact}, std::pair{"odeint", &odeint}}) {
    if (!r->Completed() || r->segments.empty()) {
      v.not_simulated = fmt::format("the {} simulation stopped early: {}", name, r->message);
      return v;
    }
  }
  v.exact = Check(exact, orbit, v.expected, event_times, /*sees_tangencies=*/true);
  v.odeint = Check(odeint, orbit, v.expected, event_times, /*sees_tangencies=*/false);
  return v;
}

}  // namespace stickslip
