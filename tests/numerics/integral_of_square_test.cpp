#include "stickslip/numerics/integral_of_square.hpp"

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

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

// Random sums of damped, growing and undamped terms with polynomial factors, over short and long
// durations, against Simpson's rule on the sum's own values: the closed form to 1e-11 of the
// terms' scale, whichever of its two branches (series or recursion) each pair takes.
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
      EXPECT_NEAR(IntegralOfSquare(f, d), q.integral, 1e-11 * q.scale) << "trial " << trial << ", d = " << d;
    }
  }
}

TEST(IntegralOfSquare, IsNotFiniteWhereTheExponentialOverflows) {
  EXPECT_FALSE(std::isfinite(IntegralOfSquare(ExponentialSum({{0, 500.0, {1.0, 1.0, 0.0}}}), 2.0)));
}

}  // namespace
}  // namespace stickslip
