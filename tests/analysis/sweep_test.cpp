// The brute-force sweep: its section states against the independent Odeint simulator, the
// chaining of points (the down pass from where the up pass ended), chains independent of each
// other, and an output that does not depend on the number of threads; for a model of the user's,
// Den Hartog's closed-form amplitude over the forcing frequency.
#include "stickslip/analysis/sweep.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <tuple>

#include <gtest/gtest.h>

#include "stickslip/model/linear_oscillator.hpp"
#include "stickslip/model/pascal_2014/modal.hpp"
#include "stickslip/model/simulation.hpp"
#include "stickslip/model/pascal_2014/odeint_simulator.hpp"
#include "stickslip/model/pascal_2014/paper_examples.hpp"
#include "stickslip/orbits/orbit_measures.hpp"
#include "support/belt_cycle.hpp"
#include "support/den_hartog_orbit.hpp"
#include "support/den_hartogs_mass.hpp"
#include "support/solved_presets.hpp"

namespace stickslip {
namespace {

// Odeint over `periods` forcing periods of p from x0 at phase phi: the state at the end.
State OdeintAfter(const Parameters& p, const State& x0, double phi, int periods) {
  SimulationOptions options;
  options.duration = periods * 2.0 * std::numbers::pi / p.omega;
  const SimulationResult r = SimulateOdeint(p, x0, phi, options);
  EXPECT_TRUE(r.Completed()) << r.message;
  return r.segments.back().end;
}

SweepOptions ShortSweep(SweepStart start) {
  return {.from = 0.56, .to = 0.6, .steps = 2, .transient_periods = 2, .recorded_periods = 2, .start = start};
}

Parameters WithOmega(Parameters p, double omega) {
  p.omega = omega;
  return p;
}

// Section 5.1: stops and sticks in every period, so the section states pass through every kind
// of event. Odeint tolerance 1e-10 over four periods: 1e-7.
TEST(Sweep, SectionStatesAreTheStatesAtTheForcingPhaseEveryPeriod) {
  const PaperExample& e = *FindPaperExample("paper-5.1");
  const SweepOptions o = ShortSweep(SweepStart::kChained);
  const std::vector<SweepPoint> points = Sweep(e.parameters, {e.initial_state}, e.phi, o);
  ASSERT_EQ(points.size(), 6u);
  const SweepPoint& first = points.front();
  EXPECT_EQ(first.pass, SweepPass::kUp);
  EXPECT_DOUBLE_EQ(first.value, 0.56);
  ASSERT_EQ(first.section.size(), 2u);
  for (int k = 0; k < 2; ++k) {
    const State expected = OdeintAfter(WithOmega(e.parameters, 0.56), e.initial_state, e.phi, 2 + k + 1);
    EXPECT_LT((first.section[k] - expected).lpNorm<Eigen::Infinity>(), 1e-7) << "k = " << k;
  }
}

TEST(Sweep, EachPointStartsFromThePreviousOneAndTheDownPassFromTheUpPassEnd) {
  const PaperExample& e = *FindPaperExample("paper-5.1");
  const SweepOptions o = ShortSweep(SweepStart::kChained);
  const std::vector<SweepPoint> points = Sweep(e.parameters, {e.initial_state}, e.phi, o);
  ASSERT_EQ(points.size(), 6u);
  const double expected_values[] = {0.56, 0.58, 0.6, 0.6, 0.58, 0.56};
  for (std::size_t i = 1; i < points.size(); ++i) {
    EXPECT_EQ(points[i].pass, i < 3 ? SweepPass::kUp : SweepPass::kDown);
    EXPECT_NEAR(points[i].value, expected_values[i], 1e-15);
    const State expected =
        OdeintAfter(WithOmega(e.parameters, points[i].value), points[i - 1].section.back(), e.phi, 3);
    EXPECT_LT((points[i].section.front() - expected).lpNorm<Eigen::Infinity>(), 1e-7) << "point " << i;
  }
}

TEST(Sweep, FixedStartsEveryPointFromItsChainStart) {
  const PaperExample& e = *FindPaperExample("paper-5.1");
  const std::vector<State> starts = ScatteredStarts(e.initial_state, 0.5, 2, 7);
  const std::vector<SweepPoint> points = Sweep(e.parameters, starts, e.phi, ShortSweep(SweepStart::kFixed));
  ASSERT_EQ(points.size(), 6u);
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_EQ(points[i].pass, SweepPass::kFixed);
    EXPECT_EQ(points[i].chain, static_cast<int>(i / 3));
    EXPECT_EQ(points[i].step, static_cast<int>(i % 3));
    const State expected = OdeintAfter(WithOmega(e.parameters, points[i].value), starts[points[i].chain], e.phi, 3);
    EXPECT_LT((points[i].section.front() - expected).lpNorm<Eigen::Infinity>(), 1e-7) << "point " << i;
  }
}

TEST(Sweep, ChainsDoNotInfluenceEachOther) {
  const PaperExample& e = *FindPaperExample("paper-6");
  const std::vector<State> starts = ScatteredStarts(e.initial_state, 1.0, 3, 11);
  SweepOptions o = ShortSweep(SweepStart::kChained);
  o.threads = 3;
  const std::vector<SweepPoint> together = Sweep(e.parameters, starts, e.phi, o);
  ASSERT_EQ(together.size(), 18u);
  for (int chain = 0; chain < 3; ++chain) {
    const std::vector<SweepPoint> alone = Sweep(e.parameters, {starts[chain]}, e.phi, o);
    for (std::size_t i = 0; i < alone.size(); ++i) {
      const SweepPoint& p = together[chain * alone.size() + i];
      EXPECT_EQ(p.chain, chain);
      EXPECT_EQ(p.section, alone[i].section) << "chain " << chain << ", point " << i;
    }
  }
}

TEST(Sweep, OutputDoesNotDependOnTheNumberOfThreads) {
  const PaperExample& e = *FindPaperExample("paper-5.2");
  const std::vector<State> starts = ScatteredStarts(e.initial_state, 1.0, 5, 3);
  for (SweepStart start : {SweepStart::kChained, SweepStart::kFixed}) {
    SweepOptions o = ShortSweep(start);
    o.threads = 1;
    const std::string serial = SweepCsv(Pascal2014{}, Sweep(e.parameters, starts, e.phi, o), o.parameter, e.phi);
    for (int threads : {2, 3, 8}) {
      o.threads = threads;
      EXPECT_EQ(SweepCsv(Pascal2014{}, Sweep(e.parameters, starts, e.phi, o), o.parameter, e.phi), serial) << threads << " threads";
    }
  }
}

// Started on the section 4.1 orbit at its own data: period 1, two stops (reversals) and no
// stick per period, as the paper describes it.
TEST(Sweep, RecognisesThePeriodOneMotionOfSection41) {
  const PaperExample& e = *FindPaperExample("paper-4.1");
  SweepOptions o;
  o.from = o.to = e.parameters.omega;
  o.steps = 1;
  o.transient_periods = 50;
  o.recorded_periods = 6;
  const SweepPoint p = Sweep(e.parameters, {e.initial_state}, e.phi, o).front();
  EXPECT_EQ(p.period, 1);
  EXPECT_DOUBLE_EQ(p.stops_per_period, 2.0);
  EXPECT_DOUBLE_EQ(p.sticks_per_period, 0.0);
}

// The amplitude of x2 over the recorded periods against the independent Odeint simulator, densely
// sampled over the same periods (transients included, from the same start): the samples can only
// miss the true maximum, by ~h^2 |x2''|/2 (h = period/20000), plus Odeint's error (1e-7 here).
TEST(Sweep, AmplitudeOfX2IsTheMaximumOfTheSimulatedMotionOverTheRecordedPeriods) {
  const PaperExample& e = *FindPaperExample("paper-5.1");
  const SweepOptions o = ShortSweep(SweepStart::kFixed);
  const std::vector<SweepPoint> points = Sweep(e.parameters, {e.initial_state}, e.phi, o);
  for (const SweepPoint& point : points) {
    const Parameters p = WithOmega(e.parameters, point.value);
    const double period = 2.0 * std::numbers::pi / p.omega;
    SimulationOptions options;
    options.duration = (o.transient_periods + o.recorded_periods) * period;
    options.sample_step = period / 20000;
    const SimulationResult r = SimulateOdeint(p, e.initial_state, e.phi, options);
    ASSERT_TRUE(r.Completed()) << r.message;
    double sampled = 0.0;
    for (const TimeSample& s : r.samples) {
      if (s.t >= o.transient_periods * period) sampled = std::max(sampled, std::abs(s.state(1)));
    }
    EXPECT_LE(sampled, point.contact_amplitude + 1e-6) << "omega = " << point.value;
    EXPECT_GE(sampled, point.contact_amplitude - 1e-5) << "omega = " << point.value;
  }
}

// Settled on the stable section 4.1 orbit, the sweep's amplitude is the orbit's own (the measure a
// branch records, from the solved orbit's closed forms, not from a simulation).
TEST(Sweep, AmplitudeOfX2OnASettledOrbitIsTheOrbitsMeasure) {
  const Orbit orbit = SolvedPreset("paper-4.1");
  SweepOptions o;
  o.from = o.to = orbit.parameters.omega;
  o.steps = 1;
  o.transient_periods = 50;
  o.recorded_periods = 4;
  o.start = SweepStart::kFixed;
  const SweepPoint p = Sweep(orbit.parameters, {orbit.InitialState()}, orbit.phi, o).front();
  ASSERT_EQ(p.period, 1);
  EXPECT_NEAR(p.contact_amplitude, Measure(orbit).amplitude_x2, 1e-9);
}

// Issue 11, item 9: --transients 1e6 failed with max_events (2e6 events in one simulation). The
// transients run in chunks, each under the bound: 30000 periods of section 4.1 (60000 events)
// under a bound of 30000 events, settling where one simulation without that bound settles.
TEST(Sweep, TransientsLongerThanTheEventBoundRunInChunks) {
  const PaperExample& e = *FindPaperExample("paper-4.1");
  SweepOptions o;
  o.from = o.to = e.parameters.omega;
  o.steps = 1;
  o.start = SweepStart::kFixed;
  o.transient_periods = 30000;
  o.recorded_periods = 2;
  o.max_events_per_simulation = 30000;
  const SweepPoint p = Sweep(e.parameters, {e.initial_state}, e.phi, o).front();
  SimulationOptions whole;
  whole.duration = o.transient_periods * 2.0 * std::numbers::pi / e.parameters.omega;
  const SimulationResult r = SimulateExact(e.parameters, e.initial_state, e.phi, whole);
  ASSERT_TRUE(r.Completed()) << r.message;
  ASSERT_GT(r.events.size(), 30000u);
  EXPECT_LT((p.section.front() - r.segments.back().end).lpNorm<Eigen::Infinity>(), 1e-9);
  EXPECT_EQ(p.period, 1);
}

TEST(Sweep, RejectsNoStartsAndCountsOutOfRange) {
  const PaperExample& e = *FindPaperExample("paper-4.1");
  EXPECT_THROW(Sweep(e.parameters, {}, e.phi, ShortSweep(SweepStart::kChained)), InvalidInput);
  for (auto [steps, transients, recorded] : {std::tuple{0, 2, 2}, {2, -1, 2}, {2, 2, 0}}) {
    SweepOptions o = ShortSweep(SweepStart::kFixed);
    o.steps = steps;
    o.transient_periods = transients;
    o.recorded_periods = recorded;
    EXPECT_THROW(Sweep(e.parameters, {e.initial_state}, e.phi, o), InvalidInput)
        << steps << " " << transients << " " << recorded;
  }
}

// An interior grid value on a natural frequency is refused before anything is simulated, as the
// ends are, in both passes and with fixed starts.
TEST(Sweep, RejectsAnInteriorValueOnANaturalFrequencyNamingTheStep) {
  const PaperExample& e = *FindPaperExample("paper-5.1");
  const double omega1 = NaturalFrequencies(e.parameters.chi, e.parameters.eta).first;
  for (SweepStart start : {SweepStart::kChained, SweepStart::kFixed}) {
    SweepOptions o = ShortSweep(start);
    o.from = omega1 - 0.01;
    o.to = omega1 + 0.01;  // step 1 of 2 lies within rounding of omega1
    o.transient_periods = 500;
    const auto begin = std::chrono::steady_clock::now();
    try {
      Sweep(e.parameters, {e.initial_state}, e.phi, o);
      FAIL() << "no error";
    } catch (const InvalidInput& error) {
      EXPECT_EQ(error.field(), "steps");
      EXPECT_NE(std::string(error.what()).find("step 1 of the"), std::string::npos) << error.what();
      EXPECT_NE(std::string(error.what()).find("natural frequencies"), std::string::npos) << error.what();
    }
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count(), 1.0);
  }
}

