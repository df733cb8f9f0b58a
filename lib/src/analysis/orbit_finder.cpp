#include "stickslip/analysis/orbit_finder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/model/simulation.hpp"
#include "stickslip/model/transient.hpp"
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

// Throws InvalidInput for options out of range, invalid parameters or a start outside kStateRange.
void ValidateInputs(const Parameters& parameters, const State& x0, double phi, const FindOrbitOptions& options) {
  options.Validate();
  if (auto invalid = Validate(parameters)) throw *invalid;
  const std::vector<std::string>& state_names = Pascal2014{}.Description().initial_state;
  for (int i = 0; i < x0.size(); ++i) {
    if (auto invalid = ValidateStateValue(state_names[i], x0(i))) throw *invalid;
  }
  if (auto invalid = ValidateStateValue("phi", phi)) throw *invalid;
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

// What the section of a record shows: the period detected (0 when none), its mismatch, or the
// smallest mismatch seen; the defaults are FindOrbitResult's, reported when no round completed.
struct SectionPeriod {
  int period_multiple = 0;
  double mismatch = 0.0;
  int closest_multiple = 0;
  bool antisymmetric = false;
  double antisymmetry_mismatch = 0.0;
  MotionType events;      // of the detected period
  std::string unsettled;  // why a section repeat was not taken (its events do not repeat with it)
};

// The forcing periods of the record: the section over (confirmations + 1) max_multiple periods,
// and the events of one period from an origin that may lie up to 2 k T in, with one period to spare.
int SectionPeriods(const FindOrbitOptions& options) { return (options.confirmations + 1) * options.max_multiple; }
int RecordPeriods(const FindOrbitOptions& options) {
  return std::max(SectionPeriods(options), 3 * options.max_multiple) + 1;
}

// The smallest k whose section repeats and whose events repeat with it (a section that repeats to
// a loose tolerance after fewer periods than the motion does has events that do not); else the
// smallest mismatch seen. The closest k and the antisymmetry of the last k read carry over from
// `previous` (the last round's) when no k improves on them.
SectionPeriod DetectPeriod(const SimulationResult& record, double period, const FindOrbitOptions& options,
                           SectionPeriod previous) {
  std::vector<State> section;
  for (int n = 0; n <= SectionPeriods(options); ++n) section.push_back(StateAt(record, n * period));
  const std::vector<double> mismatches = SectionMismatches(section, options);
  SectionPeriod found = std::move(previous);
  found.period_multiple = 0;
  found.mismatch = std::numeric_limits<double>::infinity();
  found.unsettled.clear();
  for (int k = 1; k <= options.max_multiple && found.period_multiple == 0; ++k) {
    if (mismatches[k - 1] < found.mismatch) {
      found.mismatch = mismatches[k - 1];
      found.closest_multiple = k;
    }
    if (mismatches[k - 1] > options.periodicity_tolerance) continue;
    found.period_multiple = k;
    found.mismatch = mismatches[k - 1];
    found.events = ReadMotionType(record, k, period,
                                  {options.periodicity_tolerance, options.confirmations, options.max_segments});
    found.antisymmetric = found.events.antisymmetric;
    found.antisymmetry_mismatch = found.events.antisymmetry_mismatch;
    if (found.events.unsettled) {
      found.unsettled = fmt::format("the section repeats after k = {} forcing periods to {:.3g}, but {}", k,
                                    mismatches[k - 1], found.events.problem);
      found.period_multiple = 0;
    }
  }
  return found;
}

// The transient of one settling round: `periods` forcing periods from `start`, its progress
// counted on from the `before` periods of the earlier rounds (done never decreases).
Transient SimulateRoundTransient(const Parameters& parameters, const State& start, double phi, int periods,
                                 int before, const FindOrbitOptions& options) {
  TransientOptions transient;
  transient.periods = periods;
  transient.simulation.max_events = options.max_events;
  if (options.progress) {
    transient.simulation.progress = [&options, before, periods](const Progress& p) {
      options.progress({before + p.done, static_cast<double>(before + periods), p.unit, p.value});
    };
  }
  return SimulateTransient(SimulateExact, parameters, start, phi, transient);
}

// The settling rounds' outcome: the last record and what its section shows, or why a simulation
// stopped early.
struct SettledRecord {
  std::string incomplete;  // "the transient simulation stopped early: ..."; empty when none did
  int transient_periods = 0;
  SimulationResult record;
  SectionPeriod section;
};

// No more rounds: the last one allowed, or a transient that cannot grow (none, or beyond kMaxTransient).
bool LastRound(int round, int next, int transient_periods, const FindOrbitOptions& options) {
  return round == options.settle_rounds || next == 0 ||
         transient_periods + 2 * next > FindOrbitOptions::kMaxTransient;
}

// The transient, then the record, whose section decides the period. Each simulation restarts the
// clock at a section time, where the forcing phase is phi again. While the section does not
// repeat, or its events do not repeat with it, the transient goes on, twice as long each round.
SettledRecord SettleOnSection(const Parameters& parameters, const State& x0, double phi,
                              const FindOrbitOptions& options) {
  const double period = 2.0 * std::numbers::pi / parameters.omega;
  SimulationOptions record_options;
  record_options.max_events = options.max_events;
  record_options.duration = RecordPeriods(options) * period;
  SettledRecord settled;
  State state = x0;
  for (int round = 0, next = options.transient_periods;; ++round, next *= 2) {
    const Transient transient =
        SimulateRoundTransient(parameters, state, phi, next, settled.transient_periods, options);
    if (!transient.Completed()) {
      settled.incomplete = fmt::format("the transient simulation stopped early: {}", transient.message);
      return settled;
    }
    state = transient.state;
    settled.transient_periods += next;
    settled.record = SimulateExact(parameters, state, phi, record_options);
    if (!settled.record.Completed()) {
      settled.incomplete = fmt::format("the recorded simulation stopped early: {}", settled.record.message);
      return settled;
    }
    settled.section = DetectPeriod(settled.record, period, options, std::move(settled.section));
    if (settled.section.period_multiple > 0 || LastRound(round, next, settled.transient_periods, options)) {
      return settled;
    }
  }
}

// The result's section fields, as the settling rounds left them.
FindOrbitResult SectionResult(const SettledRecord& settled) {
  FindOrbitResult result;
  result.transient_periods = settled.transient_periods;
  result.period_multiple = settled.section.period_multiple;
  result.mismatch = settled.section.mismatch;
  result.closest_multiple = settled.section.closest_multiple;
  result.antisymmetric = settled.section.antisymmetric;
  result.antisymmetry_mismatch = settled.section.antisymmetry_mismatch;
  return result;
}

std::string NotPeriodicMessage(const SectionPeriod& section, int transient_periods, const FindOrbitOptions& options) {
  if (!section.unsettled.empty()) {
    return fmt::format("the motion has not settled after {} transient periods: {}", transient_periods,
                       section.unsettled);
  }
  return fmt::format("the motion is not periodic with k <= {} forcing periods after {} transient periods: the "
                     "smallest section mismatch is {:.3g} (k = {}), above the tolerance {:g}",
                     options.max_multiple, transient_periods, section.mismatch, section.closest_multiple,
                     options.periodicity_tolerance);
}

// The orbit as the record shows it: the signature, the origin's state and phase, and the durations
// between the events of one period from the origin on.
Orbit ReadOffOrbit(const SimulationResult& record, const MotionType& events, const Parameters& parameters,
                   double phi) {
  const Event& origin = record.events[events.origin];
  Orbit orbit{*events.signature, parameters, origin.state(0), origin.state(1), origin.state(2),
              PhaseInCycle(parameters.omega * origin.t + phi), {}};
  for (int j = events.origin; j < events.origin + events.segments; ++j) {
    orbit.durations.push_back(record.events[j + 1].t - record.events[j].t);
  }
  return orbit;
}

// The solved orbit's status: a motion (every margin > 0) verified by both simulators, or why not.
FindOrbitResult ClassifySolution(FindOrbitResult result, const std::string& found) {
  const Orbit& orbit = result.solution->orbit;
  result.margins = AdmissibilityMargins(orbit);
  result.verification = VerifyOrbit(orbit);
  const Margin smallest = SmallestMargin(result.margins);
  result.status = FindOrbitStatus::kNotAMotion;
  if (!(smallest.value > 0.0)) {
    result.message = fmt::format("the motion is {}, but the solved orbit is not a motion of the system: margin {} = {:.6g}",
                                 found, smallest.Name(), smallest.value);
  } else if (!result.verification->Passed()) {
    result.message = fmt::format("the motion is {}, but the solved orbit failed its verification by simulation", found);
  } else {
    result.status = FindOrbitStatus::kFound;
    result.message = fmt::format("found {}, solved and verified", found);
  }
  return result;
}

// Newton on the periodicity equations from result.start, then the solution classified.
FindOrbitResult SolveFromStart(FindOrbitResult result, const FindOrbitOptions& options) {
  try {
    result.problem = BuildStartProblem(*result.start);
  } catch (const InvalidInput& e) {
    result.status = FindOrbitStatus::kNoOrbitType;
    result.message = fmt::format("the start read off the motion is refused: {}", e.what());
    return result;
  }
  const StartProblem& problem = *result.problem;
  result.solution = SolveOrbit(problem.orbit, problem.free, problem.unknowns.tie_static_friction, options.solver);
  const std::string found =
      fmt::format("{} (k = {}, section mismatch {:.2g})", result.start->signature, result.period_multiple, result.mismatch);
  if (!result.solution->summary.Converged()) {
    result.status = FindOrbitStatus::kSolveFailed;
    result.message = fmt::format("the motion is {}, but Newton did not converge from it: {}", found,
                                 result.solution->summary.BriefReport());
    return result;
  }
  return ClassifySolution(std::move(result), found);
}

}  // namespace

