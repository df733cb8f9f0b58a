// The exact event-driven simulator: the paper's section 4.1 orbit, event location accuracy,
// and Coulomb's decisions at constructed tangencies (abnormal stop, onset of a stick) and at a
// near-tangency whose two stops are too close for any sampling to see.
#include "stickslip/model/simulation.hpp"

#include <chrono>
#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "stickslip/model/pascal_2014/events.hpp"
#include "stickslip/model/pascal_2014/odeint_simulator.hpp"
#include "stickslip/model/pascal_2014/paper_examples.hpp"

namespace stickslip {
namespace {

constexpr double kPi = std::numbers::pi;

SimulationResult SimulatePeriods(const PaperExample& e, double periods) {
  SimulationOptions options;
  options.duration = periods * 2.0 * kPi / e.parameters.omega;
  return SimulateExact(e.parameters, e.initial_state, e.phi, options);
}

// Section 4.1: stops at t = pi/omega and 2 pi/omega, and x(pi/omega) = -x(0) (the orbit is
// symmetric about the origin). The paper prints 4-5 digits and u_r = 0.2996 sits on the
// boundary between nonsticking and sticking orbits (ERRATA), hence 1e-3.
TEST(PaperSection41, StopsAtHalfAndFullPeriodWithOppositeStates) {
  const PaperExample& e = *FindPaperExample("paper-4.1");
  const SimulationResult r = SimulatePeriods(e, 1.0 + 1e-6);
  const double half = kPi / e.parameters.omega;
  ASSERT_GE(r.events.size(), 2u);
  EXPECT_NEAR(r.events[0].t, half, 1e-3);
  // x2 starts at its maximum (f > 0, eq. 12): slip with x2' < 0, then overshooting.
  EXPECT_STREQ(ToString(r.events[0].mode_before), "slip-");
  EXPECT_STREQ(ToString(r.events[0].mode_after), "slip+");
  EXPECT_NEAR(r.events[1].t, 2 * half, 1e-3);
  EXPECT_STREQ(ToString(r.events[1].mode_after), "slip-");
  EXPECT_LT((r.events[0].state + e.initial_state).lpNorm<Eigen::Infinity>(), 1e-3);
  EXPECT_LT((r.events[1].state - e.initial_state).lpNorm<Eigen::Infinity>(), 1e-3);
}

// Every stop is a zero of x2' and every stick exit a zero of G or G1, recomputed from the
// segment's start with the flow: the residual divided by the slope bounds the time error.
TEST(ExactSimulator, LocatesEveryEventToTheTimeTolerance) {
  for (const PaperExample& e : PaperExamples()) {
    const SimulationResult r = SimulatePeriods(e, 3.0);
    const Parameters& p = e.parameters;
    for (const Segment& s : r.segments) {
      if (s.end_reason == SegmentEnd::kHorizon) continue;
      const double elapsed = s.t_end - s.t_start;
      const double phase = p.omega * s.t_start + e.phi;
      const State x = Flow(s.mode, s.start, phase, elapsed, p);
      const double end_phase = phase + p.omega * elapsed;
      double value, slope;
      if (s.mode == Mode::kStick) {
        const double force = StickForce(x, end_phase, p);
        value = std::abs(force) - p.eta * p.u_r;
        slope = std::abs(-p.chi * p.eta * x(2) + p.omega * std::sin(end_phase));
      } else {
        value = x(3);
        slope = std::abs(Acceleration(s.mode, x, end_phase, p)(1));
      }
      if (slope < 1e-6) continue;  // a tangency: located on the extremum instead
      EXPECT_LT(std::abs(value) / slope, 1e-12) << e.name << " segment ending at " << s.t_end;
    }
  }
}

// A state where x2' = 0 and x2'' = 0 with x2''' > 0 in slip+: x2' touches zero and goes on
// positive. Flowed back by one time unit it gives a start whose first event is that touch.
struct Tangency {
  Parameters p;
  State start;
  double phi;
};

Tangency ConstructTangency(double u_r, double dip) {
  Tangency t;
  t.p = {0.3, 4.0, 0.6, 0.1, u_r};
  const double psi = 2.0;  // forcing phase at the tangency
  State xc;
  xc(0) = 0.4;
  xc(2) = 0.8;  // x2''' = chi eta x1' - omega sin(psi) = 0.96 - 0.546 > 0
  // x2'' = -chi eta (x2 - x1) - eta u_s + cos(psi) = 0 in slip+ (eq. 2, 8).
  xc(1) = xc(0) + (std::cos(psi) - t.p.eta * t.p.u_s) / (t.p.chi * t.p.eta);
  xc(3) = -dip;
  t.phi = psi - t.p.omega * 1.0;
  t.start = Flow(Mode::kSlipPositive, xc, psi, -1.0, t.p);
  return t;
}

TEST(ExactSimulator, ClassifiesAnExactTangencyAsAnAbnormalStopWhenFrictionLevelsAreEqual) {
  const Tangency c = ConstructTangency(/*u_r=*/0.1, /*dip=*/0.0);
  ASSERT_GT(c.start(3), 0.0);
  SimulationOptions options;
  options.duration = 1.5;
  const SimulationResult r = SimulateExact(c.p, c.start, c.phi, options);
  ASSERT_FALSE(r.events.empty());
  EXPECT_NEAR(r.events[0].t, 1.0, 1e-9);
  EXPECT_TRUE(r.events[0].IsAbnormalStop());
  EXPECT_STREQ(ToString(r.events[0].mode_after), "slip+");
}

TEST(ExactSimulator, StartsAStickWhereVelocityTouchesZeroBelowTheStaticLevel) {
  // Same touch with u_r > u_s: the force there is eta u_s < eta u_r, so m2 sticks (eq. 4).
  const Tangency c = ConstructTangency(/*u_r=*/0.2, /*dip=*/0.0);
  SimulationOptions options;
  options.duration = 1.5;
  const SimulationResult r = SimulateExact(c.p, c.start, c.phi, options);
  ASSERT_FALSE(r.events.empty());
  EXPECT_NEAR(r.events[0].t, 1.0, 1e-9);
  EXPECT_STREQ(ToString(r.events[0].kind), "stop");
  EXPECT_STREQ(ToString(r.events[0].mode_after), "stick");
}

TEST(ExactSimulator, FindsTheFirstOfTwoStopsCloserThanAnySamplingStep) {
  // x2' dips to -1e-9 at t = 1: its zeros are ~1e-4 apart on either side.
  const Tangency c = ConstructTangency(/*u_r=*/0.2, /*dip=*/1e-9);
  SimulationOptions options;
  options.duration = 1.5;
  const SimulationResult r = SimulateExact(c.p, c.start, c.phi, options);
  ASSERT_FALSE(r.events.empty());
  const double jerk = c.p.chi * c.p.eta * 0.8 - c.p.omega * std::sin(2.0);
  const double half_gap = std::sqrt(2.0 * 1e-9 / jerk);
  EXPECT_NEAR(r.events[0].t, 1.0 - half_gap, 1e-6);
  EXPECT_STREQ(ToString(r.events[0].mode_after), "stick");
}

TEST(ExactSimulator, SegmentsJoinUpAndSamplesFollowTheFlow) {
  const PaperExample& e = *FindPaperExample("paper-5.1");
  SimulationOptions options;
  options.duration = 2 * 2.0 * kPi / e.parameters.omega;
  options.sample_step = 0.05;
  const SimulationResult r = SimulateExact(e.parameters, e.initial_state, e.phi, options);
  ASSERT_TRUE(r.Completed());
  for (std::size_t i = 1; i < r.segments.size(); ++i) {
    EXPECT_EQ(r.segments[i].t_start, r.segments[i - 1].t_end);
    EXPECT_EQ(r.segments[i].start, r.segments[i - 1].end);
  }
  EXPECT_DOUBLE_EQ(r.segments.back().t_end, options.duration);
  EXPECT_EQ(r.samples.size(), static_cast<std::size_t>(std::floor(options.duration / 0.05)) + 1);
}

// Time is in whole forcing periods in a sweep's section: N T, sampled every T, must give N + 1
// samples whatever rounding does to N T / T.
TEST(ExactSimulator, SamplesTheEndOfADurationOfWholeSampleSteps) {
  const PaperExample& e = *FindPaperExample("paper-5.1");
  int checked = 0;
  for (double omega = 0.5; omega < 0.6; omega += 1e-3) {
    Parameters p = e.parameters;
    p.omega = omega;
    const double period = 2.0 * kPi / omega;
    SimulationOptions options;
    options.duration = 3 * period;
    options.sample_step = period;
    const SimulationResult r = SimulateExact(p, e.initial_state, e.phi, options);
    ASSERT_EQ(r.samples.size(), 4u) << "omega = " << omega;
    EXPECT_EQ(r.samples.back().t, options.duration);
    ++checked;
  }
  EXPECT_EQ(checked, 100);
}

// Bad input is an exception naming the field; stopping early is a status of the result.
TEST(OdeintSimulator, ThrowsInvalidInputNamingTheFieldAndReportsMaxEventsAsAnEnd) {
  const PaperExample& e = *FindPaperExample("paper-4.1");
  auto field_of = [&](const Parameters& p, const SimulationOptions& options, const OdeintOptions& odeint) {
    try {
      SimulateOdeint(p, e.initial_state, e.phi, options, odeint);
    } catch (const InvalidInput& error) {
      return error.field();
    }
    return std::string("none");
  };
  SimulationOptions options;
  options.duration = 10.0;
  Parameters bad = e.parameters;
  bad.chi = 2.0;
  EXPECT_EQ(field_of(bad, options, {}), "chi");
  EXPECT_EQ(field_of(e.parameters, {}, {}), "duration");
  OdeintOptions loose;
  loose.relative_tolerance = -1.0;
  EXPECT_EQ(field_of(e.parameters, options, loose), "relative_tolerance");
  options.max_events = 1;
  const SimulationResult r = SimulateOdeint(e.parameters, e.initial_state, e.phi, options);
  EXPECT_EQ(r.end, SimulationEnd::kMaxEvents);
  EXPECT_FALSE(r.Completed());
  EXPECT_EQ(r.events.size(), 1u);
}

// A stick whose force beats slowly toward the static level (forcing near the stick frequency 1,
// starting out of phase with the free motion of x1) exits after more than five forcing periods:
// found where the independent Odeint integration finds it, and so is every event after it.
TEST(ExactSimulator, FindsAStickExitManyForcingPeriodsIntoTheStick) {
  const Parameters p{0.3, 2.0, 0.95, 0.1, 0.55};
  const State rest(0.5, 0.0, 0.0, 0.0);
  SimulationOptions options;
  options.duration = 200.0;
  const SimulationResult exact = SimulateExact(p, rest, kPi, options);
  const SimulationResult odeint = SimulateOdeint(p, rest, kPi, options);
  ASSERT_GE(exact.events.size(), 10u);
  EXPECT_EQ(exact.events[0].kind, EventKind::kStickExit);
  EXPECT_GT(exact.events[0].t, 5.0 * 2.0 * kPi / p.omega);
  ASSERT_EQ(exact.events.size(), odeint.events.size());
  for (std::size_t i = 0; i < exact.events.size(); ++i) {
    EXPECT_EQ(exact.events[i].mode_after, odeint.events[i].mode_after) << "event " << i;
    EXPECT_NEAR(exact.events[i].t, odeint.events[i].t, 1e-8) << "event " << i;
  }
}

// Held by a static level just above the largest stick force, the mass sticks for the whole
// duration while G comes within 1e-6 of zero every period: each near-touch costs the root finder
// many sub-intervals, so the search over a thousand periods completes only because it runs in
// windows, each within the bound (searched to the horizon at once, it would need more).
TEST(ExactSimulator, SticksThroughAThousandForcingPeriodsInBoundedSearches) {
  Parameters p{0.3, 2.0, 0.6, 0.1, 1.0};
  const State start(0.0, 0.0, 0.0, 0.0);  // x1 = chi x2 at rest: s is the forcing alone
  const double period = 2.0 * kPi / p.omega;
  const SinusoidSum s = StickForceAlong(MotionInMode(Mode::kStick, start, 0.0, p), 0.0, p);
  const double largest = std::max(-Minimum(s.Affine(-1.0, 0.0), 0.0, period).value, -Minimum(s, 0.0, period).value);
  p.u_r = largest * (1.0 + 1e-6) / p.eta;
  SimulationOptions options;
  options.duration = 1000.0 * period;
  options.zeros.max_intervals = 4096;
  const auto t0 = std::chrono::steady_clock::now();
  const SimulationResult r = SimulateExact(p, start, 0.0, options);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 10.0);
  EXPECT_TRUE(r.Completed()) << r.message;
  EXPECT_TRUE(r.events.empty());
  ASSERT_EQ(r.segments.size(), 1u);
  EXPECT_EQ(r.segments[0].mode, Mode::kStick);
  // The same search to the horizon at once runs out of the bound.
  const SinusoidSum g = s.Affine(1.0, p.eta * p.u_r);
  EXPECT_EQ(Zeros(g, 0.0, options.duration, 1, options.zeros).status, ZeroSearchStatus::kTooManyIntervals);
}

TEST(ExactSimulator, ReportsTheSearchLimitInsteadOfRunningOn) {
  const PaperExample& e = *FindPaperExample("paper-5.1");
  SimulationOptions options;
  options.duration = 2.0 * 2.0 * kPi / e.parameters.omega;
  options.zeros.max_intervals = 2;
  const SimulationResult r = SimulateExact(e.parameters, e.initial_state, e.phi, options);
  EXPECT_EQ(r.end, SimulationEnd::kSearchLimit);
  EXPECT_FALSE(r.Completed());
  EXPECT_NE(r.message.find("too many sub-intervals"), std::string::npos) << r.message;
}

// A stick from rest with x1 off its stick equilibrium chi x2 by -0.2: the stick force s (eq. 11)
// beats the free motion of x1 (frequency 1) against the forcing (omega = 0.6). The search for
// the stick's exit first reaches one forcing period T ahead; a grazing or a crossing of G just
// behind that reach must come out as a search that went on past it would find it.
struct BeatingStick {
  Parameters p{0.3, 2.0, 0.6, 0.1, 1.0};
  State start = State(p.chi * -1.0 - 0.2, -1.0, 0.0, 0.0);
  double period = 2.0 * kPi / p.omega;
  SinusoidSum Force(double phi) const { return StickForceAlong(MotionInMode(Mode::kStick, start, phi, p), phi, p); }
  // The phase that puts the minimum of s near T at T + 1e-7.
  double PhaseWithForceMinimumJustAfterOnePeriod() const {
    double phi = 0.3;
    for (int i = 0; i < 60; ++i) phi += p.omega * (Minimum(Force(phi), period - 1.0, period + 1.0).t - (period + 1e-7));
    return phi;
  }
};

TEST(ExactSimulator, SticksOnThroughAGrazingJustAfterTheFirstForcingPeriod) {
  BeatingStick c;
  const double phi = c.PhaseWithForceMinimumJustAfterOnePeriod();
  const SinusoidSum s = c.Force(phi);
  const double low = Minimum(s, c.period - 1.0, c.period + 1.0).value;
  // G = s + eta u_r grazes zero from above, 5e-12 of its scale away: a touch, the stick goes on.
  c.p.u_r = (-low + 5e-12 * s.Affine(1.0, -low).Scale()) / c.p.eta;
  c.p.u_s = 0.5 * c.p.u_r;
  const SinusoidSum g = s.Affine(1.0, c.p.eta * c.p.u_r);
  const SinusoidSum g1 = s.Affine(-1.0, c.p.eta * c.p.u_r);
  ASSERT_NEAR(Minimum(g, c.period - 1.0, c.period + 1.0).t, c.period + 1e-7, 1e-9);
  ASSERT_GT(Minimum(g, 0.0, 2.0 * c.period - 1.0).value, 0.0);
  ASSERT_GT(Minimum(g1, 0.0, 2.0 * c.period - 1.0).value, 0.0);
  SimulationOptions options;
  options.duration = 3.0 * c.period;
  const SimulationResult r = SimulateExact(c.p, c.start, phi, options);
  ASSERT_FALSE(r.events.empty());
  EXPECT_GT(r.events[0].t, 2.0 * c.period - 1.0);
}

TEST(ExactSimulator, FindsAStickExitJustAfterTheFirstForcingPeriod) {
  BeatingStick c;
  const double phi = c.PhaseWithForceMinimumJustAfterOnePeriod() - c.p.omega * 0.5;
  const SinusoidSum s = c.Force(phi);
  const double exit = c.period + 3e-14;
  // G = s + eta u_r falls through zero 3e-14 after T: at T it is within rounding of zero.
  c.p.u_r = -s(exit) / c.p.eta;
  c.p.u_s = 0.5 * c.p.u_r;
  const SinusoidSum g = s.Affine(1.0, c.p.eta * c.p.u_r);
  const SinusoidSum g1 = s.Affine(-1.0, c.p.eta * c.p.u_r);
  ASSERT_LT(g.JetAt(c.period).slope, -0.1);
  ASSERT_GT(Minimum(g, 0.0, c.period - 1e-6).value, 0.0);
  ASSERT_GT(Minimum(g1, 0.0, c.period + 1.0).value, 0.0);
  SimulationOptions options;
  options.duration = 3.0 * c.period;
  const SimulationResult r = SimulateExact(c.p, c.start, phi, options);
  ASSERT_FALSE(r.events.empty());
  EXPECT_EQ(r.events[0].kind, EventKind::kStickExit);
  EXPECT_EQ(r.events[0].mode_after, Mode::kSlipPositive);
  EXPECT_NEAR(r.events[0].t, exit, 1e-12);
}

}  // namespace
}  // namespace stickslip