TEST(Sweep, NamesTheEndThatIsInvalid) {
  const PaperExample& e = *FindPaperExample("paper-4.1");
  SweepOptions o = ShortSweep(SweepStart::kChained);
  o.parameter = static_cast<int>(ParameterId::kStaticFriction);
  o.from = 0.3;
  o.to = 0.05;  // below u_s = 0.1
  try {
    Sweep(e.parameters, {e.initial_state}, e.phi, o);
    FAIL() << "no error";
  } catch (const InvalidInput& error) {
    EXPECT_EQ(error.field(), "to");
  }
}

// A simulation cut short by the event guard fails the whole sweep, naming the point, instead of
// recording a motion that was not simulated to the end.
TEST(Sweep, ReportsASimulationStoppedByTheEventGuardWithItsPoint) {
  const PaperExample& e = *FindPaperExample("paper-5.1");
  SweepOptions o = ShortSweep(SweepStart::kChained);
  o.max_events_per_simulation = 3;  // section 5.1 has four events per period
  try {
    Sweep(e.parameters, {e.initial_state}, e.phi, o);
    FAIL() << "no error";
  } catch (const std::runtime_error& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("chain 0, up pass, step 0 (omega = 0.56)"), std::string::npos) << message;
    EXPECT_NE(message.find("max_events"), std::string::npos) << message;
  }
}

