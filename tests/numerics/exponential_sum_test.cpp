#include "stickslip/numerics/exponential_sum.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "stickslip/invalid_input.hpp"

namespace stickslip {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kAll = std::numeric_limits<int>::max();
// The two ways a zero is polished (ZeroSearchOptions::Polish): every zero test holds for both.
constexpr ZeroSearchOptions::Polish kPolishes[] = {ZeroSearchOptions::Polish::kBracket, ZeroSearchOptions::Polish::kJet};

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Expects the search complete, with zeros of the given kind exactly at `roots` (to `tolerance`).
void ExpectZerosAt(const ZeroSearch& search, const std::vector<double>& roots, double tolerance,
                   ZeroKind kind = ZeroKind::kCrossing) {
  EXPECT_TRUE(search.Complete()) << ToString(search.status);
  ASSERT_EQ(search.zeros.size(), roots.size());
  for (std::size_t k = 0; k < roots.size(); ++k) {
    EXPECT_NEAR(search.zeros[k].t, roots[k], tolerance) << "zero " << k;
    EXPECT_EQ(search.zeros[k].kind, kind) << "zero " << k;
  }
}

// t0 + k step for k = 0, 1, ... while <= end.
std::vector<double> Progression(double t0, double step, double end) {
  std::vector<double> roots;
  for (int k = 0; t0 + k * step <= end; ++k) roots.push_back(t0 + k * step);
  return roots;
}

TEST(ExponentialSumZeros, FindsTheZerosOfADampedCosine) {
  const ExponentialSum f({{0, -0.3, {2.0, 1.0, 0.0}}});  // e^{-0.3 t} cos 2t
  ExpectZerosAt(Zeros(f, 0.0, 20.0, kAll), Progression(kPi / 4, kPi / 2, 20.0), 1e-12);
}

TEST(ExponentialSumZeros, FindsTheZerosOfGrowingExponentials) {
  // (e^t - 1)(e^t - 2) = e^{2t} - 3 e^t + 2: zeros at 0 and ln 2.
  const ExponentialSum f({{0, 2.0, {0.0, 1.0, 0.0}}, {0, 1.0, {0.0, -3.0, 0.0}}, {0, 0.0, {0.0, 2.0, 0.0}}});
  ExpectZerosAt(Zeros(f, -1.0, 3.0, kAll), {0.0, std::log(2.0)}, 1e-12);
  // A growing sine, e^{0.7 t} sin t, crosses at k pi.
  const ExponentialSum g({{0, 0.7, {1.0, 0.0, 1.0}}});
  ExpectZerosAt(Zeros(g, 0.5, 20.0, kAll), Progression(kPi, kPi, 20.0), 1e-12);
}

TEST(ExponentialSumZeros, FindsBothRootsOfTTimesADecayMinusAConstant) {
  // t e^{-t} = c at t and 2t when e^{t} = 2: the roots ln 2 and 2 ln 2 for c = ln 2 / 2.
  const double ln2 = std::log(2.0);
  const ExponentialSum f({{1, -1.0, {0.0, 1.0, 0.0}}, {0, 0.0, {0.0, -ln2 / 2.0, 0.0}}});
  ExpectZerosAt(Zeros(f, 0.0, 5.0, kAll), {ln2, 2.0 * ln2}, 1e-12);
}

TEST(ExponentialSumZeros, FindsTheRootsOfAPolynomialGivenAsPowerTerms) {
  // (t - 1)(t - 2) = t^2 - 3 t + 2, and the same damped: e^{-t} (t - 1)(t - 2).
  const ExponentialSum f({{2, 0.0, {0.0, 1.0, 0.0}}, {1, 0.0, {0.0, -3.0, 0.0}}, {0, 0.0, {0.0, 2.0, 0.0}}});
  ExpectZerosAt(Zeros(f, 0.0, 3.0, kAll), {1.0, 2.0}, 1e-12);
  const ExponentialSum g({{2, -1.0, {0.0, 1.0, 0.0}}, {1, -1.0, {0.0, -3.0, 0.0}}, {0, -1.0, {0.0, 2.0, 0.0}}});
  ExpectZerosAt(Zeros(g, -0.5, 30.0, kAll), {1.0, 2.0}, 1e-12);
}

TEST(ExponentialSumZeros, FindsTheZerosOfDampedUndampedAndGrowingTermsTogether) {
  // (0.5 + e^{-0.2 t} + 0.1 e^{0.1 t}) cos 3t vanishes exactly where cos 3t does.
  const ExponentialSum f({{0, 0.0, {3.0, 0.5, 0.0}}, {0, -0.2, {3.0, 1.0, 0.0}}, {0, 0.1, {3.0, 0.1, 0.0}}});
  ExpectZerosAt(Zeros(f, 0.0, 15.0, kAll), Progression(kPi / 6, kPi / 3, 15.0), 1e-12);
}

TEST(ExponentialSumZeros, ReportsTheDoubleZerosOfADampedOneMinusCosineAsTouches) {
  // e^{-0.1 t} (1 - cos t) >= 0 touches zero at 2 pi k, where e^{-0.1 t} has shrunk it to 0.15.
  const ExponentialSum f({{0, -0.1, {0.0, 1.0, 0.0}}, {0, -0.1, {1.0, -1.0, 0.0}}});
  ExpectZerosAt(Zeros(f, 0.5, 20.0, kAll), {2 * kPi, 4 * kPi, 6 * kPi}, 1e-7, ZeroKind::kTouch);
  // From the double zero at 0 (f = f' = 0), the next is the touch at 2 pi.
  ExpectZerosAt(Zeros(f, 0.0, 7.0, kAll), {2 * kPi}, 1e-7, ZeroKind::kTouch);
  // Strongly damped, e^{-20 t} (1 - cos 5t): at 2 pi k/5 it has decayed to ~1e-11 .. 1e-44, and is
  // judged against the size of its terms there.
  const ExponentialSum g({{0, -20.0, {0.0, 1.0, 0.0}}, {0, -20.0, {5.0, -1.0, 0.0}}});
  ExpectZerosAt(Zeros(g, 0.1, 6.0, kAll), Progression(2 * kPi / 5, 2 * kPi / 5, 6.0), 1e-7, ZeroKind::kTouch);
}

TEST(ExponentialSumZeros, SkipsTheDoubleZeroAtTheStartOfAStronglyGrowingOneMinusCosine) {
  // e^{5t} (1 - cos t): the bound over all of [0, 20] is e^{100} times too large near 0; the
  // exclusion after the start must still clear the rounding there.
  const ExponentialSum f({{0, 5.0, {0.0, 1.0, 0.0}}, {0, 5.0, {1.0, -1.0, 0.0}}});
  ExpectZerosAt(Zeros(f, 0.0, 20.0, kAll), {2 * kPi, 4 * kPi, 6 * kPi}, 1e-7, ZeroKind::kTouch);
}

TEST(ExponentialSumZeros, SeparatesTwoDampedZerosAThousandthApart) {
  // e^{-0.5 t} (cos(t - 5) - cos 1e-3): zeros at 5 -+ 1e-3, positive in between.
  const double delta = 1e-3;
  const ExponentialSum f({{0, -0.5, {1.0, std::cos(5.0), std::sin(5.0)}}, {0, -0.5, {0.0, -std::cos(delta), 0.0}}});
  ExpectZerosAt(Zeros(f, 0.0, 6.0, kAll), {5.0 - delta, 5.0 + delta}, 1e-12);
}

TEST(ExponentialSumZeros, FindsTheZerosOfAStronglyDampedCosineWithBoundedWork) {
  // e^{-50 t} cos 2t on [0, 10]: the last zeros lie where f is ~1e-170, far below any absolute
  // tolerance, and the products of its values underflow.
  const ExponentialSum f({{0, -50.0, {2.0, 1.0, 0.0}}});
  const ZeroSearch search = Zeros(f, 0.0, 10.0, kAll);
  ExpectZerosAt(search, Progression(kPi / 4, kPi / 2, 10.0), 1e-12);
  EXPECT_LT(search.intervals, 20000);
  // e^{-50 t} - 1/2 and (e^{-50 t} + 1e-3) cos 2t.
  ExpectZerosAt(Zeros(ExponentialSum({{0, -50.0, {0.0, 1.0, 0.0}}, {0, 0.0, {0.0, -0.5, 0.0}}}), 0.0, 10.0, kAll),
                    {std::log(2.0) / 50.0}, 1e-14);
  ExpectZerosAt(Zeros(ExponentialSum({{0, -50.0, {2.0, 1.0, 0.0}}, {0, 0.0, {2.0, 1e-3, 0.0}}}), 0.0, 10.0, kAll),
                    Progression(kPi / 4, kPi / 2, 10.0), 1e-12);
}

TEST(ExponentialSumZeros, FindsTheZerosOfAStronglyGrowingSineWithBoundedWork) {
  // e^{5 t} sin 3t on (0, 20], growing by e^{100}; and e^{5 t} - e^{50}, zero at 10.
  const ExponentialSum f({{0, 5.0, {3.0, 0.0, 1.0}}});
  const ZeroSearch search = Zeros(f, 0.0, 20.0, kAll);
  ExpectZerosAt(search, Progression(kPi / 3, kPi / 3, 20.0), 1e-12);
  EXPECT_LT(search.intervals, 20000);
  const ExponentialSum g({{0, 5.0, {0.0, 1.0, 0.0}}, {0, 0.0, {0.0, -std::exp(50.0), 0.0}}});
  ExpectZerosAt(Zeros(g, 0.0, 20.0, kAll), {10.0}, 1e-13);
}

TEST(ExponentialSumZeros, EndsNotBoundedWhereTheExponentialOverflowsAfterTheZerosBefore) {
  // e^{5 t} sin 3t overflows past t ~ 142: the zeros before are found, then the search says it
  // could not go on.
  // Both polishings: the jet's steps must neither overflow nor stop on a value that did.
  const ExponentialSum f({{0, 5.0, {3.0, 0.0, 1.0}}});
  for (const auto polish : kPolishes) {
    SCOPED_TRACE(static_cast<int>(polish));
    const auto start = std::chrono::steady_clock::now();
    const ZeroSearch search = Zeros(f, 0.0, 200.0, kAll, {.polish = polish});
    EXPECT_LT(SecondsSince(start), 1.0);
    EXPECT_EQ(search.status, ZeroSearchStatus::kNotBounded);
    EXPECT_STREQ(ToString(search.status), "not bounded");
    EXPECT_LT(search.intervals, 100000);
    ASSERT_GE(search.zeros.size(), 130u);
    for (std::size_t k = 0; k < search.zeros.size(); ++k) {
      EXPECT_NEAR(search.zeros[k].t, static_cast<double>(k + 1) * kPi / 3, 1e-12);
    }
    EXPECT_LT(search.zeros.back().t, 142.0);
  }
}

TEST(ExponentialSumZeros, PolishesToTheRootWhereTheSlopeIsSmallAgainstTheCurvature) {
  // t^2 - 1e-16 from t = 1e-17: its one zero is at 1e-8. Near the start g' is tiny against g'',
  // where Halley's step is small however far the root is: it must not pass for convergence.
  const ExponentialSum f({{2, 0.0, {0.0, 1.0, 0.0}}, {0, 0.0, {0.0, -1e-16, 0.0}}});
  for (const auto polish : kPolishes) {
    const ZeroSearch search = Zeros(f, 1e-17, 3.0, kAll, {.polish = polish});
    ASSERT_EQ(search.zeros.size(), 1u) << static_cast<int>(polish);
    EXPECT_NEAR(search.zeros[0].t, 1e-8, 1e-13) << static_cast<int>(polish);
  }
}

TEST(ExponentialSumZeros, PolishesAcrossABracketOfAHundredDecades) {
  // t^2 - 1 on (1e-10, 1e100]: one zero, at 1, polished from a bracket the bounds prove monotone.
  const ExponentialSum f({{2, 0.0, {0.0, 1.0, 0.0}}, {0, 0.0, {0.0, -1.0, 0.0}}});
  const ZeroSearch search = Zeros(f, 1e-10, 1e100, kAll, {.polish = ZeroSearchOptions::Polish::kJet});
  ASSERT_EQ(search.zeros.size(), 1u);
  EXPECT_NEAR(search.zeros[0].t, 1.0, 1e-13);
}

TEST(ExponentialSumZeros, EndsNotBoundedWhereEveryTermUnderflows) {
  // e^{-t} cos t on [0, 1e300]: below e^{-708} it cannot be told from zero.
  const ExponentialSum f({{0, -1.0, {1.0, 1.0, 0.0}}});
  for (const auto polish : kPolishes) {
    SCOPED_TRACE(static_cast<int>(polish));
    const ZeroSearch search = Zeros(f, 0.0, 1e300, kAll, {.polish = polish});
    EXPECT_EQ(search.status, ZeroSearchStatus::kNotBounded);
    ASSERT_GE(search.zeros.size(), 200u);
    for (std::size_t k = 0; k < search.zeros.size(); ++k) {
      EXPECT_NEAR(search.zeros[k].t, (static_cast<double>(k) + 0.5) * kPi, 1e-11);
    }
  }
}

TEST(ExponentialSumZeros, ReportsNonFiniteCoefficientsAndEndsAsNotFinite) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const ExponentialSum ok({{0, -0.3, {2.0, 1.0, 0.0}}});
  const std::vector<ExponentialTerm> hostile = {{0, -0.3, {2.0, nan, 0.0}}, {0, inf, {2.0, 1.0, 0.0}},
                                                {1, 0.0, {nan, 1.0, 0.0}}, {0, 0.0, {1.0, 1.0, -inf}}};
  for (const ExponentialTerm& term : hostile) {
    const ExponentialSum f({{0, 0.0, {1.0, 0.5, 0.0}}, term});
    const ZeroSearch search = Zeros(f, 0.0, 10.0, kAll);
    EXPECT_EQ(search.status, ZeroSearchStatus::kNotFinite);
    EXPECT_TRUE(search.zeros.empty());
  }
  EXPECT_EQ(Zeros(ok, 0.0, nan, kAll).status, ZeroSearchStatus::kNotFinite);
  EXPECT_EQ(Zeros(ok, -inf, 1.0, kAll).status, ZeroSearchStatus::kNotFinite);
  EXPECT_TRUE(std::isnan(Minimum(ExponentialSum({{0, 0.0, {1.0, nan, 0.0}}}), 0.0, 1.0).value));
}

