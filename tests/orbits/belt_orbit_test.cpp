// Self-excited stick-slip of a mass on a moving belt (../shared/FRICTION-LITERATURE.md): the
// general linear oscillator with no forcing (autonomous: the period is an unknown, the phase
// pinned) and the contact against a surface at speed v_b, against the closed form of the
// undamped cycle (derived below) and the Odeint integration of the equation of motion (the damped
// cycle's end in a fold as the belt speeds up: tests/branches/linear_oscillator_branch_test.cpp).
//
// m x'' + k x = F, s = x' - v_b. In a stick the mass moves with the belt until k x reaches F_s;
// then it slips (s < 0, F = +F_k) harmonically about F_k/k from x = F_s/k, x' = v_b, with radius
// A = sqrt(d^2 + (v_b/w)^2), d = (F_s - F_k)/k, w = sqrt(k/m): x - F_k/k = A cos(w t - theta),
// tan theta = v_b/(w d). It sticks again where x' = v_b next, at w t = pi + 2 theta, x = F_k/k - d
// = (2 F_k - F_s)/k. So T_slip = (pi + 2 atan(v_b/(w d)))/w, T_stick = 2 d / v_b, and the slip
// reaches F_k/k +- A.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "stickslip/model/exact_simulator.hpp"
#include "stickslip/model/linear_oscillator.hpp"
#include "stickslip/model/odeint_simulation.hpp"
#include "stickslip/numerics/newton.hpp"
#include "stickslip/orbits/margins.hpp"
#include "stickslip/orbits/orbit_measures.hpp"
#include "stickslip/orbits/orbit_system.hpp"
#include "support/belt_cycle.hpp"
#include "support/general_models.hpp"