// No transients: the first section state is the state one forcing period after the start.
TEST(Sweep, RecordsFromTheStartWithoutTransients) {
  const PaperExample& e = *FindPaperExample("paper-5.1");
  SweepOptions o = ShortSweep(SweepStart::kFixed);
  o.transient_periods = 0;
  const SweepPoint first = Sweep(e.parameters, {e.initial_state}, e.phi, o).front();
  const State expected = OdeintAfter(WithOmega(e.parameters, 0.56), e.initial_state, e.phi, 1);
  EXPECT_LT((first.section.front() - expected).lpNorm<Eigen::Infinity>(), 1e-7);
}

// splitmix64's published test values (Vigna's reference implementation): seed 0 gives
// 0xe220a8397b1dcdaf first; seed 1234567 gives 6457827717110365317 and 3203168211198807973.
TEST(ScatteredStarts, DrawsFromSplitmix64InTheBoxAroundTheCentre) {
  const State centre(1.0, -2.0, 0.5, 0.0);
  auto unit = [](std::uint64_t v) { return static_cast<double>(v >> 11) * 0x1.0p-53; };
  const std::vector<State> zero = ScatteredStarts(centre, 2.0, 2, 0);
  ASSERT_EQ(zero.size(), 2u);
  EXPECT_EQ(zero[0], centre);
  EXPECT_DOUBLE_EQ(zero[1](0), centre(0) + 2.0 * (2.0 * unit(0xe220a8397b1dcdafULL) - 1.0));
  const std::vector<State> other = ScatteredStarts(centre, 2.0, 2, 1234567);
  EXPECT_DOUBLE_EQ(other[1](0), centre(0) + 2.0 * (2.0 * unit(6457827717110365317ULL) - 1.0));
  EXPECT_DOUBLE_EQ(other[1](1), centre(1) + 2.0 * (2.0 * unit(3203168211198807973ULL) - 1.0));

  const std::vector<State> many = ScatteredStarts(centre, 0.25, 400, 5);
  ASSERT_EQ(many.size(), 400u);
  Eigen::Vector4d lowest = Eigen::Vector4d::Constant(1.0), highest = Eigen::Vector4d::Constant(-1.0);
  for (const State& x : many) {
    const Eigen::Vector4d offset = (x - centre) / 0.25;
    EXPECT_LE(offset.lpNorm<Eigen::Infinity>(), 1.0);
    lowest = lowest.cwiseMin(offset);
    highest = highest.cwiseMax(offset);
  }
  // Uniform over the box: 399 draws reach within 0.1 of every face (a miss has odds 0.95^399).
  EXPECT_LT(lowest.maxCoeff(), -0.9);
  EXPECT_GT(highest.minCoeff(), 0.9);
  EXPECT_EQ(ScatteredStarts(centre, 0.25, 400, 5), many);
}

}  // namespace
}  // namespace stickslip