TEST(ExponentialSumZeros, HandlesHugeCoefficientsOrSaysItCannot) {
  // 1e300 e^{-0.3 t} cos 2t: the bounds stay finite, the zeros are those of the damped cosine.
  const ExponentialSum big({{0, -0.3, {2.0, 1e300, 0.0}}});
  ExpectZerosAt(Zeros(big, 0.0, 20.0, kAll), Progression(kPi / 4, kPi / 2, 20.0), 1e-12);
  // 1e300 cos(1e5 t): |f''| <= 1e310 overflows, so nothing can be proved.
  const ExponentialSum fast({{0, 0.0, {1e5, 1e300, 0.0}}});
  const ZeroSearch search = Zeros(fast, 0.0, 1.0, kAll);
  EXPECT_EQ(search.status, ZeroSearchStatus::kNotBounded);
  EXPECT_LT(search.intervals, 10000);
  // e^{800 t}: sigma t overflows at once past t ~ 0.89; the zero of e^{800 t} cos 2t at pi/4 is
  // found first.
  const ZeroSearch overflow = Zeros(ExponentialSum({{0, 800.0, {2.0, 1.0, 0.0}}}), 0.0, 2.0, kAll);
  EXPECT_EQ(overflow.status, ZeroSearchStatus::kNotBounded);
  ASSERT_EQ(overflow.zeros.size(), 1u);
  EXPECT_NEAR(overflow.zeros[0].t, kPi / 4, 1e-13);
}

