// Functions of time of the form
//   f(t) = sum_k t^{m_k} e^{sigma_k t} (a_k cos(nu_k t) + b_k sin(nu_k t)),
// the form every coordinate and every event function of a linear oscillator with viscous damping
// takes inside one mode: each eigenvalue sigma + i nu contributes a damped (sigma < 0), growing
// (sigma > 0) or undamped sinusoid, with a polynomial factor t^m where the eigenvalue is repeated
// (a constant is m = sigma = nu = 0, a drift c t is m = 1, sigma = nu = 0).
//
// The root finder on them has the guarantee of sinusoid_sum.hpp's, by the same search: it
// excludes an interval only where a bound on |f''| proves f has no zero there. The bounds hold on
// each sub-interval [l, r] (e^{sigma t} and t^m grow or decay), from Leibniz's rule with
// lambda = sigma + i nu,
//   |d^n/dt^n t^m e^{lambda t}| <= sum_{j <= min(n, m)} C(n, j) m!/(m-j)! |t|^{m-j} |lambda|^{n-j} e^{sigma t},
// with |t| <= max(|l|, |r|) and e^{sigma t} <= e^{sigma r} (sigma > 0) or e^{sigma l} (sigma < 0).
// "Zero" is judged against the size of the terms where f is tested, so that a decayed tail is not
// taken for zero. Where f or a bound overflows, or every term underflows (as for f = 0, where
// every time is a zero), the search says so (kNotBounded) instead of claiming completeness.
#pragma once

#include <vector>

#include "stickslip/numerics/sinusoid_sum.hpp"
#include "stickslip/numerics/zero_search.hpp"

namespace stickslip {

// t^power e^{rate t} times a sinusoid a cos(nu t) + b sin(nu t).
struct ExponentialTerm {
  int power = 0;      // m >= 0: the polynomial factor of a repeated (or zero) eigenvalue
  double rate = 0.0;  // sigma: < 0 damped, > 0 growing
  Sinusoid sinusoid;
};

// A term that is zero at every time (no coefficients, or b sin(0 t)): left out wherever a term is
// evaluated, so that 0 e^{sigma t} never becomes NaN where the exponential overflows.
inline bool Vanishes(const ExponentialTerm& term) {
  const Sinusoid& s = term.sinusoid;
  return s.cos_coefficient == 0.0 && (s.sin_coefficient == 0.0 || s.frequency == 0.0);
}

class ExponentialSum {
 public:
  ExponentialSum() = default;
  // Throws InvalidInput if a term's power is negative.
  explicit ExponentialSum(std::vector<ExponentialTerm> terms);
  // c0 + c1 t + sum_k (a_k cos(nu_k t) + b_k sin(nu_k t)): the function SinusoidSum(constant,
  // slope, sinusoids) is.
  static ExponentialSum OfSinusoids(double constant, double slope, const SinusoidTerms& sinusoids);

  double operator()(double t) const;
  // f(t), f'(t), f''(t) (as for a SinusoidSum), at the cost of one exponential, sine and cosine
  // per term.
  using Jet = SinusoidSum::Jet;
  Jet JetAt(double t) const;
  ExponentialSum Derivative() const;
  ExponentialSum Affine(double k, double c) const;  // k f + c
  // A bound on sup over [l, r] of |f^(order)(t)|, for order >= 0 (order 0: the sum of the terms'
  // magnitudes, the size against which "zero" is judged; at l = r = t, their size at t).
  double DerivativeBound(int order, double l, double r) const;
  // Every coefficient, rate and frequency finite.
  bool IsFinite() const;
  const std::vector<ExponentialTerm>& terms() const { return terms_; }

 private:
  std::vector<ExponentialTerm> terms_;
};

// The size of f's terms at t, against which "zero" is judged there.
inline double SizeAt(const ExponentialSum& f, double t) { return f.DerivativeBound(0, t, t); }

// The zeros of f in (a, b], in increasing order, at most max_count of them, with the conventions
// of the Zeros of sinusoid_sum.hpp: a zero at a itself is skipped (one heading for zero at once is
// reported), every zero of odd multiplicity is found, one of even multiplicity as a touch when
// the extremum lies within touch_tolerance of zero (relative to the size of the terms there).
// Only a complete search proves there is no other zero.
ZeroSearch Zeros(const ExponentialSum& f, double a, double b, int max_count, const ZeroSearchOptions& options = {});

// The minimum of f over [a, b]; NaN if the search for the zeros of f' was not complete.
Extremum Minimum(const ExponentialSum& f, double a, double b, const ZeroSearchOptions& options = {});

// The minimum and maximum of f over [a, b] from one search for the zeros of f'; both NaN if that
// search was not complete.
Extrema MinimumAndMaximum(const ExponentialSum& f, double a, double b, const ZeroSearchOptions& options = {});

}  // namespace stickslip
