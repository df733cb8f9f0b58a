#include "stickslip/numerics/integral_of_square.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <vector>

#include <boost/math/quadrature/gauss.hpp>

#include "stickslip/invalid_input.hpp"

namespace stickslip {

namespace {

using Complex = std::complex<double>;

// K_M(z) = int_0^1 u^M e^{z u} du for M <= 2 (see the header): a series of terms of one sign in
// the real part where |z| <= M + 1, e^z's own where Re z < 0, upward recursion beyond.
Complex UnitIntegral(int m, Complex z) {
  if (std::abs(z) > m + 1.0) {
    const Complex e = std::exp(z);
    Complex k = (e - 1.0) / z;
    for (int j = 1; j <= m; ++j) k = (e - double(j) * k) / z;
    return k;
  }
  // sum_j z^j / (j! (M + j + 1)) for Re z >= 0; e^z sum_j (-z)^j M! / (M + 1 + j)! for Re z < 0.
  // With |z| <= 3 the terms fall below 1e-17 of the sum within 30 of them.
  const bool decaying = z.real() < 0.0;
  const Complex w = decaying ? -z : z;
  Complex sum = 0.0, power = 1.0;  // power: w^j / j!, or w^j M! / (M + j)!
  for (int j = 0; j < 40; ++j) {
    const Complex term = power / double(m + j + 1);
    sum += term;
    if (std::abs(term) <= 1e-17 * std::abs(sum)) return decaying ? std::exp(z) * sum : sum;
    power *= w / double(decaying ? m + j + 1 : j + 1);
  }
  return {std::numeric_limits<double>::quiet_NaN(), 0.0};  // not reached for |z| <= 3
}

// int_0^d t^M e^{lambda t} dt.
Complex PowerExponentialIntegral(int m, Complex lambda, double d) {
  return std::pow(d, m + 1) * UnitIntegral(m, lambda * d);
}

// int_0^d f^2 dt from f's values, by 20-point Gauss-Legendre on panels where every term turns by at
// most a radian (|lambda| h <= 1), on which it is exact to rounding; NaN beyond kMaxPanels.
constexpr double kMaxPanels = 1e5;
double QuadratureOfSquare(const ExponentialSum& f, double d) {
  double reach = 0.0;  // the largest |lambda|
  for (const ExponentialTerm& term : f.terms()) {
    if (!Vanishes(term)) reach = std::max(reach, std::abs(Complex(term.rate, term.sinusoid.frequency)));
  }
  const double panels = std::ceil(reach * d) + 1.0;
  if (!(panels <= kMaxPanels)) return std::numeric_limits<double>::quiet_NaN();
  const int count = static_cast<int>(panels);
  double sum = 0.0;
  for (int i = 0; i < count; ++i) {
    sum += boost::math::quadrature::gauss<double, 20>::integrate(
        [&f](double t) {
          const double value = f(t);
          return value * value;
        },
        d * i / count, d * (i + 1) / count);
  }
  return sum;
}

}  // namespace

double IntegralOfSquare(const ExponentialSum& f, double d) {
  if (!(d >= 0.0 && d <= std::numeric_limits<double>::max())) throw InvalidInput("duration", d, "0 <= duration, finite");
  const std::vector<ExponentialTerm>& terms = f.terms();
  for (const ExponentialTerm& term : terms) {
    if (term.power > 1) throw InvalidInput("power", term.power, "0 or 1 (a constant or a drift times the exponential)");
  }
  double sum = 0.0, scale = 0.0;  // scale: int (sum_k |c_k| t^{m_k} e^{sigma_k t})^2 dt, the rounding's
  for (std::size_t j = 0; j < terms.size(); ++j) {
    const Sinusoid& a = terms[j].sinusoid;
    if (Vanishes(terms[j])) continue;
    const Complex cj(a.cos_coefficient, -a.sin_coefficient), lj(terms[j].rate, a.frequency);
    for (std::size_t k = j; k < terms.size(); ++k) {
      const Sinusoid& b = terms[k].sinusoid;
      if (Vanishes(terms[k])) continue;
      const Complex ck(b.cos_coefficient, -b.sin_coefficient), lk(terms[k].rate, b.frequency);
      const int m = terms[j].power + terms[k].power;
      const double pair = 0.5 * (cj * ck * PowerExponentialIntegral(m, lj + lk, d) +
                                 cj * std::conj(ck) * PowerExponentialIntegral(m, lj + std::conj(lk), d))
                                    .real();
      const double size = std::abs(cj) * std::abs(ck) * PowerExponentialIntegral(m, lj.real() + lk.real(), d).real();
      sum += k == j ? pair : 2.0 * pair;  // the pair (j, k) and (k, j): conjugate integrals, equal real parts
      scale += k == j ? size : 2.0 * size;
    }
  }
  // Terms that cancel to a much smaller f (a slip near critical damping: two nearly equal rates with
  // large opposite coefficients) would leave the closed form's rounding, about eps scale, above
  // 1e-12 of the result, while f's values lose only the square root of that: integrated from them.
  if (scale > 1e3 * sum) sum = QuadratureOfSquare(f, d);
  return std::max(sum, 0.0);  // a square's integral; rounding below zero where f is nearly 0 (NaN stays)
}

double IntegralOfSquare(const SinusoidSum& f, double d) {
  return IntegralOfSquare(ExponentialSum::OfSinusoids(f.constant(), f.slope(), f.terms()), d);
}

}  // namespace stickslip
