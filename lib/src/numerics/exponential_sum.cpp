#include "stickslip/numerics/exponential_sum.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <optional>
#include <vector>

#include "stickslip/invalid_input.hpp"
#include "zero_finder.hpp"

namespace stickslip {

namespace {

using Complex = std::complex<double>;

double Power(double x, int k) {
  double power = 1.0;
  for (int i = 0; i < k; ++i) power *= x;
  return power;
}

// c e^{(sigma + i nu) t} with c = a - i b, whose real part is e^{sigma t} (a cos(nu t) + b sin(nu t)).
Complex Oscillation(const ExponentialTerm& term, double t) {
  const Sinusoid& s = term.sinusoid;
  const double envelope = std::exp(term.rate * t);
  const Complex turn(envelope * std::cos(s.frequency * t), envelope * std::sin(s.frequency * t));
  return Complex(s.cos_coefficient, -s.sin_coefficient) * turn;
}

// sigma + i nu.
Complex Exponent(const ExponentialTerm& term) { return {term.rate, term.sinusoid.frequency}; }

// sup over [l, r] of |d^n/dt^n t^m e^{lambda t}| |c| by Leibniz's rule:
//   d^n (t^m e^{lambda t}) = sum_{j <= min(n, m)} C(n, j) m!/(m-j)! t^{m-j} lambda^{n-j} e^{lambda t},
// each factor bounded by its own sup: |t| <= max(|l|, |r|), e^{sigma t} at the end where it is largest.
double TermBound(const ExponentialTerm& term, int order, double l, double r) {
  const double size = std::hypot(term.sinusoid.cos_coefficient, term.sinusoid.sin_coefficient);
  const double modulus = std::abs(Exponent(term));
  const double reach = std::max(std::abs(l), std::abs(r));
  const double envelope = std::exp(term.rate * (term.rate > 0.0 ? r : l));
  double sum = 0.0;
  double weight = 1.0;  // C(n, j) m!/(m-j)!
  for (int j = 0; j <= std::min(order, term.power); ++j) {
    sum += weight * Power(reach, term.power - j) * Power(modulus, order - j);
    weight *= static_cast<double>(order - j) * static_cast<double>(term.power - j) / (j + 1);
  }
  return size * envelope * sum;
}

// An exponential sum's bounds depend on the interval. Where every term lies below the normal
// range of doubles f has lost its digits and cannot be told from zero: its scale is NaN there,
// which ends the search honestly.
class IntervalBounds {
 public:
  explicit IntervalBounds(const ExponentialSum& f) : f_(f) {}
  detail::DerivativeBounds On(double l, double r) const {
    const double scale = f_.DerivativeBound(0, l, r);
    return {scale >= std::numeric_limits<double>::min() ? scale : std::numeric_limits<double>::quiet_NaN(),
            f_.DerivativeBound(1, l, r), f_.DerivativeBound(2, l, r), f_.DerivativeBound(3, l, r),
            f_.DerivativeBound(4, l, r)};
  }

