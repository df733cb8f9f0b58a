#include "stickslip/numerics/integral_of_square.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "stickslip/invalid_input.hpp"

namespace stickslip {
namespace {

constexpr double kPi = std::numbers::pi;

// int_0^d f^2 dt by composite Simpson on f's own values (exponential_sum.hpp's operator()), and
// the same of the terms' magnitudes, the scale the closed form's rounding is relative to.
struct Quadrature {
  double integral = 0.0, scale = 0.0;
};
Quadrature Simpson(const ExponentialSum& f, double d, int intervals) {
  Quadrature q;
  const double h = d / intervals;
  for (int i = 0; i <= intervals; ++i) {
    const double t = i * h, weight = (i == 0 || i == intervals) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
    q.integral += weight * f(t) * f(t) * h / 3.0;
    q.scale += weight * SizeAt(f, t) * SizeAt(f, t) * h / 3.0;
  }
  return q;
}

TEST(IntegralOfSquare, AgreesWithTheTextbookIntegrals) {
  EXPECT_NEAR(IntegralOfSquare(ExponentialSum::OfSinusoids(2.0, 0.0, {}), 3.0), 12.0, 1e-14);  // 4 d
  EXPECT_NEAR(IntegralOfSquare(ExponentialSum::OfSinusoids(0.0, 1.0, {}), 3.0), 9.0, 1e-13);   // d^3/3
  // cos^2 over a period: pi; (sin t + t)^2 over [0, pi]: pi/2 + 2 pi + pi^3/3.
  EXPECT_NEAR(IntegralOfSquare(ExponentialSum::OfSinusoids(0.0, 0.0, {{1.0, 1.0, 0.0}}), 2.0 * kPi), kPi, 1e-14);
  EXPECT_NEAR(IntegralOfSquare(SinusoidSum(0.0, 1.0, {{1.0, 0.0, 1.0}}), kPi), kPi / 2 + 2 * kPi + kPi * kPi * kPi / 3,
              1e-12);
  // e^{-t}^2: (1 - e^{-2d})/2; (t e^{-t})^2: int t^2 e^{-2t} = (1 - e^{-2d}(1 + 2d + 2d^2))/4.
  const double d = 1.7;
  EXPECT_NEAR(IntegralOfSquare(ExponentialSum({{0, -1.0, {0.0, 1.0, 0.0}}}), d), (1 - std::exp(-2 * d)) / 2, 1e-15);
  EXPECT_NEAR(IntegralOfSquare(ExponentialSum({{1, -1.0, {0.0, 1.0, 0.0}}}), d),
              (1 - std::exp(-2 * d) * (1 + 2 * d + 2 * d * d)) / 4, 1e-15);
  EXPECT_EQ(IntegralOfSquare(ExponentialSum::OfSinusoids(5.0, 1.0, {{2.0, 1.0, 3.0}}), 0.0), 0.0);
}

// Random sums of damped, growing and undamped terms with drifts (t factors), over short and long
// durations, against Simpson's rule on the sum's own values: the closed form to 1e-12 of the
// terms' scale, whichever of its three branches (either series, or the recursion) each pair takes.
TEST(IntegralOfSquare, AgreesWithQuadratureOfTheSumsValues) {
  std::mt19937 random(20261130);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 40; ++trial) {
    std::vector<ExponentialTerm> terms;
    const int count = 2 + trial % 5;
    for (int k = 0; k < count; ++k) {
      const double rate = k % 3 == 0 ? 0.0 : 0.8 * unit(random), frequency = k % 4 == 1 ? 0.0 : 3.0 * std::abs(unit(random));
      terms.push_back({(trial + k) % 3 == 0 ? 1 : 0, rate, {frequency, unit(random), unit(random)}});
    }
    // Exponents that nearly cancel in a product: lambda and -conj(lambda) + 1e-9.
    terms.push_back({0, -terms[1].rate + 1e-9, {terms[1].sinusoid.frequency, unit(random), unit(random)}});
    const ExponentialSum f(terms);
    for (const double d : {1e-6, 0.3, 4.0}) {
      const Quadrature q = Simpson(f, d, 20000);
      EXPECT_NEAR(IntegralOfSquare(f, d), q.integral, 1e-12 * q.scale) << "trial " << trial << ", d = " << d;
    }
  }
}

// Near critical damping a slip's speed is a difference of two nearly equal exponentials with large
// coefficients: (e^{-t} - e^{-(1 + delta) t}) / delta, about t e^{-t}. Its square's integral against
// Simpson's rule on the same function written without the cancellation, -e^{-t} expm1(-delta t) /
// delta: to twice the rounding of f's own values, eps / delta relative, with a margin of 10 (the
// pairwise closed form alone would lose about eps / delta^2: 2e-4 at delta = 1e-6).
TEST(IntegralOfSquare, KeepsItsDigitsWhereTheTermsCancelNearCriticalDamping) {
  for (const double delta : {1e-3, 1e-6}) {
    const ExponentialSum f({{0, -1.0, {0.0, 1.0 / delta, 0.0}}, {0, -(1.0 + delta), {0.0, -1.0 / delta, 0.0}}});
    const double d = 6.0;
    constexpr int kIntervals = 20000;
    double reference = 0.0;
    for (int i = 0; i <= kIntervals; ++i) {
      const double t = d * i / kIntervals, weight = (i == 0 || i == kIntervals) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
      const double value = -std::exp(-t) * std::expm1(-delta * t) / delta;
      reference += weight * value * value * d / kIntervals / 3.0;
    }
    const double rounding = std::numeric_limits<double>::epsilon() / delta;
    EXPECT_NEAR(IntegralOfSquare(f, d), reference, 20.0 * rounding * reference) << "delta = " << delta;
  }
}

TEST(IntegralOfSquare, IsNotFiniteWhereTheExponentialOverflowsAndRefusesWhatItDoesNotCover) {
  EXPECT_FALSE(std::isfinite(IntegralOfSquare(ExponentialSum({{0, 500.0, {1.0, 1.0, 0.0}}}), 2.0)));
  // A term that is zero everywhere stays zero where its exponential overflows: b sin(0 t) = 0.
  EXPECT_EQ(IntegralOfSquare(ExponentialSum({{0, 500.0, {0.0, 0.0, 1.0}}, {0, 0.0, {0.0, 1.0, 0.0}}}), 2.0), 2.0);
  EXPECT_THROW(IntegralOfSquare(ExponentialSum({{2, -1.0, {0.0, 1.0, 0.0}}}), 1.0), InvalidInput);  // t^2: no drift
  for (const double d : {-1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    EXPECT_THROW(IntegralOfSquare(ExponentialSum::OfSinusoids(1.0, 0.0, {}), d), InvalidInput) << d;
  }
}

}  // namespace
}  // namespace stickslip
