#include "stickslip/numerics/integral_of_square.hpp"

#include <cmath>
#include <complex>
#include <vector>

namespace stickslip {

namespace {

using Complex = std::complex<double>;

// K_M(z) = int_0^1 u^M e^{z u} du (see the header).
Complex UnitIntegral(int m, Complex z) {
  if (std::abs(z) <= m + 1.0) {
    // The terms fall at least geometrically once j > |z|; 60 of them reach rounding for |z| <= M + 1
    // at the powers a linear oscillator's sums have.
    Complex sum = 0.0, power = 1.0;  // power = z^j / j!
    for (int j = 0; j < 60; ++j) {
      const Complex term = power / double(m + j + 1);
      sum += term;
      if (std::abs(term) <= 1e-17 * std::abs(sum)) break;
      power *= z / double(j + 1);
    }
    return sum;
  }
  const Complex e = std::exp(z);
  Complex k = (e - 1.0) / z;
  for (int j = 1; j <= m; ++j) k = (e - double(j) * k) / z;
  return k;
}

// int_0^d t^M e^{lambda t} dt.
Complex PowerExponentialIntegral(int m, Complex lambda, double d) {
  return std::pow(d, m + 1) * UnitIntegral(m, lambda * d);
}

}  // namespace

double IntegralOfSquare(const ExponentialSum& f, double d) {
  const std::vector<ExponentialTerm>& terms = f.terms();
  double sum = 0.0;
  for (std::size_t j = 0; j < terms.size(); ++j) {
    const Sinusoid& a = terms[j].sinusoid;
    if (a.cos_coefficient == 0.0 && a.sin_coefficient == 0.0) continue;  // 0 e^{lambda t} stays 0
    const Complex cj(a.cos_coefficient, -a.sin_coefficient), lj(terms[j].rate, a.frequency);
    for (std::size_t k = j; k < terms.size(); ++k) {
      const Sinusoid& b = terms[k].sinusoid;
      if (b.cos_coefficient == 0.0 && b.sin_coefficient == 0.0) continue;
      const Complex ck(b.cos_coefficient, -b.sin_coefficient), lk(terms[k].rate, b.frequency);
      const int m = terms[j].power + terms[k].power;
      const double pair = 0.5 * (cj * ck * PowerExponentialIntegral(m, lj + lk, d) +
                                 cj * std::conj(ck) * PowerExponentialIntegral(m, lj + std::conj(lk), d))
                                    .real();
      sum += k == j ? pair : 2.0 * pair;  // the pair (j, k) and (k, j)
    }
  }
  return sum;
}

double IntegralOfSquare(const SinusoidSum& f, double d) {
  return IntegralOfSquare(ExponentialSum::OfSinusoids(f.constant(), f.slope(), f.terms()), d);
}

}  // namespace stickslip
