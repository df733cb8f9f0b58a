// Den Hartog's closed-form non-sticking orbit of his one-mass oscillator
// (den_hartog_oscillator.hpp; ../shared/FRICTION-LITERATURE.md), the check that a simulator
// follows it through the model interface, and the orbit as periodicity variables.
#pragma once

#include <array>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <gtest/gtest.h>

#include "stickslip/model/simulation.hpp"
#include "stickslip/orbits/orbit.hpp"
#include "stickslip/orbits/periodicity_equations.hpp"
#include "support/den_hartog_oscillator.hpp"

namespace stickslip {

// The symmetric orbit with two stops per period, in the time tau = r t: V = 1/(1 - r^2),
// U = tan(pi/(2r))/r, amplitude X = sqrt(V^2 - beta^2 U^2), forcing phase at the upper stop with
// sin phi = -beta U/V, cos phi = X/V, and on the half period tau in [0, pi]
//   x(tau) = X cos tau + beta U sin tau + beta (1 - cos(tau/r) - U r sin(tau/r)).
struct DenHartogOrbit {
  double r, beta, v, u, amplitude, phi;
  DenHartogOrbit(double r_, double beta_) : r(r_), beta(beta_) {
    v = 1.0 / (1.0 - r * r);
    u = std::tan(std::numbers::pi / (2.0 * r)) / r;
    amplitude = std::sqrt(v * v - beta * beta * u * u);
    phi = std::atan2(-beta * u / v, amplitude / v);
  }
  double Period() const { return 2.0 * std::numbers::pi / r; }
  double X(double t) const {  // t in [0, pi/r]
    const double tau = r * t;
    return amplitude * std::cos(tau) + beta * u * std::sin(tau) +
           beta * (1.0 - std::cos(tau / r) - u * r * std::sin(tau / r));
  }
};

// (r, beta): r >= 1/2 away from the degenerate 1/(2n) and from resonance; beta at half the largest
// value without a stick, r^2 X > beta.
inline constexpr std::array<std::pair<double, double>, 4> kDenHartogNonStickingCases = {
    std::pair{0.6, 0.1}, std::pair{0.8, 0.2}, std::pair{1.5, 0.25}, std::pair{2.5, 0.25}};

// `simulate(model, p, x0, phi, options)` from the orbit's upper stop at rest over 1.25 periods (the
// second stop inside the horizon, not on it): two stops per period, at the turning points, each a
// reversal (no stick), and every sample of the first period on the closed form, the second half
// by x(t + T/2) = -x(t); all within `tolerance`.
template <typename Simulate>
void ExpectDenHartogsOrbit(Simulate simulate, std::pair<double, double> r_beta, double tolerance) {
  const auto [r, beta] = r_beta;
  const DenHartogOrbit orbit(r, beta);
  ASSERT_GT(r * r * orbit.amplitude, beta) << "the orbit must not stick at its turning points";
  const DenHartogOscillator model = DenHartogModel();
  const DenHartogOscillator::Parameters p{r, beta, beta};
  ASSERT_FALSE(model.Validate(p));
  const double period = orbit.Period();
  BasicSimulationOptions<DenHartogOscillator::State> options;
  options.duration = 1.25 * period;
  options.sample_step = period / 40.0;
  const BasicSimulationResult<DenHartogOscillator> result =
      simulate(model, p, DenHartogOscillator::State(orbit.amplitude, 0.0), orbit.phi, options);
  ASSERT_TRUE(result.Completed()) << result.message;
  ASSERT_EQ(result.events.size(), 2u);
  for (int i = 0; i < 2; ++i) {
    const BasicEvent<DenHartogOscillator::State>& event = result.events[i];
    EXPECT_NEAR(event.t, 0.5 * (i + 1) * period, tolerance);
    EXPECT_EQ(event.mode_after, i == 0 ? Mode::kSlipPositive : Mode::kSlipNegative);
    EXPECT_NEAR(event.state(0), i == 0 ? -orbit.amplitude : orbit.amplitude, tolerance);
  }
  for (const auto& sample : result.samples) {
    if (sample.t > period) break;
    const bool second_half = sample.t > 0.5 * period;
    const double expected = second_half ? -orbit.X(sample.t - 0.5 * period) : orbit.X(sample.t);
    EXPECT_NEAR(sample.state(0), expected, tolerance) << "t = " << sample.t;
  }
}

// Den Hartog's orbit as the variables of a signature: antisymmetric "slip-" (one listed half
// period), or "slip- slip+" over the whole period with, for multiple shooting, the lower turning
// point as the second segment's start.
inline Eigen::VectorXd DenHartogVariables(const DenHartogOrbit& orbit,
                                          const BasicPeriodicityEquations<DenHartogOscillator>& equations) {
  const double half = 0.5 * orbit.Period();
  Eigen::VectorXd v(equations.VariableCount());
  v(0) = orbit.amplitude;
  v(equations.Phi()) = orbit.phi;
  for (int i = 0; i < equations.signature().size(); ++i) v(equations.Duration(i)) = half;
  v.segment<4>(equations.Parameter(0)) << orbit.r, orbit.beta, orbit.beta, 0.0;  // a fixed ground: v_b = 0
  if (equations.VariableCount() > equations.FullCount()) v.tail<2>() << -orbit.amplitude, 0.0;
  return v;
}

// Den Hartog's orbit as an orbit of `signature` ("slip- / antisymmetric" or "slip- slip+"), from
// its upper turning point, with the static level `beta_static`.
inline BasicOrbit<DenHartogOscillator> DenHartogOnSignature(const DenHartogOrbit& o, const char* signature,
                                                            double beta_static) {
  const Signature s = Signature::Parse(signature);
  return {s, {o.r, o.beta, beta_static}, {o.amplitude, 0.0}, o.phi, std::vector<double>(s.size(), 0.5 * o.Period())};
}

}  // namespace stickslip
