#include "stickslip/numerics/sinusoid_sum.hpp"

#include <algorithm>
#include <cmath>

#include "zero_finder.hpp"

namespace stickslip {

double SinusoidSum::operator()(double t) const {
  double value = constant_ + slope_ * t;
  for (const Sinusoid& s : terms_) {
    value += s.cos_coefficient * std::cos(s.frequency * t) +
             s.sin_coefficient * std::sin(s.frequency * t);
  }
  return value;
}

SinusoidSum::Jet SinusoidSum::JetAt(double t) const {
  Jet jet{constant_ + slope_ * t, slope_, 0.0};
  for (const Sinusoid& s : terms_) {
    const double c = std::cos(s.frequency * t);
    const double n = std::sin(s.frequency * t);
    const double even = s.cos_coefficient * c + s.sin_coefficient * n;
    jet.value += even;
    jet.slope += s.frequency * (s.sin_coefficient * c - s.cos_coefficient * n);
    jet.curvature -= s.frequency * s.frequency * even;
  }
  return jet;
}

SinusoidSum SinusoidSum::Affine(double k, double c) const {
  SinusoidTerms terms = terms_;
  for (Sinusoid& s : terms) {
    s.cos_coefficient *= k;
    s.sin_coefficient *= k;
  }
  return SinusoidSum(k * constant_ + c, k * slope_, std::move(terms));
}

SinusoidSum SinusoidSum::Derivative() const {
  SinusoidTerms terms;
  for (const Sinusoid& s : terms_) {
    terms.push_back({s.frequency, s.frequency * s.sin_coefficient, -s.frequency * s.cos_coefficient});
  }
  return SinusoidSum(slope_, 0.0, std::move(terms));
}

double SinusoidSum::DerivativeBound(int order) const {
  double bound = order == 1 ? std::abs(slope_) : 0.0;
  for (const Sinusoid& s : terms_) {
    double power = 1.0;
    for (int k = 0; k < order; ++k) power *= std::abs(s.frequency);
    bound += std::hypot(s.cos_coefficient, s.sin_coefficient) * power;
  }
  return bound;
}

std::array<double, 5> SinusoidSum::ScaleAndDerivativeBounds() const {
  // The sums of Scale() and DerivativeBound(order), term by term in the same order: the same numbers.
  std::array<double, 5> bounds = {std::abs(constant_), std::abs(slope_), 0.0, 0.0, 0.0};
  for (const Sinusoid& s : terms_) {
    const double magnitude = std::hypot(s.cos_coefficient, s.sin_coefficient);
    bounds[0] += magnitude;
    double power = 1.0;
    for (int order = 1; order <= 4; ++order) {
      power *= std::abs(s.frequency);
      bounds[order] += magnitude * power;
    }
  }
  return bounds;
}

double SinusoidSum::Scale() const {
  double scale = std::abs(constant_);
  for (const Sinusoid& s : terms_) scale += std::hypot(s.cos_coefficient, s.sin_coefficient);
  return scale;
}

bool SinusoidSum::IsFinite() const {
  if (!std::isfinite(constant_) || !std::isfinite(slope_)) return false;
  return std::all_of(terms_.begin(), terms_.end(), [](const Sinusoid& s) {
    return std::isfinite(s.frequency) && std::isfinite(s.cos_coefficient) && std::isfinite(s.sin_coefficient);
  });
}

namespace {

// A sum of sinusoids has bounds that hold on the whole line: computed once, the same on every
// sub-interval.
class GlobalBounds {
 public:
  explicit GlobalBounds(const SinusoidSum& f) {
    const std::array<double, 5> b = f.ScaleAndDerivativeBounds();
    bounds_ = {b[0], b[1], b[2], b[3], b[4]};
  }
  detail::DerivativeBounds On(double /*l*/, double /*r*/) const { return bounds_; }

 private:
  detail::DerivativeBounds bounds_;
};

}  // namespace

ZeroSearch Zeros(const SinusoidSum& f, double a, double b, int max_count, const ZeroSearchOptions& options) {
  return detail::FindZeros<GlobalBounds>(f, a, b, max_count, options);
}

Extremum Minimum(const SinusoidSum& f, double a, double b, const ZeroSearchOptions& options) {
  return MinimumAndMaximum(f, a, b, options).minimum;
}

Extrema MinimumAndMaximum(const SinusoidSum& f, double a, double b, const ZeroSearchOptions& options) {
  return detail::FindExtrema<GlobalBounds>(f, a, b, options);
}

}  // namespace stickslip
