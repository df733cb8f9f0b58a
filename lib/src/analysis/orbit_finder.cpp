#include "stickslip/analysis/orbit_finder.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/model/simulation.hpp"
#include "stickslip/analysis/motion_type.hpp"
#include "stickslip/orbits/signature.hpp"

namespace stickslip {

const char* ToString(FindOrbitStatus status) {
  switch (status) {
    case FindOrbitStatus::kFound: return "found";
    case FindOrbitStatus::kNotPeriodic: return "not-periodic";
    case FindOrbitStatus::kSimulationIncomplete: return "simulation-incomplete";
    case FindOrbitStatus::kNoOrbitType: return "no-orbit-type";
    case FindOrbitStatus::kSolveFailed: return "solve-failed";
    case FindOrbitStatus::kNotAMotion: break;
  }
  return "not-a-motion";
}

void FindOrbitOptions::Validate() const {
  auto check_int = [](const char* field, int value, int lo, int hi) {
    if (value < lo || value > hi) {
      throw InvalidInput(field, std::to_string(value), fmt::format("{} <= {} <= {}", lo, field, hi));
    }
  };
  check_int("transient_periods", transient_periods, 0, kMaxTransient);
  check_int("settle_rounds", settle_rounds, 0, 10);
  check_int("max_multiple", max_multiple, 1, kMaxMultiple);
  check_int("confirmations", confirmations, 1, kMaxConfirmations);
  check_int("max_segments", max_segments, 1, 1000);
  check_int("max_events", max_events, 1, 100000000);
  if (!(periodicity_tolerance >= kMinTolerance && periodicity_tolerance <= kMaxTolerance)) {
    throw InvalidInput("periodicity_tolerance", periodicity_tolerance,
                       fmt::format("{} <= periodicity_tolerance <= {}", kMinTolerance, kMaxTolerance));
  }
}

namespace {

double ReducedPhase(double phase) {
  double reduced = std::fmod(phase, 2.0 * std::numbers::pi);
  if (reduced < 0.0) reduced += 2.0 * std::numbers::pi;
  return reduced;
}

// The section mismatch of every k = 1..max_multiple (index k - 1): the largest relative distance
// between section points k periods apart, over `confirmations` periods of k T.
std::vector<double> SectionMismatches(const std::vector<State>& section, const FindOrbitOptions& options) {
  std::vector<double> mismatches;
  for (int k = 1; k <= options.max_multiple; ++k) {
    double mismatch = 0.0;
    for (int n = 0; n < options.confirmations * k; ++n) {
      mismatch = std::max(mismatch, RelativeDistance(section[n + k], section[n]));
    }
    mismatches.push_back(mismatch);
  }
  return mismatches;
}

}  // namespace

StartInput StartInputOf(const Orbit& orbit) {
  StartInput start;
  start.signature = orbit.signature.ToString();
  for (ParameterId id : kAllParameters) start.set.emplace_back(ToString(id), orbit.parameters[id]);
  start.guess = {{"x10", orbit.x10}, {"x20", orbit.x20}, {"v10", orbit.v10}, {"phi", orbit.phi}};
  for (std::size_t i = 0; i < orbit.durations.size(); ++i) {
    start.guess.emplace_back(fmt::format("d{}", i + 1), orbit.durations[i]);
  }
  for (int i = 0; i < orbit.signature.size(); ++i) {
    if (orbit.signature.EndKind(i) == SegmentEndKind::kAbnormalStop) {
      start.free = {"u_s"};
      start.tie_u_r = true;
    }
  }
  return start;
}

FindOrbitResult FindOrbit(const Parameters& parameters, const State& x0, double phi, const FindOrbitOptions& options) {
  options.Validate();
  if (auto invalid = Validate(parameters)) throw *invalid;
  constexpr std::array<const char*, 4> kStateNames = {"x10", "x20", "v10", "v20"};
  for (int i = 0; i < 4; ++i) {
    if (auto invalid = ValidateStateValue(kStateNames[i], x0(i))) throw *invalid;
  }
  if (auto invalid = ValidateStateValue("phi", phi)) throw *invalid;

  FindOrbitResult result;
  const double period = 2.0 * std::numbers::pi / parameters.omega;
  SimulationOptions sim;
  sim.max_events = options.max_events;
  auto incomplete = [&](const char* which, const std::string& why) {
    result.status = FindOrbitStatus::kSimulationIncomplete;
    result.message = fmt::format("the {} simulation stopped early: {}", which, why);
    return result;
  };

  // The transient, then the record: the section over (confirmations + 1) max_multiple periods,
  // and the events of one period from an origin that may lie up to 2 k T in, with one period to
  // spare. Each simulation restarts the clock at a section time, where the forcing phase is phi
  // again. While the section does not repeat, or its events do not repeat with it, the transient
  // goes on, twice as long each round.
  const int k_max = options.max_multiple;
  const int recorded = (options.confirmations + 1) * k_max;
  const int record_periods = std::max(recorded, 3 * k_max) + 1;
  State settled = x0;
  SimulationResult record;
  std::vector<State> section;
  MotionType period_events;
  std::string unsettled;  // why the last round's section repeat was not taken
  int next = options.transient_periods;
  for (int round = 0;; ++round) {
    TransientOptions transient;
    transient.periods = next;
    transient.simulation = sim;
    if (options.progress) {  // counted over every round: done never decreases
      transient.simulation.progress = [&options, before = result.transient_periods, next](const Progress& p) {
        options.progress({before + p.done, static_cast<double>(before + next), p.unit, p.value});
      };
    }
    const Transient settling = SimulateTransient(SimulateExact, parameters, settled, phi, transient);
    if (!settling.Completed()) return incomplete("transient", settling.message);
    settled = settling.state;
    result.transient_periods += next;
    sim.duration = record_periods * period;
    record = SimulateExact(parameters, settled, phi, sim);
    if (!record.Completed()) return incomplete("recorded", record.message);
    section.clear();
    for (int n = 0; n <= recorded; ++n) section.push_back(StateAt(record, n * period));
    // The smallest k whose section repeats and whose events repeat with it (a section that
    // repeats to a loose tolerance after fewer periods than the motion does has events that do
    // not); else the smallest mismatch seen.
    const std::vector<double> mismatches = SectionMismatches(section, options);
    result.period_multiple = 0;
    result.mismatch = std::numeric_limits<double>::infinity();
    unsettled.clear();
    for (int k = 1; k <= k_max && result.period_multiple == 0; ++k) {
      if (mismatches[k - 1] < result.mismatch) {
        result.mismatch = mismatches[k - 1];
        result.closest_multiple = k;
      }
      if (mismatches[k - 1] > options.periodicity_tolerance) continue;
      result.period_multiple = k;
      result.mismatch = mismatches[k - 1];
      period_events = ReadMotionType(record, k, period,
                                     {options.periodicity_tolerance, options.confirmations, options.max_segments});
      result.antisymmetric = period_events.antisymmetric;
      result.antisymmetry_mismatch = period_events.antisymmetry_mismatch;
      if (period_events.unsettled) {
        unsettled = fmt::format("the section repeats after k = {} forcing periods to {:.3g}, but {}", k,
                                mismatches[k - 1], period_events.problem);
        result.period_multiple = 0;
      }
    }
    if (result.period_multiple > 0) break;
    if (round == options.settle_rounds || next == 0 || result.transient_periods + 2 * next > FindOrbitOptions::kMaxTransient) {
      break;
    }
    next *= 2;
  }
  const int k = result.period_multiple;
  if (k == 0) {
    result.status = FindOrbitStatus::kNotPeriodic;
    result.message =
        unsettled.empty()
            ? fmt::format("the motion is not periodic with k <= {} forcing periods after {} transient periods: the "
                          "smallest section mismatch is {:.3g} (k = {}), above the tolerance {:g}",
                          k_max, result.transient_periods, result.mismatch, result.closest_multiple,
                          options.periodicity_tolerance)
            : fmt::format("the motion has not settled after {} transient periods: {}", result.transient_periods,
                          unsettled);
    return result;
  }
  if (!period_events.signature) {
    result.status = FindOrbitStatus::kNoOrbitType;
    result.message = fmt::format("the motion repeats after k = {} forcing periods, but {}", k, period_events.problem);
    return result;
  }
  const int first = period_events.origin;
  const int m = period_events.segments;
  const Signature& signature = *period_events.signature;

  const Event& origin = record.events[first];
  result.origin_time = origin.t;
  Orbit read_off{signature, parameters, origin.state(0), origin.state(1), origin.state(2),
                 ReducedPhase(parameters.omega * origin.t + phi), {}};
  for (int j = first; j < first + m; ++j) read_off.durations.push_back(record.events[j + 1].t - record.events[j].t);
  const StartInput start = StartInputOf(read_off);
  result.start = start;

  try {
    result.problem = BuildStartProblem(start);
  } catch (const InvalidInput& e) {
    result.status = FindOrbitStatus::kNoOrbitType;
    result.message = fmt::format("the start read off the motion is refused: {}", e.what());
    return result;
  }
  const StartProblem& problem = *result.problem;
  result.solution = SolveOrbit(problem.orbit, problem.free, problem.unknowns.tie_static_friction, options.solver);
  const std::string found = fmt::format("{} (k = {}, section mismatch {:.2g})", start.signature, k, result.mismatch);
  if (!result.solution->summary.Converged()) {
    result.status = FindOrbitStatus::kSolveFailed;
    result.message = fmt::format("the motion is {}, but Newton did not converge from it: {}", found,
                                 result.solution->summary.BriefReport());
    return result;
  }
  const Orbit& orbit = result.solution->orbit;
  result.margins = AdmissibilityMargins(orbit);
  result.verification = VerifyOrbit(orbit);
  const Margin smallest = SmallestMargin(result.margins);
  if (!(smallest.value > 0.0)) {
    result.status = FindOrbitStatus::kNotAMotion;
    result.message = fmt::format("the motion is {}, but the solved orbit is not a motion of the system: margin {} = {:.6g}",
                                 found, smallest.Name(), smallest.value);
  } else if (!result.verification->Passed()) {
    result.status = FindOrbitStatus::kNotAMotion;
    result.message = fmt::format("the motion is {}, but the solved orbit failed its verification by simulation", found);
  } else {
    result.status = FindOrbitStatus::kFound;
    result.message = fmt::format("found {}, solved and verified", found);
  }
  return result;
}

}  // namespace stickslip