namespace stickslip {
namespace {

// The callback is called at every event with the time simulated, in forcing periods.
TEST(SimulationProgress, ReportsEveryEventInForcingPeriods) {
  const PaperExample& e = *FindPaperExample("paper-5.1");
  const double period = 2.0 * std::numbers::pi / e.parameters.omega;
  SimulationOptions o;
  o.duration = 7.5 * period;
  std::vector<Progress> seen;
  o.progress = [&](const Progress& p) { seen.push_back(p); };
  for (bool exact : {true, false}) {
    seen.clear();
    const SimulationResult r = exact ? SimulateExact(e.parameters, e.initial_state, e.phi, o)
                                     : SimulateOdeint(e.parameters, e.initial_state, e.phi, o);
    ASSERT_EQ(seen.size(), r.events.size());
    for (std::size_t k = 0; k < seen.size(); ++k) {
      EXPECT_DOUBLE_EQ(seen[k].done, r.events[k].t / period);
      EXPECT_DOUBLE_EQ(seen[k].total, 7.5);
      EXPECT_STREQ(seen[k].unit, "periods");
    }
  }
}

// A streamed simulation (SimulationOptions::on_sample) gives the samples a stored one keeps, in
// the same order, each with the mode of the first segment that reaches its time; section 5.1
// (stops and sticks every period), both simulators.
TEST(Simulators, StreamTheSamplesTheyWouldStoreWithTheirSegmentsModes) {
  const PaperExample& e = *FindPaperExample("paper-5.1");
  SimulationOptions options;
  options.duration = 3.3 * 2.0 * std::numbers::pi / e.parameters.omega;
  options.sample_step = 0.0137;
  for (const bool exact : {true, false}) {
    SCOPED_TRACE(exact ? "exact" : "odeint");
    auto simulate = [&](const SimulationOptions& o) {
      return exact ? SimulateExact(e.parameters, e.initial_state, e.phi, o)
                   : SimulateOdeint(e.parameters, e.initial_state, e.phi, o);
    };
    const SimulationResult stored = simulate(options);
    std::vector<std::pair<TimeSample, Mode>> streamed;
    SimulationOptions streaming = options;
    streaming.on_sample = [&](const TimeSample& s, Mode m) { streamed.emplace_back(s, m); };
    const SimulationResult result = simulate(streaming);
    EXPECT_TRUE(result.samples.empty());
    ASSERT_EQ(streamed.size(), stored.samples.size());
    ASSERT_GT(streamed.size(), 1000u);
    for (std::size_t k = 0; k < streamed.size(); ++k) {
      ASSERT_EQ(streamed[k].first.t, stored.samples[k].t);
      ASSERT_EQ(streamed[k].first.state, stored.samples[k].state);
      std::size_t segment = 0;
      while (segment + 1 < stored.segments.size() && stored.segments[segment].t_end < streamed[k].first.t) ++segment;
      ASSERT_EQ(streamed[k].second, stored.segments[segment].mode) << "t = " << streamed[k].first.t;
    }
  }
}

}  // namespace
}  // namespace stickslip