TEST(ExponentialSumZeros, ReturnsNothingForNoCountOrAnEmptyInterval) {
  const ExponentialSum f({{0, -0.3, {2.0, 1.0, 0.0}}});
  const ZeroSearch none = Zeros(f, 0.0, 10.0, 0);
  EXPECT_TRUE(none.Complete());
  EXPECT_TRUE(none.zeros.empty());
  const ZeroSearch reversed = Zeros(f, 10.0, 0.0, kAll);
  EXPECT_TRUE(reversed.Complete());
  EXPECT_TRUE(reversed.zeros.empty());
  EXPECT_EQ(reversed.intervals, 0);
}

TEST(ExponentialSumZeros, ReportsTheZeroFunctionAsNotBounded) {
  // Every time is a zero of f = 0: no list of zeros is complete.
  for (const ExponentialSum& f : {ExponentialSum(), ExponentialSum({{1, -2.0, {3.0, 0.0, 0.0}}})}) {
    const ZeroSearch search = Zeros(f, 0.0, 1.0, kAll);
    EXPECT_EQ(search.status, ZeroSearchStatus::kNotBounded);
    EXPECT_LT(search.intervals, 1000);
  }
}

TEST(ExponentialSumZeros, StopsAtTheSubIntervalBound) {
  ZeroSearchOptions options;
  options.max_intervals = 1000;
  const ZeroSearch search = Zeros(ExponentialSum({{0, 0.0, {1.0, 1.0, 0.0}}}), 0.0, 1e6, kAll, options);
  EXPECT_EQ(search.status, ZeroSearchStatus::kTooManyIntervals);
  EXPECT_EQ(search.intervals, 1000);
  ASSERT_FALSE(search.zeros.empty());
  EXPECT_NEAR(search.zeros.front().t, kPi / 2, 1e-12);
}