namespace stickslip {
namespace {

using Belt = LinearOscillator<1>;
using Equations = BasicPeriodicityEquations<Belt>;

// x0, phi, the stick's and the slip's durations, then omega (no part), F_k, F_s, v_b.
Eigen::VectorXd Variables(const BeltCycle& b, double x0, double stick, double slip) {
  Eigen::VectorXd v(8);
  v << x0, 0.0, stick, slip, 1.0, b.F_k, b.F_s, b.v_b;
  return v;
}

BasicOrbit<Belt> OrbitOf(const Eigen::VectorXd& v) {
  return {Signature::Parse("stick slip-"), {v(4), v(5), v(6), v(7)}, {v(0), v(7)}, v(1), {v(2), v(3)}};
}

constexpr BeltCycle kCases[] = {{1.0, 1.0, 1.5, 1.0, 0.3}, {2.0, 5.0, 0.8, 0.5, 0.3}, {0.5, 3.0, 2.0, 0.4, 0.05}};

TEST(BeltStickSlip, IsTheClosedFormCycleWithItsPeriodAnUnknown) {
  for (const BeltCycle& b : kCases) {
    SCOPED_TRACE(testing::Message() << "m = " << b.m << ", k = " << b.k << ", v_b = " << b.v_b);
    const Belt model(b.Data());
    ASSERT_TRUE(model.Autonomous());
    const Equations equations(model, Signature::Parse("stick slip-"), Shooting::kSingle);
    const Eigen::VectorXd exact = Variables(b, b.Restick(), b.Stick(), b.Slip());
    Eigen::VectorXd residual;
    equations.Evaluate(exact, &residual, nullptr);
    EXPECT_LT(residual.lpNorm<Eigen::Infinity>(), 1e-12);
    EXPECT_EQ(equations.EquationNames().back(), "phase");

    const BasicOrbitSystem<Belt> system(equations, exact, {0, 1, 2, 3}, false);
    const Eigen::VectorXd guess = Variables(b, b.Restick() + 0.02 * b.d(), 0.98 * b.Stick(), 1.02 * b.Slip());
    const NewtonResult solved = SolveNewton(system, system.Unknowns(guess));
    ASSERT_TRUE(solved.summary.Converged()) << solved.summary.message;
    const Eigen::VectorXd v = system.Variables(solved.solution);
    EXPECT_NEAR(v(0), b.Restick(), 1e-10);
    EXPECT_NEAR(v(2), b.Stick(), 1e-10);
    EXPECT_NEAR(v(3), b.Slip(), 1e-10);

    const BasicOrbit<Belt> orbit = OrbitOf(v);
    EXPECT_GT(SmallestMargin(AdmissibilityMargins(model, orbit)).value, 0.0);
    const Belt::State stick_end = model.Flow(Mode::kStick, orbit.start, 0.0, v(2), orbit.parameters);
    const Extrema slip = MinimumAndMaximum(
        model.CoordinateAlong(model.MotionInMode(Mode::kSlipNegative, stick_end, 0.0, orbit.parameters), 0), 0.0, v(3));
    EXPECT_NEAR(slip.maximum.value, b.F_k / b.k + b.Radius(), 1e-10);
    EXPECT_NEAR(slip.minimum.value, b.F_k / b.k - b.Radius(), 1e-10);
    // In the slip the belt runs v_b T_slip while the mass comes back 2d: friction's work per
    // cycle is F_k (v_b T_slip + 2d); the stick's share of the cycle is T_stick / (T_stick + T_slip).
    const BasicOrbitMeasures m = Measure(model, orbit);
    EXPECT_NEAR(m.friction_work, b.F_k * (b.v_b * b.Slip() + 2.0 * b.d()), 1e-10);
    EXPECT_NEAR(m.stick_fraction, b.Stick() / (b.Stick() + b.Slip()), 1e-10);
  }
}

// Odeint integrates m x'' + c x' + k x = F itself (the stick held at the belt's speed) and meets
// the exact simulator at every stick and stop over three cycles, undamped and damped.
TEST(BeltStickSlip, ExactAndOdeintSimulatorsAgreeOnEveryEvent) {
  for (double c : {0.0, 0.2}) {
    const BeltCycle b = kCases[0];
    const Belt model(b.Data(c));
    const Belt::Parameters p{1.0, b.F_k, b.F_s, b.v_b};
    BasicSimulationOptions<Belt::State> options;
    options.duration = 3.0 * (b.Stick() + b.Slip());
    const Belt::State start(b.Restick(), b.v_b);
    const auto exact = SimulateExact(model, p, start, 0.0, options);
    const auto odeint = SimulateOdeint(model, p, start, 0.0, options);
    ASSERT_TRUE(exact.Completed()) << exact.message;
    ASSERT_TRUE(odeint.Completed()) << odeint.message;
    ASSERT_EQ(exact.events.size(), odeint.events.size()) << "c = " << c;
    ASSERT_GE(exact.events.size(), 5u);
    for (std::size_t i = 0; i < exact.events.size(); ++i) {
      EXPECT_EQ(exact.events[i].mode_after, odeint.events[i].mode_after) << "event " << i;
      EXPECT_NEAR(exact.events[i].t, odeint.events[i].t, 1e-8) << "event " << i;
      EXPECT_LT((exact.events[i].state - odeint.events[i].state).lpNorm<Eigen::Infinity>(), 1e-8) << "event " << i;
    }
  }
}

// Nearly equal levels (F_s = 1.002 F_k, v_b = 1): each stick of the undamped cycle lasts
// T_stick = 2 (F_s - F_k)/(k v_b) = 0.004, less than the integrator's steps, so one step straddles
// both crossings of s = 0 at a re-stick (Odeint saw 3 of these 9 events before it looked for a
// constraint's minimum within a step). Both simulators see every stick exit and every re-stick at
// the closed form's times, from the re-stick over four and a half cycles.
TEST(BeltStickSlip, OdeintSeesEveryStickShorterThanItsSteps) {
  BeltCycle b;
  b.F_s = 1.002;
  b.v_b = 1.0;
  const Belt model(b.Data());
  const Belt::Parameters p{1.0, b.F_k, b.F_s, b.v_b};
  const double cycle = b.Stick() + b.Slip();
  BasicSimulationOptions<Belt::State> options;
  options.duration = 4.5 * cycle;
  const Belt::State start(b.Restick(), b.v_b);
  const auto exact = SimulateExact(model, p, start, 0.0, options);
  const auto odeint = SimulateOdeint(model, p, start, 0.0, options);
  for (const auto* r : {&exact, &odeint}) {
    ASSERT_TRUE(r->Completed()) << r->message;
    ASSERT_EQ(r->events.size(), 9u) << (r == &exact ? "exact" : "odeint");
    for (std::size_t i = 0; i < r->events.size(); ++i) {
      const double t = static_cast<double>(i / 2) * cycle + (i % 2 == 0 ? b.Stick() : cycle);
      EXPECT_NEAR(r->events[i].t, t, 1e-8) << (r == &exact ? "exact" : "odeint") << ", event " << i;
      EXPECT_EQ(r->events[i].mode_after, i % 2 == 0 ? Mode::kSlipNegative : Mode::kStick) << "event " << i;
    }
  }
}

// Kinetic friction falling with the slip speed, F_k + alpha |s| with c + alpha < 0, makes steady
// sliding (x* = (F_k + alpha v_b)/k) unstable: Odeint, started next to it, grows into a stick-slip
// cycle. Its last cycle, from the simulated events (a stick entry, the stick's exit, the next
// entry), and the autonomous orbit 'stick slip-' the periodicity equations solve from it (Newton).
struct FallingFrictionCycle {
  LinearOscillatorData data;
  Belt::Parameters p{1.0, 1.0, 1.5, 0.3};
  std::vector<BasicEvent<Belt::State>> odeint;  // entry, exit, next entry
  Eigen::VectorXd solved;                                  // the orbit's variables; empty: failed
};
FallingFrictionCycle GrownFromSteadySliding() {
  FallingFrictionCycle c;
  c.data.mass = c.data.stiffness = Eigen::MatrixXd::Ones(1, 1);
  c.data.damping = Eigen::MatrixXd::Constant(1, 1, 0.05);
  c.data.forcing = Eigen::VectorXd::Zero(1);
  c.data.friction_slope = -0.3;
  const Belt model(c.data);
  const double steady = (c.p.F_k + c.data.friction_slope * c.p.v_b) / 1.0;
  BasicSimulationOptions<Belt::State> options;
  options.duration = 200.0;
  const auto odeint = SimulateOdeint(model, c.p, Belt::State(steady + 1e-3, 0.0), 0.0, options);
  std::vector<std::size_t> entries;  // events into a stick
  for (std::size_t i = 0; i < odeint.events.size(); ++i) {
    if (odeint.events[i].mode_after == Mode::kStick) entries.push_back(i);
  }
  if (!odeint.Completed() || entries.size() < 3) return c;
  const std::size_t entry = entries[entries.size() - 2];
  c.odeint = {odeint.events[entry], odeint.events[entry + 1], odeint.events[entries.back()]};
  const Equations equations(model, Signature::Parse("stick slip-"), Shooting::kSingle);
  Eigen::VectorXd guess(8);
  guess << c.odeint[0].state(0), 0.0, c.odeint[1].t - c.odeint[0].t, c.odeint[2].t - c.odeint[1].t, c.p.omega, c.p.F_k,
      c.p.F_s, c.p.v_b;
  const BasicOrbitSystem<Belt> system(equations, guess, {0, 1, 2, 3}, false);
  const NewtonResult solved = SolveNewton(system, system.Unknowns(guess));
  if (solved.summary.Converged()) c.solved = system.Variables(solved.solution);
  return c;
}

TEST(BeltStickSlip, FrictionFallingWithSpeedGrowsSteadySlidingIntoTheSolvedCycle) {
  const FallingFrictionCycle c = GrownFromSteadySliding();
  ASSERT_EQ(c.odeint.size(), 3u) << "steady sliding did not grow into stick-slip";
  ASSERT_EQ(c.odeint[1].mode_after, Mode::kSlipNegative);
  ASSERT_EQ(c.odeint[2].mode_after, Mode::kStick) << "one slip per cycle";
  ASSERT_EQ(c.solved.size(), 8) << "Newton did not converge from the simulated cycle";
  const Eigen::VectorXd& v = c.solved;
  const double stick = c.odeint[1].t - c.odeint[0].t, slip = c.odeint[2].t - c.odeint[1].t;
  EXPECT_NEAR(v(0), c.odeint[0].state(0), 1e-7);
  EXPECT_NEAR(v(0), c.odeint[2].state(0), 1e-7);
  EXPECT_NEAR(v(2), stick, 1e-7);
  EXPECT_NEAR(v(3), slip, 1e-7);
  EXPECT_GT(SmallestMargin(AdmissibilityMargins(Belt(c.data), OrbitOf(v))).value, 0.0);
  RecordProperty("cycle_stick_slip", fmt::format("{:.10g} {:.10g}", v(2), v(3)));
  RecordProperty("odeint_difference", fmt::format("{:.2g}", std::max(std::abs(v(2) - stick), std::abs(v(3) - slip))));
}

// Friction's work over that cycle against the power the friction force does on Odeint's motion,
// -F s with F the model's slip force (VectorField's, which the closed forms do not use), by the
// trapezoidal rule on one simulated cycle (the power is continuous, zero in the stick; its kink
// where the slip ends costs O(h^2)). The slope's share is no rounding: without it the work would
// be F_k times the distance slid relative to the belt, v_b times the cycle.
TEST(BeltStickSlip, FrictionWorkWithASlopeIsWhatTheSimulatedCycleDissipates) {
  const FallingFrictionCycle c = GrownFromSteadySliding();
  ASSERT_EQ(c.solved.size(), 8) << "no solved cycle";
  const Belt model(c.data);
  const Eigen::VectorXd& v = c.solved;
  BasicSimulationOptions<Belt::State> cycle;
  cycle.duration = v(2) + v(3);
  cycle.sample_step = cycle.duration / 200000;
  const auto sampled = SimulateOdeint(model, c.p, Belt::State(v(0), c.p.v_b), 0.0, cycle);
  ASSERT_TRUE(sampled.Completed()) << sampled.message;
  ASSERT_NEAR(sampled.samples.back().t, cycle.duration, 1e-9);
  const auto power = [&](const Belt::State& x) {
    const double s = x(1) - c.p.v_b;
    if (s == 0.0) return 0.0;  // the stick: no slip, no work
    // m x'' = -k x - c x' + F: F from the slip's acceleration.
    const double force = model.VectorField(s > 0.0 ? Mode::kSlipPositive : Mode::kSlipNegative, x, 0.0, c.p)(1) +
                         c.data.stiffness(0, 0) * x(0) + c.data.damping(0, 0) * x(1);
    return -force * s;
  };
  double work = 0.0;
  for (std::size_t i = 1; i < sampled.samples.size(); ++i) {
    const auto &before = sampled.samples[i - 1], &after = sampled.samples[i];
    work += 0.5 * (power(before.state) + power(after.state)) * (after.t - before.t);
  }
  const double measured = Measure(model, OrbitOf(v)).friction_work;
  EXPECT_NEAR(measured, work, 1e-8 * work);
  EXPECT_GT(std::abs(measured - c.p.F_k * c.p.v_b * (v(2) + v(3))), 1e-3 * work);
}

}  // namespace
}  // namespace stickslip
