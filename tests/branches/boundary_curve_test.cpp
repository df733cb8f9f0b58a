// Type boundaries in two parameters (margin = 0, branches/margin_condition.hpp), each against
// something independent: the located points of the stored one-parameter runs on the lines the
// curves cross, the exact simulator started on orbits of the curves, the curves meeting at a
// codimension-two point found from each side, and the zero-length-stick construction.
#include "stickslip/branches/boundary_curve.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <set>

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include "stickslip/branches/margin_condition.hpp"
#include "stickslip/branches/type_switch.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/io/result_files.hpp"
#include "stickslip/io/run.hpp"
#include "stickslip/orbits/adjacent_type.hpp"
#include "stickslip/model/pascal_2014/events.hpp"
#include "stickslip/model/simulation.hpp"
#include "stickslip/orbits/orbit_measures.hpp"
#include "support/restart_in_omega.hpp"

namespace stickslip {
namespace {

namespace fs = std::filesystem;

fs::path Results() { return fs::path(STICKSLIP_SOURCE_DIR) / "results"; }

// A curve as a run file's restart = { run, label, boundary = "u_r" } starts it, continued in
// omega the way `direction` says, with user values of omega.
OrbitContinuationSetup CurveFrom(const std::string& run, const std::string& label, int direction,
                                 const NamedValues& user_values = {}) {
  RunFile file = RestartInOmega(run, label);
  file.restart_boundary = "u_r";
  file.direction = direction;
  file.steps.ds = 0.005;
  file.steps.ds_max = 0.02;
  file.steps.max_points = 400;
  file.user_values = user_values;
  return MakeSetup(file, Results());
}

double Stored(const std::string& run, const std::string& label, const std::string& name) {
  for (const auto& [key, value] : ReadLabelledPoint(Results(), run, label).variables) {
    if (key == name) return value;
  }
  throw std::runtime_error(name + " not stored at " + run + ":" + label);
}

const SpecialPoint& Special(const OrbitBranch& curve, const std::string& type) {
  for (const SpecialPoint& s : curve.branch.special_points) {
    if (s.type == type) return s;
  }
  throw std::runtime_error("no " + type + " on the curve: " + curve.branch.end_message);
}

double MarginOf(const Orbit& orbit, const std::string& name) {
  for (const Margin& m : AdmissibilityMargins(orbit)) {
    if (m.Name() == name) return m.value;
  }
  throw std::runtime_error("no margin " + name);
}

// The exact simulator started on `orbit` of the curve of `condition` (tau: the condition's
// extremum time, if interior) shows the degeneracy the margin names. A grazing of G or G1 inside a
// stick keeps the motion on the orbit: over one period it closes. A grazing of x2' inside a slip
// brings the mass to rest with |s| = eta u_s < eta u_r (x2'' = 0 there): the simulator stops and
// sticks at the grazing (grazing-sliding, the adjacent type). At a stop or a stick exit it is
// followed to the orbit's degenerate end (the modes before it are the orbit's), where the force
// is at the static level; what follows is the boundary's business (at the §5.1 reversal boundary
// the mass sticks there, as the switch found: lib/README.md, switching table).
void ExpectSimulatorShowsTheDegeneracy(const Orbit& orbit, const MarginCondition& condition, double tau) {
  const Parameters& p = orbit.parameters;
  const std::string name = condition.Name().substr(std::string("margin:").size());
  const int i = std::stoi(name.substr(name.find(':') + 1)) - 1;
  double t0 = 0.0;
  for (int k = 0; k < i; ++k) t0 += orbit.durations[k];
  const double t_end = t0 + orbit.durations[i];
  // A stick of zero length: the degenerate end is the stop before it.
  const bool stick_duration = name.starts_with("duration");
  const int last = stick_duration ? i - 1 : i;
  SimulationOptions options;
  options.duration = condition.Interior() ? orbit.Period() : t_end;
  const SimulationResult sim = SimulateExact(p, orbit.InitialState(), orbit.phi, options);
  ASSERT_TRUE(sim.Completed()) << sim.message;
  if (name.starts_with("G")) {
    EXPECT_LT((StateAt(sim, options.duration) - orbit.InitialState()).norm(), 1e-8) << "the orbit does not close";
  } else if (!condition.Interior()) {
    // (The degenerate event itself may be found a rounding before t_end: a last segment then
    // starts there.)
    ASSERT_GE(last, 0);
    ASSERT_GE(sim.segments.size(), static_cast<std::size_t>(last + 1));
    for (int k = 0; k <= last; ++k) EXPECT_EQ(sim.segments[k].mode, orbit.signature.segments()[k]);
    // A tangential exit is a double root of |s| - eta u_r: the simulator locates it to about the
    // square root of rounding (measured 2e-8 here); a transversal end to 1e-9.
    EXPECT_NEAR(sim.segments[last].t_end, t_end, name.starts_with("exit-slope") ? 1e-7 : 1e-9);
  }
  auto force = [&](double t) { return StickForce(StateAt(sim, t), p.omega * t + orbit.phi, p); };
  auto force_rate = [&](double t) { return StickForceRate(StateAt(sim, t), p.omega * t + orbit.phi, p); };
  const double level = p.eta * p.u_r;
  if (name.starts_with("reversal") || stick_duration) {
    // The force at the simulated stop is the static level.
    EXPECT_NEAR(std::abs(force(t_end)), level, 1e-9 * level);
  } else if (name.starts_with("exit-slope")) {
    // s reaches the static level tangentially where the simulator leaves the stick (its rate
    // there to |s''| times that time's uncertainty).
    const double t_exit = sim.segments[i].t_end;
    EXPECT_NEAR(std::abs(force(t_exit)), level, 1e-9 * level);
    EXPECT_NEAR(force_rate(t_exit), 0.0, 1e-6);
  } else if (name.starts_with("G")) {
    // Inside the stick the simulated force reaches the static level tangentially, and stays
    // within it elsewhere.
    const double t = t0 + tau;
    ASSERT_GT(tau, 0.0);
    ASSERT_LT(t, t_end);
    EXPECT_NEAR(std::abs(force(t)), level, 1e-9 * level);
    EXPECT_NEAR(force_rate(t), 0.0, 1e-8);
    for (int k = 1; k < 200; ++k) EXPECT_LE(std::abs(force(t0 + (t_end - t0) * k / 200.0)), level * (1 + 1e-12));
  } else if (name.starts_with("velocity")) {
    // x2' touches zero inside the slip, keeping its sign before; the simulator stops there (a
    // double root of x2', located to about the square root of rounding) and sticks.
    const double t = t0 + tau;
    EXPECT_NEAR(StateAt(sim, t)(3), 0.0, 1e-9);
    const auto stop = std::find_if(sim.events.begin(), sim.events.end(),
                                   [&](const Event& e) { return std::abs(e.t - t) < 1e-7; });
    ASSERT_NE(stop, sim.events.end()) << "no stop at the grazing";
    EXPECT_EQ(stop->kind, EventKind::kStop);
    EXPECT_EQ(stop->mode_after, Mode::kStick);
    for (int k = 1; k < 200; ++k) {
      const double tk = t0 + (stop->t - t0) * k / 200.0;
      EXPECT_GE(SlipDirection(orbit.signature.segments()[i]) * StateAt(sim, tk)(3), -1e-12);
    }
  } else {
    ADD_FAILURE() << "no simulator check for " << name;
  }
}

// Along the curve, at points between its ends (its codimension-two points): the margin is zero
// (1e-10), so is everything the condition says sits on zero with it, and nothing else is; the
// exact simulator shows the degeneracy.
void ExpectAlongTheCurve(const OrbitBranch& curve, const OrbitContinuationSetup& setup) {
  const auto* condition = dynamic_cast<const MarginCondition*>(setup.condition.get());
  ASSERT_NE(condition, nullptr);
  const std::vector<std::string> defining = condition->Defining();
  const std::set<std::string> zero_columns(defining.begin(), defining.end());
  const int count = static_cast<int>(curve.orbits.size());
  ASSERT_GE(count, 12) << curve.branch.end_message;
  const int unknowns = static_cast<int>(curve.branch.points[0].u.size());
  for (int k = 1; k <= 5; ++k) {
    const int at = k * (count - 1) / 6;
    const Orbit& orbit = curve.orbits[at];
    SCOPED_TRACE(testing::Message() << condition->Name() << " at omega = " << orbit.parameters.omega
                                    << ", u_r = " << orbit.parameters.u_r);
    for (const Margin& m : AdmissibilityMargins(orbit)) {
      const std::string column = "margin:" + m.Name();
      if (zero_columns.count(column)) {
        EXPECT_NEAR(m.value, 0.0, 1e-10) << column;
      } else {
        EXPECT_GT(std::abs(m.value), 1e-6) << column << " is zero too";
      }
    }
    const double tau = condition->Interior() ? curve.branch.points[at].u(unknowns - 1) : 0.0;
    ExpectSimulatorShowsTheDegeneracy(orbit, *condition, tau);
  }
}

struct Crossing {
  const char* run;    // the curve starts at run:label, a located type change in omega ...
  const char* label;
  int direction;      // ... and runs this way in omega
  double omega;       // to the line omega = const of a u_r run,
  const char* u_run;  // whose located change of the same margin is at u_run:u_label
  const char* u_label;
};

TEST(BoundaryCurve, PassesThroughTheLocatedPointsOfTheOneParameterRuns) {
  for (const Crossing& c : {
           // end margins: a reversal (§5.1 and §4.1, crossing-sliding) and a stick's exit slope (§5.1)
           Crossing{"paper-5.1-omega-down", "SK2", 1, 0.5711986642890533, "paper-5.1-u_r-down", "SK2"},
           Crossing{"paper-4.1-omega-down", "SK2", 1, 0.6, "paper-4.1-u_r-up", "SK2"},
           Crossing{"paper-5.1-omega-up", "GR6", -1, 0.5711986642890533, "paper-5.1-u_r-up", "GR4"},
           Crossing{"paper-5.1-omega-up", "GR6", 1, 0.58, "paper-5.1-u_r-from-uz", "GR2"},
           // an interior extremum: G grazing zero inside the §5.2 stick
           Crossing{"paper-5.2-omega-down", "GR2", 1, 0.66, "paper-5.2-u_r-up", "GR2"},
       }) {
    SCOPED_TRACE(testing::Message() << c.run << ":" << c.label << " to " << c.u_run << ":" << c.u_label);
    const OrbitContinuationSetup setup = CurveFrom(c.run, c.label, c.direction, {{"omega", c.omega}});
    EXPECT_EQ(setup.condition->Name(), ReadLabelledPoint(Results(), c.u_run, c.u_label).test_function);
    const OrbitBranch curve = ContinueOrbit(setup);
    const SpecialPoint& uz = Special(curve, "UZ");
    const Orbit& at = curve.orbits[uz.point];
    const double located = Stored(c.u_run, c.u_label, "u_r");
    std::printf("%s %s:%s at omega = %.10g: u_r %.16g, stored %.16g, difference %.2e\n", setup.condition->Name().c_str(),
                c.run, c.label, c.omega, at.parameters.u_r, located, at.parameters.u_r - located);
    EXPECT_NEAR(at.parameters.omega, c.omega, 1e-14);
    EXPECT_NEAR(at.parameters.u_r, located, 1e-9);
    ExpectAlongTheCurve(curve, setup);
  }
}

// The first special point whose test function is `column`.
const SpecialPoint& Where(const OrbitBranch& curve, const std::string& column) {
  for (const SpecialPoint& s : curve.branch.special_points) {
    if (s.test_function == column) return s;
  }
  throw std::runtime_error(column + " not on the curve: " + curve.branch.end_message);
}

// Where the curve of `first` ends at a sign change of `second`: both margins zero there (1e-9).
Parameters CodimensionTwoPoint(const OrbitBranch& curve, const std::string& first, const std::string& second) {
  const SpecialPoint& s = Where(curve, "margin:" + second);
  EXPECT_TRUE(s.located);
  const Orbit& orbit = curve.orbits[s.point];
  EXPECT_NEAR(MarginOf(orbit, first), 0.0, 1e-9) << first;
  EXPECT_NEAR(MarginOf(orbit, second), 0.0, 1e-9) << second;
  std::printf("%s meets %s at omega = %.16g, u_r = %.16g (margins %.1e, %.1e)\n", first.c_str(), second.c_str(),
              orbit.parameters.omega, orbit.parameters.u_r, MarginOf(orbit, first), MarginOf(orbit, second));
  return orbit.parameters;
}

void ExpectSamePoint(const Parameters& a, const Parameters& b) {
  std::printf("  from each side: omega differs by %.2e, u_r by %.2e\n", a.omega - b.omega, a.u_r - b.u_r);
  EXPECT_NEAR(a.omega, b.omega, 1e-9);
  EXPECT_NEAR(a.u_r, b.u_r, 1e-9);
}

TEST(BoundaryCurve, CurvesMeetingAtACodimensionTwoPointFindItFromEachSide) {
  // §5.1: the crossing-sliding boundary (reversal:1, from the omega branch's SK2) and the
  // tangential stick exit (exit-slope:3, from GR6), both followed down in omega, each end where
  // the other's margin changes sign.
  const Parameters from_reversal =
      CodimensionTwoPoint(ContinueOrbit(CurveFrom("paper-5.1-omega-down", "SK2", -1)), "reversal:1", "exit-slope:3");
  const Parameters from_exit =
      CodimensionTwoPoint(ContinueOrbit(CurveFrom("paper-5.1-omega-up", "GR6", -1)), "exit-slope:3", "reversal:1");
  ExpectSamePoint(from_reversal, from_exit);

  // §4.1: the crossing-sliding boundary, down in omega, ends where x2' grazes zero inside the slip
  // (paper-4.1-sk-boundary's NS). The grazing's own curve, started where an omega branch at
  // u_r = 0.11 locates it, reaches the same point. (It is the line omega = const: the slip orbit
  // does not depend on u_r, only its reversal margin does; so the omega branch locates the
  // grazing at the codimension-two point's omega too. u_r >= u_s = 0.1 leaves it short: small
  // steps.)
  const Parameters from_sk =
      CodimensionTwoPoint(ContinueOrbit(CurveFrom("paper-4.1-omega-down", "SK2", -1)), "reversal:1", "velocity:1");
  RunFile file = ReadRunFile(fs::path(STICKSLIP_SOURCE_DIR) / "continuation-scripts" / "paper-4.1-omega-down.toml");
  file.set.emplace_back("u_r", 0.11);
  const OrbitContinuationSetup branch_setup = MakeSetup(file, Results());
  const OrbitBranch branch = ContinueOrbit(branch_setup);
  const LocatedTypeChange grazing = TypeChangeAt(branch, Where(branch, "margin:velocity:1"), branch_setup);
  std::printf("velocity:1 located on the omega branch at u_r = 0.11: omega = %.16g\n", grazing.orbit.parameters.omega);
  const CurveStart start{.orbit = grazing.orbit, .condition = "margin:velocity:1", .parameter = "omega",
                         .unknowns = branch_setup.unknowns};
  OrbitContinuationSetup velocity = BoundaryCurve(start, branch_setup, "u_r");
  EXPECT_TRUE(dynamic_cast<const MarginCondition&>(*velocity.condition).Interior());
  velocity.options.direction = 1;
  velocity.options.step.ds = 0.0005;
  velocity.options.step.ds_max = 0.001;
  const OrbitBranch velocity_curve = ContinueOrbit(velocity);
  EXPECT_NEAR(grazing.orbit.parameters.omega, from_sk.omega, 1e-9);
  ExpectSamePoint(from_sk, CodimensionTwoPoint(velocity_curve, "velocity:1", "reversal:1"));
  ExpectAlongTheCurve(velocity_curve, velocity);
}

// The u_r of the curve of `setup` at each of `omegas` (user values), continued `direction`.
std::vector<double> CurveAt(OrbitContinuationSetup setup, int direction, const std::vector<double>& omegas) {
  setup.options.direction = direction;
  setup.options.max_points = 400;
  setup.options.step.ds = 0.005;
  setup.options.step.ds_max = 0.02;
  const int lambda =
      static_cast<int>(FreeIndices(setup.start.signature, setup.unknowns).size());
  for (double omega : omegas) setup.options.user_values.push_back({lambda, omega, "omega"});
  const OrbitBranch curve = ContinueOrbit(setup);
  std::vector<double> u_r;
  for (const SpecialPoint& s : curve.branch.special_points) {
    if (s.type == "UZ") u_r.push_back(curve.orbits[s.point].parameters.u_r);
  }
  EXPECT_EQ(u_r.size(), omegas.size()) << curve.branch.end_message;
  return u_r;
}

// The zero-length-stick construction of a crossing-sliding boundary (what branches/type_boundary
// did before margin = 0): the adjacent type with the stick crossing-sliding inserts after the stop,
// of zero length (orbits/adjacent_type.hpp), held there: the curve of that stick's duration.
CurveStart ZeroLengthStick(const OrbitContinuationSetup& branch, const std::string& margin) {
  const std::vector<Margin> margins = AdmissibilityMargins(branch.start);
  const auto m = std::find_if(margins.begin(), margins.end(), [&](const Margin& x) { return x.Name() == margin; });
  const bool equal_friction = branch.start.parameters.u_r == branch.start.parameters.u_s;
  for (const AdjacentType& a : AdjacentTypes(m->base, m->segment, branch.start.signature, equal_friction)) {
    if (a.kind != TypeEdit::kInsert || a.edit.signature.segments()[a.new_segment] != Mode::kStick) continue;
    UnknownChoice unknowns = branch.unknowns;
    for (std::string& name : unknowns.fix) name = a.edit.Renamed(name);
    for (std::string& name : unknowns.release) name = a.edit.Renamed(name);
    return {.orbit = AdjacentStart(branch.start, *m, a),
            .condition = "margin:duration:" + std::to_string(a.new_segment + 1),
            .parameter = "omega",
            .unknowns = unknowns};
  }
  throw std::runtime_error("no stick inserted at " + margin);
}

TEST(BoundaryCurve, AgreesWithTheZeroLengthStickConstruction) {
  // The crossing-sliding boundaries of §4.1 and §5.1: reversal:1 = 0 on the located type against
  // the adjacent type's inserted stick held at zero length (its duration = 0, T0), at three values
  // of omega each way (within the curves' ends: the zero-length stick's exit becomes tangential
  // at omega = 0.5773647 on §4.1, below).
  struct Case {
    const char* run;
    double step;  // between the values of omega
  };
  for (const Case c : {Case{"paper-4.1-omega-down", 0.007}, Case{"paper-5.1-omega-down", 0.003}}) {
    const OrbitContinuationSetup branch = MakeSetup(RestartInOmega(c.run, "SK2"), Results());
    const OrbitContinuationSetup margin = BoundaryCurve(
        {.orbit = branch.start, .condition = "margin:reversal:1", .parameter = "omega", .unknowns = branch.unknowns},
        branch, "u_r");
    const OrbitContinuationSetup stick = BoundaryCurve(ZeroLengthStick(branch, "reversal:1"), branch, "u_r");
    const double omega = branch.start.parameters.omega;
    for (const int direction : {1, -1}) {
      std::vector<double> omegas;
      for (int k = 1; k <= 3; ++k) omegas.push_back(omega + direction * c.step * k);
      const std::vector<double> a = CurveAt(margin, direction, omegas);
      const std::vector<double> b = CurveAt(stick, direction, omegas);
      for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k) {
        std::printf("%s:SK2 reversal:1 at omega = %.6g: u_r %.16g, zero-length stick %.16g, difference %.2e\n", c.run,
                    omegas[k], a[k], b[k], a[k] - b[k]);
        EXPECT_NEAR(a[k], b[k], 1e-9);
      }
    }
  }
  // The §4.1 sticking type's own zero-length stick (the trace's second branch starts on it):
  // along its T0 curve the stick's entry force and its ending constraint G1:2 sit on zero with
  // its duration, and nothing else does; down in omega the curve ends where the zero-length
  // stick's exit becomes tangential (which the reversal:1 curve of the nonsticking type, without
  // that stick, does not see).
  const OrbitContinuationSetup branch = MakeSetup(RestartInOmega("branch-2", "EP1"), Results() / "paper-4.1-omega-trace");
  OrbitContinuationSetup up = BoundaryCurve(
      {.orbit = branch.start, .condition = "margin:duration:2", .parameter = "omega", .unknowns = branch.unknowns}, branch,
      "u_r");
  up.options.max_points = 40;
  ExpectAlongTheCurve(ContinueOrbit(up), up);
  OrbitContinuationSetup down = up;
  down.options.direction = -1;
  CodimensionTwoPoint(ContinueOrbit(down), "duration:2", "exit-slope:2");
}

// max |x1|, |x2| of the exact simulator started on `orbit`, sampled 20000 times over a period (the
// sampled maximum is below the true one by about A (omega dt)^2/8: 1e-8 relative), and the state's
// distance from its start after the period.
struct SimulatedPeriod {
  double amplitude_x1 = 0.0;
  double amplitude_x2 = 0.0;
  double closure = 0.0;
};
SimulatedPeriod SimulatePeriod(const Orbit& orbit) {
  SimulationOptions options;
  options.duration = orbit.Period();
  options.sample_step = orbit.Period() / 20000.0;
  const SimulationResult sim = SimulateExact(orbit.parameters, orbit.InitialState(), orbit.phi, options);
  EXPECT_TRUE(sim.Completed()) << sim.message;
  SimulatedPeriod period;
  for (const TimeSample& sample : sim.samples) {
    period.amplitude_x1 = std::max(period.amplitude_x1, std::abs(sample.state(0)));
    period.amplitude_x2 = std::max(period.amplitude_x2, std::abs(sample.state(1)));
  }
  period.closure = (StateAt(sim, options.duration) - orbit.InitialState()).norm();
  return period;
}

// A curve heading for a natural frequency ends at the resonance (OrbitContinuationSetup::
// max_amplitude), not at its range: the §4.1 crossing-sliding boundary upwards in omega, where the
// static level at the stops grows without bound as omega nears omega1. Against the modal analysis
// of the stiffness matrix (eq. 56 and Appendix 1, solved here by Eigen): the end lies just below
// omega1; the orbit is there the first mode's forced response, so amplitude:x2 / amplitude:x1 is
// the mode's shape lambda_1 = (1 - omega1^2)/chi up to the other mode's and the friction's bounded
// share (O(1/amplitude)), and the amplitude grows like 1/(omega1^2 - omega^2). The exact simulator
// started on the last orbits closes over the period with their recorded amplitudes.
TEST(BoundaryCurve, EndsAtAResonanceOfTheForcing) {
  // continuation-scripts/paper-4.1-sk-boundary-up.toml
  RunFile file = RestartInOmega("paper-4.1-omega-down", "SK2");
  file.restart_boundary = "u_r";
  file.direction = 1;
  file.range_max = 0.8;  // beyond omega1: only the resonance ends the curve
  file.steps.ds = 0.01;
  file.steps.ds_max = 5.0;  // u_r grows 1e5 times faster than omega near the end
  file.steps.max_points = 1000;
  OrbitContinuationSetup setup = MakeSetup(file, Results());
  // The amplitude's bound, not the approach to omega1 (which ends the run file's curve at 1 %):
  // the modal shape shows only near omega1.
  setup.resonance_approach = 0.0;
  const OrbitBranch curve = ContinueOrbit(setup);
  ASSERT_EQ(curve.branch.end, BranchEnd::kStopped) << curve.branch.end_message;
  EXPECT_TRUE(curve.branch.end_message.starts_with("resonance: the amplitude")) << curve.branch.end_message;
  const int n = static_cast<int>(curve.orbits.size());
  ASSERT_GE(n, 3);
  EXPECT_EQ(curve.branch.special_points.back().type, "EP");
  EXPECT_EQ(curve.branch.special_points.back().point, n - 1);

  const double chi = setup.start.parameters.chi, eta = setup.start.parameters.eta;
  Eigen::Matrix2d stiffness;
  stiffness << 1.0, -chi, -chi * eta, chi * eta;
  Eigen::Vector2d squares = stiffness.eigenvalues().real();
  std::sort(squares.begin(), squares.end());
  const double omega1_sq = squares(0);
  const double omega1 = std::sqrt(omega1_sq);
  const double shape = (1.0 - omega1_sq) / chi;

  const Orbit& last = curve.orbits[n - 1];
  const Orbit& before = curve.orbits[n - 2];
  const SimulatedPeriod at_end = SimulatePeriod(last);
  const SimulatedPeriod at_before = SimulatePeriod(before);
  const double amplitude_end = std::max(at_end.amplitude_x1, at_end.amplitude_x2);
  EXPECT_GT(amplitude_end, setup.max_amplitude);
  EXPECT_LE(std::max(at_before.amplitude_x1, at_before.amplitude_x2), setup.max_amplitude * (1 + 1e-7));
  for (const SimulatedPeriod& period : {at_end, at_before}) EXPECT_LT(period.closure, 1e-10 * amplitude_end);
  const OrbitMeasures measures = Measure(last);
  EXPECT_NEAR(measures.amplitude_x1, at_end.amplitude_x1, 1e-7 * amplitude_end);
  EXPECT_NEAR(measures.amplitude_x2, at_end.amplitude_x2, 1e-7 * amplitude_end);

  const double omega = last.parameters.omega;
  EXPECT_LT(omega, omega1);
  EXPECT_GT(omega, omega1 - 1e-3);
  EXPECT_GT(last.parameters.u_r, 100.0);  // the stops' static level, far beyond the start's 0.3
  // measured 7e-4 relative at the end
  EXPECT_NEAR(at_end.amplitude_x2 / at_end.amplitude_x1, shape, 2e-3 * shape);
  // amplitude (omega1^2 - omega^2) at the end and where the amplitude was half of it: measured 6e-4
  // apart relative (a growth like 1/(omega1 - omega)^2 would halve it).
  int half = n - 1;
  while (half > 0 && std::max(Measure(curve.orbits[half]).amplitude_x1, Measure(curve.orbits[half]).amplitude_x2) >
                         0.5 * amplitude_end) {
    --half;
  }
  const Orbit& middle = curve.orbits[half];
  const SimulatedPeriod at_half = SimulatePeriod(middle);
  const double growth_end = at_end.amplitude_x2 * (omega1_sq - omega * omega);
  const double growth_half = at_half.amplitude_x2 * (omega1_sq - middle.parameters.omega * middle.parameters.omega);
  EXPECT_NEAR(growth_half, growth_end, 2e-3 * growth_end);
}

TEST(BoundaryCurve, RefusesConditionsAndSecondParametersItGivesNoCurveOf) {
  const OrbitContinuationSetup setup = CurveFrom("paper-4.1-omega-down", "SK2", -1);
  CurveStart start{.orbit = setup.start, .condition = "margin:reversal:1", .parameter = "omega", .unknowns = {}};
  auto field = [&](const std::string& condition, const std::string& second) {
    start.condition = condition;
    try {
      BoundaryCurve(start, setup, second);
    } catch (const InvalidInput& e) {
      return e.field();
    }
    return std::string("none");
  };
  EXPECT_EQ(field("margin:reversal:1", "u_r"), "none");
  EXPECT_EQ(field("margin:duration:1", "u_r"), "condition");  // a slip's duration
  EXPECT_EQ(field("margin:sliding-friction", "u_r"), "condition");
  EXPECT_EQ(field("margin:G:1", "u_r"), "condition");  // no such margin
  EXPECT_EQ(field("margin:velocity:1", "u_r"), "condition");  // no interior minimum at the start
  EXPECT_EQ(field("margin:reversal:1", "omega"), "second");  // the continued one
  EXPECT_EQ(field("margin:reversal:1", "x10"), "second");
  EXPECT_EQ(field("margin:reversal:1", "nonsense"), "second");
  start.unknowns.release = {"u_r"};
  EXPECT_EQ(field("margin:reversal:1", "u_r"), "second");  // released already
}

}  // namespace
}  // namespace stickslip