TEST(ExponentialSum, LeavesOutASineOfZeroFrequencyWhereItsExponentialOverflows) {
  // b sin(0 t) e^{800 t} is zero at every time; at t = 1 its exponential overflows, and
  // 0 * inf would make f(1) = cos(t) NaN.
  const ExponentialSum f({{0, 0.0, {1.0, 1.0, 0.0}}, {0, 800.0, {0.0, 0.0, 2.0}}});
  EXPECT_DOUBLE_EQ(f(1.0), std::cos(1.0));
  EXPECT_DOUBLE_EQ(f.JetAt(1.0).slope, -std::sin(1.0));
  EXPECT_DOUBLE_EQ(f.DerivativeBound(0, 1.0, 1.0), 1.0);
  EXPECT_DOUBLE_EQ(f.Derivative()(1.0), -std::sin(1.0));
}

TEST(ExponentialSum, RejectsANegativePower) {
  EXPECT_THROW(ExponentialSum({{-1, 0.0, {1.0, 1.0, 0.0}}}), InvalidInput);
}

TEST(ExponentialSum, JetAndDerivativeMatchFiniteDifferences) {
  const ExponentialSum f({{2, -0.4, {1.3, 0.7, -0.2}}, {1, 0.3, {0.0, 0.5, 0.0}}, {0, 0.1, {2.1, -0.3, 0.9}}});
  const ExponentialSum df = f.Derivative();
  const double h = 1e-5;
  for (double t : {-1.2, 0.0, 0.7, 3.1}) {
    const ExponentialSum::Jet jet = f.JetAt(t);
    EXPECT_NEAR(jet.value, f(t), 1e-14);
    EXPECT_NEAR(jet.slope, (f(t + h) - f(t - h)) / (2 * h), 1e-8);
    EXPECT_NEAR(jet.curvature, (f(t + h) - 2 * f(t) + f(t - h)) / (h * h), 1e-4);
    EXPECT_NEAR(df(t), jet.slope, 1e-13);
    EXPECT_NEAR(df.JetAt(t).slope, jet.curvature, 1e-13);
  }
  const ExponentialSum g = f.Affine(-2.0, 0.5);
  EXPECT_NEAR(g(0.7), -2.0 * f(0.7) + 0.5, 1e-15);
}

