// Admissibility margins against dense sampling of the closed-form flow (an independent way to
// find a minimum, since the margins use root finding on derivatives).
#include "stickslip/orbits/margins.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "stickslip/model/pascal_2014/events.hpp"
#include "support/den_hartog_orbit.hpp"
#include "support/den_hartog_oscillator.hpp"
#include "support/solved_presets.hpp"

namespace stickslip {
namespace {

Margin Find(const std::vector<Margin>& margins, const std::string& name) {
  return *std::find_if(margins.begin(), margins.end(), [&](const Margin& m) { return m.Name() == name; });
}

struct Sampled {
  double t = 0.0;
  double value = std::numeric_limits<double>::infinity();
};

// Minimum of f over [a, b] on a grid of `count` intervals.
template <typename F>
Sampled SampledMinimum(F&& f, double a, double b, int count) {
  Sampled best;
  for (int k = 0; k <= count; ++k) {
    const double t = a + (b - a) * k / count;
    const double value = f(t);
    if (value < best.value) best = {t, value};
  }
  return best;
}

// The stick constraints over the stick of an orbit, sampled from the flow.
void ExpectStickConstraintMinima(const Orbit& o, int stick) {
  const std::vector<State> states = o.SegmentStates();
  const std::vector<double> times = o.SegmentTimes();
  const Parameters& p = o.parameters;
  const double phase0 = o.phi + p.omega * times[stick];
  auto at = [&](double s) { return Flow(Mode::kStick, states[stick], phase0, s, p); };
  const double d = o.durations[stick];
  const Sampled g = SampledMinimum(
      [&](double s) { return StickConstraintG(at(s), phase0 + p.omega * s, p); }, 0.0, d, 200000);
  const Sampled g1 = SampledMinimum(
      [&](double s) { return StickConstraintG1(at(s), phase0 + p.omega * s, p); }, 0.0, d, 200000);
  const std::vector<Margin> margins = AdmissibilityMargins(o);
  const std::string suffix = ":" + std::to_string(stick + 1);
  // The grid step is 1.4e-5: the sampled minimum lies above the true one by at most
  // |G''| h^2/8 < 1e-9, and the true one is never above it.
  const Margin mg = Find(margins, "G" + suffix);
  const Margin mg1 = Find(margins, "G1" + suffix);
  // For the constraint that ends the stick, the exit end (where it is zero) is excluded.
  if (g.t < d) {
    EXPECT_NEAR(mg.value, g.value, 1e-8);
    EXPECT_LE(mg.value, g.value + 1e-12);
    EXPECT_NEAR(mg.t - times[stick], g.t, 1e-4);
  }
  if (g1.t < d) {
    EXPECT_NEAR(mg1.value, g1.value, 1e-8);
  }
}

TEST(StickConstraintMargins, AreTheTrueMinimaOverTheStick) {
  ExpectStickConstraintMinima(SolvedPreset("paper-5.1"), 2);
  ExpectStickConstraintMinima(SolvedPreset("paper-5.2"), 2);  // the negative interior minimum
  ExpectStickConstraintMinima(SolvedPreset("paper-6"), 1);
}

// A hand-made slip+ segment that runs past its first stop: x2' goes negative inside and comes
// back up, so the velocity margin is that negative interior minimum (a new stop is born).
TEST(SlipVelocityMargin, IsTheInteriorMinimumOfTheSignedVelocity) {
  const Parameters p{0.3, 4.0, 0.6, 0.1, 0.2};
  // At rest with s = chi eta (x2 - x1) - cos(phi) = -2.2 < -eta u_r: a slip with x2' > 0.
  Orbit o{Signature::Parse("slip+ slip-"), p, 1.0, 0.0, 0.0, 0.0, {0.0, 1.0}};
  auto v2 = [&](double t) { return Flow(Mode::kSlipPositive, o.InitialState(), o.phi, t, p)(3); };
  // The first interior local minimum of x2' on a fine grid.
  const double h = 1e-4;
  double t_min = -1.0;
  for (double t = 0.05; t < 30.0; t += h) {
    if (v2(t) < v2(t - h) && v2(t) < v2(t + h)) {
      t_min = t;
      break;
    }
  }
  ASSERT_GT(t_min, 0.0);
  o.durations[0] = t_min + 0.3;
  const Margin m = Find(AdmissibilityMargins(o), "velocity:1");
  const Sampled sampled = SampledMinimum(v2, t_min - h, t_min + h, 2000);
  EXPECT_NEAR(m.value, sampled.value, 1e-10);
  EXPECT_NEAR(m.t, sampled.t, 1e-6);
  EXPECT_EQ(m.kind, MarginKind::kSlipVelocity);
}

TEST(Margins, SmallestIsTheDistanceToTheNearestChangeOfType) {
  // Section 4.1 sits on the boundary between nonsticking and sticking orbits (ERRATA): its
  // smallest margin is the force at the stop, barely above eta u_r.
  const Orbit o = SolvedPreset("paper-4.1");
  const Margin smallest = SmallestMargin(AdmissibilityMargins(o));
  EXPECT_EQ(smallest.Name(), "reversal:1");
  EXPECT_GT(smallest.value, 0.0);
  EXPECT_LT(smallest.value, 1e-3);
  // Reproduce it from the stop state: -s - eta u_r before the slip+ half.
  const State stop = o.SegmentStates()[1];
  const double phase = o.phi + o.parameters.omega * o.durations[0];
  EXPECT_NEAR(smallest.value, -StickForce(stop, phase, o.parameters) - o.parameters.eta * o.parameters.u_r, 1e-14);
}

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

TEST(Margins, AreNaNNotASpinForAnOrbitWithANaNValue) {
  Orbit o = SolvedPreset("paper-5.1");
  o.x10 = std::numeric_limits<double>::quiet_NaN();
  const auto start = std::chrono::steady_clock::now();
  const std::vector<Margin> margins = AdmissibilityMargins(o);
  EXPECT_LT(SecondsSince(start), 2.0);
  EXPECT_TRUE(std::isnan(Find(margins, "velocity:1").value));
  EXPECT_TRUE(std::isnan(Find(margins, "G:3").value));
  EXPECT_TRUE(std::isnan(SmallestMargin(margins).value));
}

TEST(Margins, AreNaNNotASpinForANaNDuration) {
  Orbit o = SolvedPreset("paper-5.1");
  o.durations[0] = std::numeric_limits<double>::quiet_NaN();
  const auto start = std::chrono::steady_clock::now();
  const std::vector<Margin> margins = AdmissibilityMargins(o);
  EXPECT_LT(SecondsSince(start), 2.0);
  EXPECT_TRUE(std::isnan(Find(margins, "velocity:1").value));
}

TEST(Margins, AreNaNWhenASegmentIsTooLongForTheSearchBound) {
  Orbit o = SolvedPreset("paper-5.1");
  o.durations[0] = 1e308;
  const auto start = std::chrono::steady_clock::now();
  const std::vector<Margin> margins = AdmissibilityMargins(o);
  EXPECT_LT(SecondsSince(start), 10.0);
  EXPECT_TRUE(std::isnan(Find(margins, "velocity:1").value));
  // The other segments' margins do not depend on it.
  EXPECT_FALSE(std::isnan(Find(margins, "stick-entry:2").value));
}

// Den Hartog's non-sticking orbit (FRICTION-LITERATURE.md) through the model interface: at the
// lower turning point x = -X, x' = 0 and the forcing phase is phi + pi with cos phi = X/V,
// V = 1/(1 - r^2), so the stick force x - cos(phase) is -r^2 X. Hence the reversal margin
// r^2 X - beta_static (Shaw's condition for the orbit to survive) and the deceleration into the
// stop x'' = r^2 X + beta, in closed form.

// x'(t) of the closed form on the half period, d/dt = r d/dtau.
double DenHartogVelocity(const DenHartogOrbit& o, double t) {
  const double tau = o.r * t;
  return o.r * (-o.amplitude * std::sin(tau) + o.beta * o.u * std::cos(tau) +
                o.beta * (std::sin(tau / o.r) / o.r - o.u * std::cos(tau / o.r)));
}

// The smallest sampled interior local minimum of -x' over the half period, +inf if none.
double SampledSlipVelocityMinimum(const DenHartogOrbit& o) {
  constexpr int kCount = 200000;
  const double d = 0.5 * o.Period();
  auto f = [&](int k) { return -DenHartogVelocity(o, d * k / kCount); };
  double best = std::numeric_limits<double>::infinity();
  for (int k = 1; k < kCount; ++k) {
    if (f(k) <= f(k - 1) && f(k) <= f(k + 1)) best = std::min(best, f(k));
  }
  return best;
}

TEST(ModelMargins, AreDenHartogsClosedFormsAtItsTurningPoints) {
  std::vector<std::pair<double, double>> cases(kDenHartogNonStickingCases.begin(), kDenHartogNonStickingCases.end());
  // Below r = 1/2, where -x' has positive interior minima in the slip (checked by the sampling).
  cases.insert(cases.end(), {{0.3, 0.05}, {0.38, 0.1}});
  for (const auto& [r, beta] : cases) {
    const DenHartogOrbit o(r, beta);
    for (const char* signature : {"slip- / antisymmetric", "slip- slip+"}) {
      SCOPED_TRACE(testing::Message() << "r = " << r << ", beta = " << beta << ", " << signature);
      const std::vector<Margin> margins =
          AdmissibilityMargins(DenHartogModel(), DenHartogOnSignature(o, signature, 1.5 * beta));
      const double stick_force = r * r * o.amplitude;
      const int last = Signature::Parse(signature).size();
      const std::string end = ":" + std::to_string(last);
      EXPECT_NEAR(Find(margins, "reversal" + end).value, stick_force - 1.5 * beta, 1e-11);
      EXPECT_NEAR(Find(margins, "stop-slope" + end).value, stick_force + beta, 1e-11);
      EXPECT_NEAR(Find(margins, "stop-slope:1").value, stick_force + beta, 1e-11);
      EXPECT_DOUBLE_EQ(Find(margins, "duration:1").value, std::numbers::pi / r);
      EXPECT_EQ(Find(margins, "sliding-friction").value, beta);
      // The interior minimum of -x', by root finding, against dense sampling of the closed form
      // (grid step <= 6e-5: the sampled minimum lies above the true one by < 1e-8).
      const double sampled = SampledSlipVelocityMinimum(o);
      const double velocity = Find(margins, "velocity:1").value;
      ASSERT_GT(r * r * o.amplitude, beta);
      if (std::isinf(sampled)) {
        EXPECT_TRUE(std::isinf(velocity)) << velocity;
      } else {
        EXPECT_NEAR(velocity, sampled, 1e-8);
        EXPECT_LE(velocity, sampled + 1e-12);
      }
      EXPECT_GT(SmallestMargin(margins).value, 0.0);
    }
  }
}

TEST(ModelMargins, NameTheReversalWhereStaticFrictionHoldsDenHartogsTurningPoint) {
  const DenHartogOrbit o(1.5, 0.25);
  const double holding = 1.5 * 1.5 * o.amplitude;  // Shaw: the orbit survives while r^2 X > beta_static
  const Margin below = SmallestMargin(AdmissibilityMargins(DenHartogModel(), DenHartogOnSignature(o, "slip- slip+", 0.99 * holding)));
  const Margin above = SmallestMargin(AdmissibilityMargins(DenHartogModel(), DenHartogOnSignature(o, "slip- slip+", 1.01 * holding)));
  EXPECT_GT(below.value, 0.0);
  EXPECT_LT(above.value, 0.0);
  EXPECT_EQ(std::string(above.base), "reversal");
  EXPECT_NEAR(above.value, -0.01 * holding, 1e-11);
}

}  // namespace
}  // namespace stickslip