StartInput StartInputOf(const Orbit& orbit) {
  StartInput start;
  start.signature = orbit.signature.ToString();
  // The parameters as set, the start state, phase and durations as guesses, in the layout's order.
  const int n = orbit.signature.size();
  const Eigen::VectorXd variables = orbit_variables::Pack(orbit);
  for (int i = orbit_variables::FirstParameter(n); i < variables.size(); ++i) {
    start.set.emplace_back(orbit_variables::Name(n, i), variables(i));
  }
  for (int i = 0; i < orbit_variables::FirstParameter(n); ++i) {
    start.guess.emplace_back(orbit_variables::Name(n, i), variables(i));
  }
  const UnknownChoice unknowns = UnknownsAtFixedParameters(orbit.signature);
  start.free = unknowns.release;
  start.tie_u_r = unknowns.tie_static_friction;
  return start;
}

FindOrbitResult FindOrbit(const Parameters& parameters, const State& x0, double phi, const FindOrbitOptions& options) {
  ValidateInputs(parameters, x0, phi, options);
  const SettledRecord settled = SettleOnSection(parameters, x0, phi, options);
  FindOrbitResult result = SectionResult(settled);
  if (!settled.incomplete.empty()) {
    result.status = FindOrbitStatus::kSimulationIncomplete;
    result.message = settled.incomplete;
    return result;
  }
  const SectionPeriod& section = settled.section;
  if (section.period_multiple == 0) {
    result.status = FindOrbitStatus::kNotPeriodic;
    result.message = NotPeriodicMessage(section, result.transient_periods, options);
    return result;
  }
  if (!section.events.signature) {
    result.status = FindOrbitStatus::kNoOrbitType;
    result.message = fmt::format("the motion repeats after k = {} forcing periods, but {}", section.period_multiple,
                                 section.events.problem);
    return result;
  }
  const Event& origin = settled.record.events[section.events.origin];
  result.origin_time = origin.t;
  result.start = StartInputOf(ReadOffOrbit(settled.record, section.events, parameters, phi));
  return SolveFromStart(std::move(result), options);
}

}  // namespace stickslip