TEST(ExponentialSum, DerivativeBoundsHoldOnTheirInterval) {
  // Each bound over [l, r] is at least the largest |f^(n)| sampled there (f^(n) by repeated
  // Derivative, itself checked above against finite differences).
  const ExponentialSum f({{2, -0.4, {1.3, 0.7, -0.2}}, {1, 0.9, {0.0, 0.5, 0.0}}, {0, -1.5, {2.1, -0.3, 0.9}}});
  for (const auto& [l, r] : std::vector<std::pair<double, double>>{{-2.0, -1.0}, {-0.5, 0.5}, {1.0, 4.0}}) {
    ExponentialSum g = f;
    for (int order = 0; order <= 4; ++order) {
      double largest = 0.0;
      for (int i = 0; i <= 1000; ++i) largest = std::max(largest, std::abs(g(l + (r - l) * i / 1000.0)));
      EXPECT_GE(f.DerivativeBound(order, l, r), largest) << "order " << order << " on [" << l << ", " << r << "]";
      g = g.Derivative();
    }
  }
}

TEST(ExponentialSumMinimumAndMaximum, FindsTheMaximumOfTTimesADecay) {
  // t e^{-t} is largest at t = 1, e^{-1}; on [0, 5] its minimum is 0 at t = 0.
  const ExponentialSum f({{1, -1.0, {0.0, 1.0, 0.0}}});
  const Extrema e = MinimumAndMaximum(f, 0.0, 5.0);
  EXPECT_NEAR(e.maximum.t, 1.0, 1e-7);
  EXPECT_NEAR(e.maximum.value, std::exp(-1.0), 1e-15);
  EXPECT_EQ(e.minimum.t, 0.0);
  EXPECT_EQ(Minimum(f, 0.0, 5.0).value, 0.0);
}

