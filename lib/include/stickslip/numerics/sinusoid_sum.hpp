// Functions of time of the form f(t) = c0 + c1 t + sum_k (a_k cos(nu_k t) + b_k sin(nu_k t)),
// the form every coordinate and every event function of the oscillator takes inside one mode,
// and a root finder on them that cannot miss a root: it excludes an interval only where a
// bound on |f''| proves f has no zero there. (The search is the one of exponential_sum.hpp, whose
// sums of damped and growing terms include these; here its bounds hold on the whole line.)
#pragma once

#include <array>
#include <optional>
#include <vector>

#include <boost/container/small_vector.hpp>

#include "stickslip/numerics/zero_search.hpp"

namespace stickslip {

struct Sinusoid {
  double frequency = 0.0;
  double cos_coefficient = 0.0;
  double sin_coefficient = 0.0;
};

// A coordinate of an oscillator of n degrees of freedom has at most n + 1 terms (its modes and the
// forcing): held inline up to that for small n, so that the root finder's many short-lived sums
// (derivatives, constraints) never allocate.
using SinusoidTerms = boost::container::small_vector<Sinusoid, 4>;

class SinusoidSum {
 public:
  SinusoidSum() = default;
  SinusoidSum(double constant, double slope, SinusoidTerms terms)
      : constant_(constant), slope_(slope), terms_(std::move(terms)) {}

  double operator()(double t) const;
  // f(t), f'(t), f''(t) at the cost of one sine and cosine per term.
  struct Jet {
    double value, slope, curvature;
  };
  Jet JetAt(double t) const;
  // k f + c, for the constraints G = s + eta u_r and G1 = -s + eta u_r.
  SinusoidSum Affine(double k, double c) const;
  SinusoidSum Derivative() const;
  // A bound on sup_t |f^(order)(t)|, for order >= 1.
  double DerivativeBound(int order) const;
  // Scale() and DerivativeBound(1) ... DerivativeBound(4) at once (each term's magnitude once).
  std::array<double, 5> ScaleAndDerivativeBounds() const;
  // |c0| + sum_k |(a_k, b_k)|: the size against which "zero" is judged.
  double Scale() const;
  // Every coefficient and frequency finite.
  bool IsFinite() const;
  double constant() const { return constant_; }
  double slope() const { return slope_; }
  const SinusoidTerms& terms() const { return terms_; }

 private:
  double constant_ = 0.0;
  double slope_ = 0.0;
  SinusoidTerms terms_;
};

// The size against which "zero" is judged at t: Scale(), the same at every t (as SizeAt of an
// ExponentialSum, for code written for both).
inline double SizeAt(const SinusoidSum& f, double) { return f.Scale(); }

// The zeros of f in (a, b], in increasing order, at most max_count of them. A zero at a itself
// (f(a) = 0 to the touch level, as for x2' at the start of a slip, and f moving away from zero)
// is not reported; the neighbourhood where the Taylor bound proves f has no other zero is
// skipped. If f(a) is at the touch level but moving towards zero, that zero is reported at once. Every zero of f in (a, b] whose
// multiplicity is odd is found; a zero of even multiplicity is found as a touch when the
// extremum lies within touch_tolerance of zero. Only a complete search proves there is no other
// zero; a search cut short says so in its status.
ZeroSearch Zeros(const SinusoidSum& f, double a, double b, int max_count, const ZeroSearchOptions& options = {});

// The minimum of f over [a, b] and where it is attained (an end point or a zero of f'); the value
// is NaN if the search for the zeros of f' was not complete.
Extremum Minimum(const SinusoidSum& f, double a, double b, const ZeroSearchOptions& options = {});

// The minimum and the maximum of f over [a, b] from one search for the zeros of f' (the
// candidates are a, b and those zeros); both values are NaN if that search was not complete.
Extrema MinimumAndMaximum(const SinusoidSum& f, double a, double b, const ZeroSearchOptions& options = {});

}  // namespace stickslip