namespace stickslip {
namespace {

// The callback sees every point once, one call at a time, the count rising to the total, on
// any number of threads; and the output is the same with and without it.
TEST(SweepProgress, CountsEveryPointOnceInOrderOnAnyNumberOfThreads) {
  const PaperExample& e = *FindPaperExample("paper-5.2");
  const std::vector<State> starts = ScatteredStarts(e.initial_state, 1.0, 5, 3);
  for (SweepStart start : {SweepStart::kChained, SweepStart::kFixed}) {
    SweepOptions o = ShortSweep(start);
    const std::string quiet = SweepCsv(Pascal2014{}, Sweep(e.parameters, starts, e.phi, o), o.parameter, e.phi);
    for (int threads : {1, 4}) {
      o.threads = threads;
      std::vector<double> done;
      std::atomic<int> inside{0};
      bool overlapped = false;
      double total = 0.0;
      o.progress = [&](const Progress& p) {
        overlapped = overlapped || inside.fetch_add(1) != 0;
        done.push_back(p.done);
        total = p.total;
        EXPECT_STREQ(p.unit, "points");
        inside.fetch_sub(1);
      };
      const std::vector<SweepPoint> points = Sweep(e.parameters, starts, e.phi, o);
      EXPECT_FALSE(overlapped);
      ASSERT_EQ(done.size(), points.size()) << threads << " threads";
      EXPECT_EQ(total, static_cast<double>(points.size()));
      for (std::size_t k = 0; k < done.size(); ++k) EXPECT_EQ(done[k], static_cast<double>(k + 1));
      EXPECT_EQ(SweepCsv(Pascal2014{}, points, o.parameter, e.phi), quiet);
    }
  }
}

// From rest at every omega = r (one pass), friction takes the transient out and the motion settles
// on Den Hartog's non-sticking orbit: period 1, two stops and no stick per period, and the
// amplitude X(r, beta) = sqrt(V^2 - beta^2 U^2) of his closed form (FRICTION-LITERATURE.md), to
// what 400 periods leave of the transient. Once through the paper's column names, the model's.
TEST(Sweep, FollowsDenHartogsClosedFormAmplitudeForAModelOfTheUsers) {
  const DynamicLinearOscillator model = DenHartogsMass();
  const double beta = 0.25;
  const SweepOptions o{.from = 1.5, .to = 2.5, .steps = 4, .transient_periods = 400, .recorded_periods = 8,
                       .start = SweepStart::kFixed, .threads = 2};
  const std::vector<SweepPoint> points =
      Sweep(model, {1.5, beta, beta, 0.0}, {Eigen::VectorXd::Zero(2)}, 0.0, o);
  ASSERT_EQ(points.size(), 5u);
  for (const SweepPoint& p : points) {
    EXPECT_EQ(p.period, 1) << "omega = " << p.value;
    EXPECT_EQ(p.stops_per_period, 2.0);
    EXPECT_EQ(p.sticks_per_period, 0.0);
    EXPECT_NEAR(p.contact_amplitude, DenHartogOrbit(p.value, beta).amplitude, 1e-8) << "omega = " << p.value;
    ASSERT_EQ(p.section.front().size(), 2);
  }
  const std::string csv = SweepCsv(model, points, SweepOptions::kForcingFrequency, 0.0);
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "chain,direction,step,omega,section_phase,k,m1,v_m1,stops_per_period,sticks_per_period,period,amplitude:m1");
  EXPECT_TRUE(IsSweepCsvHeader(csv.substr(0, csv.find('\n'))));
  SweepOptions one_thread = o;
  one_thread.threads = 1;
  EXPECT_EQ(SweepCsv(model, Sweep(model, {1.5, beta, beta, 0.0}, {Eigen::VectorXd::Zero(2)}, 0.0, one_thread),
                     SweepOptions::kForcingFrequency, 0.0),
            csv);
}

// A mass on a belt (no forcing) read on its stick-entry section: at every belt speed the motion
// from rest is the closed-form stick-slip cycle (FRICTION-LITERATURE.md): one stop and one stick per
// cycle, period 1, the stick entered at x = (2 F_k - F_s)/k with the belt's speed, and max |x| =
// F_k/k + hypot(d, v_b/omega_n), d = (F_s - F_k)/k.
TEST(Sweep, ReadsABeltsStickSlipCycleOnItsStickEntries) {
  const BeltCycle belt;
  const DynamicLinearOscillator model(belt.Data());
  SweepOptions o{.parameter = 3, .from = 0.2, .to = 0.9, .steps = 2, .transient_periods = 5, .recorded_periods = 6,
                 .time_unit = 2.0 * std::numbers::pi, .start = SweepStart::kFixed};
  const std::vector<SweepPoint> points = Sweep(model, {1.0, belt.F_k, belt.F_s, 0.2}, {Eigen::VectorXd::Zero(2)}, 0.0, o);
  ASSERT_EQ(points.size(), 3u);
  for (const SweepPoint& p : points) {
    BeltCycle at = belt;
    at.v_b = p.value;
    EXPECT_EQ(p.period, 1) << "v_b = " << p.value;
    EXPECT_EQ(p.stops_per_period, 1.0);
    EXPECT_EQ(p.sticks_per_period, 1.0);
    EXPECT_NEAR(p.contact_amplitude, at.F_k / at.k + at.Radius(), 1e-10) << "v_b = " << p.value;
    ASSERT_FALSE(p.section.empty());
    EXPECT_NEAR(p.section.front()(0), at.Restick(), 1e-10);
    EXPECT_NEAR(p.section.front()(1), p.value, 1e-12);
  }
  // Its forcing frequency plays no part; a model without forcing needs a time unit.
  o.parameter = SweepOptions::kForcingFrequency;
  try {
    Sweep(model, {1.0, belt.F_k, belt.F_s, 0.2}, {Eigen::VectorXd::Zero(2)}, 0.0, o);
    FAIL() << "no error";
  } catch (const InvalidInput& error) {
    EXPECT_EQ(error.field(), "parameter") << error.what();
  }
  o.parameter = 3;
  o.time_unit = 0.0;
  try {
    Sweep(model, {1.0, belt.F_k, belt.F_s, 0.2}, {Eigen::VectorXd::Zero(2)}, 0.0, o);
    FAIL() << "no error";
  } catch (const InvalidInput& error) {
    EXPECT_EQ(error.field(), "time_unit") << error.what();
  }
}

// A damped mass on a belt with equal friction levels slides steadily at x = F_k/k: period 1 on the
// section every time unit, no stop, no stick.
TEST(Sweep, ReadsASteadySlideAsPeriodOneWithoutStops) {
  BeltCycle belt;
  belt.F_s = belt.F_k;
  const DynamicLinearOscillator model(belt.Data(0.5));
  const SweepOptions o{.parameter = 3, .from = 0.5, .to = 0.6, .steps = 1, .transient_periods = 20,
                       .recorded_periods = 4, .time_unit = 2.0 * std::numbers::pi, .start = SweepStart::kFixed};
  for (const SweepPoint& p : Sweep(model, {1.0, belt.F_k, belt.F_s, 0.5}, {Eigen::VectorXd::Zero(2)}, 0.0, o)) {
    EXPECT_EQ(p.period, 1) << "v_b = " << p.value;
    EXPECT_EQ(p.stops_per_period, 0.0);
    EXPECT_EQ(p.sticks_per_period, 0.0);
    EXPECT_NEAR(p.contact_amplitude, belt.F_k / belt.k, 1e-6);
  }
  try {
    Sweep(DenHartogsMass(), {1.5, 0.25, 0.25, 0.0}, {Eigen::VectorXd::Zero(3)}, 0.0, SweepOptions{.from = 1.5, .to = 2.0});
    FAIL() << "no error";
  } catch (const InvalidInput& error) {
    EXPECT_EQ(error.field(), "starts") << error.what();
  }
}

}  // namespace
}  // namespace stickslip