// Random sums t^m e^{sigma t} (a cos nu t + b sin nu t) with a fixed seed.
ExponentialSum RandomSum(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> coefficient(-1.0, 1.0), rate(-2.0, 2.0), frequency(0.0, 5.0);
  std::vector<ExponentialTerm> terms(1 + rng() % 4);
  for (ExponentialTerm& term : terms) {
    term = {static_cast<int>(rng() % 3), rate(rng), {frequency(rng), coefficient(rng), coefficient(rng)}};
  }
  return ExponentialSum(std::move(terms));
}

// The sign changes of f seen by n samples over [a, b], each bisected down to rounding.
std::vector<double> SampledSignChanges(const ExponentialSum& f, double a, double b, int n) {
  std::vector<double> roots;
  double tl = a, fl = f(a);
  for (int i = 1; i <= n; ++i) {
    const double tr = a + (b - a) * i / n;
    const double fr = f(tr);
    if ((fl < 0.0 && fr > 0.0) || (fl > 0.0 && fr < 0.0)) {
      double lo = tl, hi = tr;
      for (int k = 0; k < 200 && hi - lo > 1e-15 * std::max(1.0, std::abs(lo)); ++k) {
        const double mid = 0.5 * (lo + hi);
        ((f(mid) < 0.0) == (fl < 0.0) ? lo : hi) = mid;
      }
      roots.push_back(0.5 * (lo + hi));
    }
    tl = tr;
    fl = fr;
  }
  return roots;
}

TEST(ExponentialSumZeros, FindsEverySignChangeADenseSamplerSeesAndNoFalseCrossing) {
  std::mt19937_64 rng(20240521);
  std::uniform_real_distribution<double> start(-3.0, 3.0), length(0.5, 6.0);
  int checked = 0;
  for (int n = 0; n < 300; ++n) {
    const ExponentialSum f = RandomSum(rng);
    const double a = start(rng);
    const double b = a + length(rng);
    const ZeroSearch search = Zeros(f, a, b, kAll);
    ASSERT_TRUE(search.Complete()) << "sum " << n;
    for (double root : SampledSignChanges(f, a, b, 20000)) {
      const bool found = std::any_of(search.zeros.begin(), search.zeros.end(),
                                     [root](const Zero& z) { return std::abs(z.t - root) <= 1e-9; });
      EXPECT_TRUE(found) << "sum " << n << ": sign change at " << root << " missed";
      ++checked;
    }
    // Every zero reported is one: |f| there is at rounding level of its size.
    const double size = f.DerivativeBound(0, a, b) + f.DerivativeBound(1, a, b);
    for (const Zero& z : search.zeros) EXPECT_LE(std::abs(f(z.t)), 1e-11 * size) << "sum " << n << " at " << z.t;
  }
  EXPECT_GT(checked, 300);
}

TEST(ExponentialSumZeros, AgreesWithTheSinusoidSumFinderOnPureSinusoids) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> coefficient(-1.0, 1.0), frequency(0.1, 5.0), length(1.0, 30.0);
  for (int n = 0; n < 200; ++n) {
    SinusoidTerms sinusoids(1 + rng() % 3);
    for (Sinusoid& s : sinusoids) s = {frequency(rng), coefficient(rng), coefficient(rng)};
    const double constant = coefficient(rng), slope = n % 2 == 0 ? 0.0 : 0.05 * coefficient(rng);
    const SinusoidSum f(constant, slope, sinusoids);
    const ExponentialSum g = ExponentialSum::OfSinusoids(constant, slope, sinusoids);
    const double b = length(rng);
    const ZeroSearch expected = Zeros(f, 0.0, b, kAll);
    const ZeroSearch found = Zeros(g, 0.0, b, kAll);
    ASSERT_TRUE(found.Complete());
    ASSERT_EQ(found.zeros.size(), expected.zeros.size()) << "sum " << n;
    for (std::size_t k = 0; k < found.zeros.size(); ++k) {
      EXPECT_NEAR(found.zeros[k].t, expected.zeros[k].t, 1e-13) << "sum " << n;
      EXPECT_EQ(found.zeros[k].kind, expected.zeros[k].kind) << "sum " << n;
    }
  }
}

}  // namespace
}  // namespace stickslip