 private:
  const ExponentialSum& f_;
};

// Undamped (every rate 0), with no polynomial factor but a drift: the sum is a SinusoidSum, whose
// bounds hold on the whole interval at once (no exponential per sub-interval and per term), and
// its search has the same guarantee and conventions. The undamped oscillators' events take it.
std::optional<SinusoidSum> AsSinusoidSum(const ExponentialSum& f) {
  double constant = 0.0, slope = 0.0;
  SinusoidTerms sinusoids;
  for (const ExponentialTerm& e : f.terms()) {
    if (Vanishes(e)) continue;
    if (e.rate != 0.0) return std::nullopt;
    if (e.sinusoid.frequency == 0.0 && e.power <= 1) {
      (e.power == 0 ? constant : slope) += e.sinusoid.cos_coefficient;
    } else if (e.power == 0) {
      sinusoids.push_back(e.sinusoid);
    } else {
      return std::nullopt;
    }
  }
  // f = 0 (every time a zero) stays with the search that reports it as not bounded.
  if (constant == 0.0 && slope == 0.0 && sinusoids.empty()) return std::nullopt;
  return SinusoidSum(constant, slope, std::move(sinusoids));
}

}  // namespace

ExponentialSum::ExponentialSum(std::vector<ExponentialTerm> terms) : terms_(std::move(terms)) {
  for (const ExponentialTerm& term : terms_) {
    if (term.power < 0) throw InvalidInput("power", term.power, "power >= 0");
  }
}

ExponentialSum ExponentialSum::OfSinusoids(double constant, double slope, const SinusoidTerms& sinusoids) {
  std::vector<ExponentialTerm> terms = {{0, 0.0, {0.0, constant, 0.0}}, {1, 0.0, {0.0, slope, 0.0}}};
  for (const Sinusoid& s : sinusoids) terms.push_back({0, 0.0, s});
  return ExponentialSum(std::move(terms));
}

double ExponentialSum::operator()(double t) const {
  double value = 0.0;
  for (const ExponentialTerm& term : terms_) {
    if (Vanishes(term)) continue;
    value += Power(t, term.power) * Oscillation(term, t).real();
  }
  return value;
}

ExponentialSum::Jet ExponentialSum::JetAt(double t) const {
  Jet jet{0.0, 0.0, 0.0};
  for (const ExponentialTerm& term : terms_) {
    if (Vanishes(term)) continue;
    // For w = c e^{lambda t}: (t^m w)' = (m t^{m-1} + lambda t^m) w and
    // (t^m w)'' = (m(m-1) t^{m-2} + 2 lambda m t^{m-1} + lambda^2 t^m) w.
    const int m = term.power;
    const double p0 = Power(t, m);
    const double p1 = m >= 1 ? m * Power(t, m - 1) : 0.0;
    const double p2 = m >= 2 ? m * (m - 1) * Power(t, m - 2) : 0.0;
    const Complex lambda = Exponent(term);
    const Complex w = Oscillation(term, t);
    jet.value += p0 * w.real();
    jet.slope += (p1 * w + p0 * lambda * w).real();
    jet.curvature += (p2 * w + 2.0 * p1 * lambda * w + p0 * lambda * lambda * w).real();
  }
  return jet;
}

ExponentialSum ExponentialSum::Affine(double k, double c) const {
  std::vector<ExponentialTerm> terms;
  terms.reserve(terms_.size() + 1);
  for (const ExponentialTerm& e : terms_) {
    const Sinusoid& s = e.sinusoid;
    terms.push_back({e.power, e.rate, {s.frequency, k * s.cos_coefficient, k * s.sin_coefficient}});
  }
  terms.push_back({0, 0.0, {0.0, c, 0.0}});
  return ExponentialSum(std::move(terms));
}

ExponentialSum ExponentialSum::Derivative() const {
  // (t^m Re(c e^{lambda t}))' = m t^{m-1} Re(c e^{lambda t}) + t^m Re(lambda c e^{lambda t}), and
  // lambda c = a' - i b' for c = a - i b.
  std::vector<ExponentialTerm> terms;
  terms.reserve(2 * terms_.size());
  for (const ExponentialTerm& e : terms_) {
    const Sinusoid& s = e.sinusoid;
    if (Vanishes(e)) continue;
    if (e.power >= 1) {
      const double m = e.power;
      terms.push_back({e.power - 1, e.rate, {s.frequency, m * s.cos_coefficient, m * s.sin_coefficient}});
    }
    const Complex turned = Exponent(e) * Complex(s.cos_coefficient, -s.sin_coefficient);
    if (turned != 0.0) terms.push_back({e.power, e.rate, {s.frequency, turned.real(), -turned.imag()}});
  }
  return ExponentialSum(std::move(terms));
}

double ExponentialSum::DerivativeBound(int order, double l, double r) const {
  double bound = 0.0;
  for (const ExponentialTerm& term : terms_) {
    if (!Vanishes(term)) bound += TermBound(term, order, l, r);
  }
  return bound;
}

bool ExponentialSum::IsFinite() const {
  return std::all_of(terms_.begin(), terms_.end(), [](const ExponentialTerm& e) {
    const Sinusoid& s = e.sinusoid;
    return std::isfinite(e.rate) && std::isfinite(s.frequency) && std::isfinite(s.cos_coefficient) &&
           std::isfinite(s.sin_coefficient);
  });
}

// The entry points of the shared search (zero_finder.hpp) with bounds per sub-interval.
ZeroSearch Zeros(const ExponentialSum& f, double a, double b, int max_count, const ZeroSearchOptions& options) {
  if (const std::optional<SinusoidSum> undamped = AsSinusoidSum(f)) return Zeros(*undamped, a, b, max_count, options);
  return detail::FindZeros<IntervalBounds>(f, a, b, max_count, options);
}
namespace {

// Where f' has decayed to the edge of the normal range of doubles to the end of [a, b] (a slide
// settling onto a steady state), f moves less than (b - a) 2.4e-296 there: constant to rounding. The start of that
// tail, found by bisection on the bound of |f'| (b where there is none).
double FlatTailStart(const ExponentialSum& f, double a, double b) {
  // With headroom over the normal range: the search before the tail bounds f' on its own sub-intervals.
  const auto flat = [&](double t) { return f.DerivativeBound(1, t, b) < 0x1p40 * std::numeric_limits<double>::min(); };
  if (!flat(b) || flat(a)) return flat(a) ? a : b;
  double low = a, high = b;
  for (int k = 0; k < 200 && low < high && std::nextafter(low, high) < high; ++k) {  // bounded: halves to an ulp
    const double middle = low + 0.5 * (high - low);
    (flat(middle) ? high : low) = middle;
  }
  return high;
}

}  // namespace

Extrema MinimumAndMaximum(const ExponentialSum& f, double a, double b, const ZeroSearchOptions& options) {
  if (const std::optional<SinusoidSum> undamped = AsSinusoidSum(f)) return MinimumAndMaximum(*undamped, a, b, options);
  const double tail = FlatTailStart(f, a, b);
  if (tail >= b) return detail::FindExtrema<IntervalBounds>(f, a, b, options);
  // The search up to the flat tail, whose extrema are its ends.
  Extrema e = tail > a ? detail::FindExtrema<IntervalBounds>(f, a, tail, options) : Extrema{{a, f(a)}, {a, f(a)}};
  for (const double t : {tail, b}) {
    if (const double v = f(t); v < e.minimum.value) e.minimum = {t, v};
    if (const double v = f(t); v > e.maximum.value) e.maximum = {t, v};
  }
  return e;
}
Extremum Minimum(const ExponentialSum& f, double a, double b, const ZeroSearchOptions& options) {
  return MinimumAndMaximum(f, a, b, options).minimum;
}

}  // namespace stickslip
