// The one search for the zeros of a function of time that cannot miss a zero: an interval is
// excluded only where a bound on |f''| proves f has no zero there. It serves every function type
// F that offers f(t), f.JetAt(t) (value, slope, curvature), f.Derivative() and f.IsFinite(),
// together with a Bounds type built from f whose On(l, r) returns DerivativeBounds valid on
// [l, r]: SinusoidSum's hold on the whole line, ExponentialSum's depend on the interval.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <boost/container/small_vector.hpp>
#include <boost/math/tools/roots.hpp>

#include "stickslip/numerics/zero_search.hpp"

namespace stickslip::detail {

// Bounds on sup |f^(n)| over an interval for n = 1..4, and the size of f there (the sup of
// the sum of its terms' magnitudes), against which "zero" is judged.
struct DerivativeBounds {
  double scale = 0.0;
  double first = 0.0;
  double second = 0.0;
  double third = 0.0;
  double fourth = 0.0;
};

// The root of g in [l, r], given g(l) and g(r) of opposite signs (neither zero), by TOMS 748
// to the time tolerance: the midpoint of a bracket that narrow.
template <class F>
double BracketedByToms748(const F& g, double l, double r, double gl, double gr, double time_tolerance) {
  std::uintmax_t max_iter = 200;
  auto tolerance = [time_tolerance](double x, double y) { return std::abs(y - x) <= time_tolerance; };
  const auto [lo, hi] = boost::math::tools::toms748_solve(
      [&g](double t) { return g(t); }, l, r, gl, gr, tolerance, max_iter);
  return 0.5 * (lo + hi);
}

// The same root by Halley's steps on g's jet (value, slope, curvature: one evaluation gives all
// three) kept inside the bracket every evaluation shrinks; a step that leaves it, or fails to
// halve the step before the last, bisects instead (the safeguard of Numerical Recipes' rtsafe).
// At a simple root the steps converge cubically. Convergence is judged on Newton's step |g/g'|,
// which is the distance to a simple root near it: Halley's step stays below ~2|g'/g''| however far
// the root is, and would stop where g' is small against g''.
template <class F>
double BracketedByJet(const F& g, double l, double r, double gl, double gr, double time_tolerance) {
  // Bisection alone narrows any bracket of doubles (width < 2^1024) below 1e-13 (> 2^-44) in fewer.
  constexpr int kMaxSteps = 1100;
  const bool rising = gl < 0.0;
  // The chord's zero, or where that rounds to an end (a root within rounding of it), that end.
  double t = l + (r - l) * (gl / (gl - gr));
  if (!(t > l && t < r)) t = std::abs(gl) < std::abs(gr) ? l : r;
  double step = r - l, step_before = step;
  for (int i = 0; i < kMaxSteps; ++i) {
    const typename F::Jet jet = g.JetAt(t);
    if (jet.value == 0.0) return t;
    if (t > l && t < r && !std::isnan(jet.value)) ((jet.value < 0.0) == rising ? l : r) = t;
    // Halley's step from Newton's, in ratios that neither overflow nor underflow with g's size.
    const double newton = jet.value / jet.slope;
    double next = t - newton / (1.0 - 0.5 * newton * (jet.curvature / jet.slope));
    // Converged: a step this small may land on the end just moved to t, or a rounding past it.
    if (std::abs(newton) <= time_tolerance && std::isfinite(next)) return next;
    // Not inside (NaN included), or too slow: bisect.
    if (!(next > l && next < r) || std::abs(next - t) > 0.5 * std::abs(step_before)) next = 0.5 * (l + r);
    step_before = step;
    step = next - t;
    // Far from t = 0 adjacent doubles may lie further apart than the tolerance: a bracket that no
    // longer splits is as narrow as it gets.
    if (r - l <= time_tolerance || !(next > l && next < r)) return next;
    t = next;
  }
  return 0.5 * (l + r);
}

// The root of g in [l, r], given g(l) and g(r) of opposite signs (or one of them zero), polished
// as the options say.
template <class F>
double Bracketed(const F& g, double l, double r, double gl, double gr, const ZeroSearchOptions& options) {
  if (gl == 0.0) return l;
  if (gr == 0.0) return r;
  if (options.polish == ZeroSearchOptions::Polish::kJet) return BracketedByJet(g, l, r, gl, gr, options.time_tolerance);
  return BracketedByToms748(g, l, r, gl, gr, options.time_tolerance);
}

// Signs are compared, not multiplied: the product of two tiny values of one sign (a damped tail)
// underflows to zero and would pass for a sign change. Where the product is a normal double (as
// for every function of order one) both tests answer as the product would.
inline bool OppositeOrZero(double x, double y) { return x == 0.0 || y == 0.0 || (x < 0.0) != (y < 0.0); }
inline bool Opposite(double x, double y) { return (x < 0.0 && y > 0.0) || (x > 0.0 && y < 0.0); }

// Proves g has no zero in [l, r] from its end values and sup|g''| <= m2: between the ends g lies
// above its chord minus m2 (t - l)(r - t)/2 >= m2 h^2/8.
inline bool ProvablyOneSigned(double gl, double gr, double h, double m2) {
  if (OppositeOrZero(gl, gr)) return false;
  return std::min(std::abs(gl), std::abs(gr)) > m2 * h * h / 8.0;
}

template <class F, class Bounds>
class ZeroFinder {
 public:
  ZeroFinder(const F& f, const ZeroSearchOptions& options)
      : f_(f), df_(f.Derivative()), options_(options), bounds_(f) {}

  // Zeros of f in [l, r] with f(l) != 0, appended to `out` in increasing order.
  ZeroSearchStatus Search(double l, double r, int max_count, std::vector<Zero>* out, int* examined) const {
    // Depth-first: the stack holds one interval per level of halving, a few dozen at most in practice.
    boost::container::small_vector<Interval, 32> stack = {{{l, f_.JetAt(l)}, {r, f_.JetAt(r)}}};
    while (!stack.empty() && static_cast<int>(out->size()) < max_count) {
      if (*examined >= options_.max_intervals) return ZeroSearchStatus::kTooManyIntervals;
      ++*examined;
      const Interval iv = stack.back();
      stack.pop_back();
      const DerivativeBounds m = bounds_.On(iv.l.t, iv.r.t);
      // Where f or its bound overflows nothing is proved: split, so that the zeros before the
      // overflow are still found, and stop where the interval no longer splits.
      const bool bounded = Bounded(iv, m);
      if (bounded && Settled(iv, m, max_count, out)) continue;
      const double h = iv.r.t - iv.l.t;
      const double tm = 0.5 * (iv.l.t + iv.r.t);
      // Far from t = 0 adjacent doubles may lie further apart than the tolerance: an interval
      // that no longer splits is as narrow as it gets.
      if (h <= options_.time_tolerance || !(tm > iv.l.t && tm < iv.r.t)) {
        if (!bounded) return ZeroSearchStatus::kNotBounded;
        // Degenerate (f, f' and f'' all near zero): report a touch if f is at zero level.
        if (OppositeOrZero(iv.l.f.value, iv.r.f.value)) {
          Push(tm, ZeroKind::kCrossing, out);
        } else if (AtZeroLevel(tm)) {
          Push(tm, ZeroKind::kTouch, out);
        }
        continue;
      }
      const End middle{tm, f_.JetAt(tm)};
      stack.push_back({middle, iv.r});  // right half after the left one
      stack.push_back({iv.l, middle});
    }
    return ZeroSearchStatus::kComplete;
  }

  // Length of a neighbourhood (a, a + length] in which f has no zero, given that f(a) is at
  // zero level. Bounds over [a, b] hold on all it may exclude; where a term grows they are set
  // by the far end, so shorter windows [a, a + w] are tried too, each proving at most w.
  double ExclusionAfterZero(double a, double b) const {
    const typename F::Jet jet = f_.JetAt(a);
    const bool slope_is_rounding = SlopeIsRounding(a, jet.slope);
    double length = ExclusionWithin(jet, slope_is_rounding, bounds_.On(a, b));
    double window = b - a;
    for (int i = 0; i < kMaxWindowHalvings && length < window; ++i) {
      window *= 0.5;
      const double within = ExclusionWithin(jet, slope_is_rounding, bounds_.On(a, a + window));
      length = std::max(length, std::min(within, window));
      if (within >= window) break;
    }
    return std::max(length, options_.time_tolerance);
  }

  bool AtZeroLevel(double t) const { return AtZeroLevel(t, f_(t)); }
  bool AtZeroLevel(double t, double value) const {
    return std::abs(value) <= options_.touch_tolerance * std::max(bounds_.On(t, t).scale, 1e-300);
  }
  double ScaleAt(double t) const { return bounds_.On(t, t).scale; }
  // Whether f'(t) = slope is at rounding level against the size of f' at t: an extremum, as far
  // as doubles tell, whatever its sign.
  bool SlopeIsRounding(double t, double slope) const {
    return std::abs(slope) <= options_.touch_tolerance * bounds_.On(t, t).first;
  }

 private:
  static constexpr int kMaxWindowHalvings = 64;

  struct End {
    double t;
    typename F::Jet f;
  };
  struct Interval {
    End l, r;
  };

  static bool Bounded(const Interval& iv, const DerivativeBounds& m) {
    auto finite = [](const typename F::Jet& j) {
      return std::isfinite(j.value) && std::isfinite(j.slope) && std::isfinite(j.curvature);
    };
    return finite(iv.l.f) && finite(iv.r.f) && std::isfinite(m.scale) && std::isfinite(m.second);
  }

  // Whether the bounds m settle [l, r]: f has no zero there, or its zeros are found (appended).
  bool Settled(const Interval& iv, const DerivativeBounds& m, int max_count, std::vector<Zero>* out) const {
    const double h = iv.r.t - iv.l.t;
    const double fl = iv.l.f.value, fr = iv.r.f.value;
    if (ProvablyOneSigned(fl, fr, h, m.second)) return true;
    const double dl = iv.l.f.slope, dr = iv.r.f.slope;
    if (ProvablyOneSigned(dl, dr, h, m.third)) {
      // f is monotone here: at most one zero, a crossing.
      if (OppositeOrZero(fl, fr)) Push(Bracketed(f_, iv.l.t, iv.r.t, fl, fr), ZeroKind::kCrossing, out);
      return true;
    }
    if (Opposite(dl, dr) && ProvablyOneSigned(iv.l.f.curvature, iv.r.f.curvature, h, m.fourth)) {
      // f' is monotone with one zero: f has one interior extremum, so f is monotone on each
      // side of it.
      const double te = Bracketed(df_, iv.l.t, iv.r.t, dl, dr);
      const double fe = f_(te);
      // An extremum within the touch level of zero is one double zero, not two crossings a
      // rounding error apart.
      if (AtZeroLevel(te, fe)) {
        Push(te, ZeroKind::kTouch, out);
      } else if (Opposite(fl, fe)) {
        Push(Bracketed(f_, iv.l.t, te, fl, fe), ZeroKind::kCrossing, out);
        if (OppositeOrZero(fe, fr) && static_cast<int>(out->size()) < max_count) {
          Push(Bracketed(f_, te, iv.r.t, fe, fr), ZeroKind::kCrossing, out);
        }
      } else if (OppositeOrZero(fe, fr)) {
        Push(Bracketed(f_, te, iv.r.t, fe, fr), ZeroKind::kCrossing, out);
      }
      return true;
    }
    return false;
  }

  template <class G>
  double Bracketed(const G& g, double l, double r, double gl, double gr) const {
    return detail::Bracketed(g, l, r, gl, gr, options_);
  }
  static void Push(double t, ZeroKind kind, std::vector<Zero>* out) {
    // A zero exactly at the end two sub-intervals share is found from both.
    if (!out->empty() && out->back().t == t) return;
    out->push_back({t, kind});
  }

  // The exclusion after a zero at a from f's jet there and bounds m valid on what it excludes:
  //   |f(a+h)| >= |f'| h - m2 h^2/2                      > 0 for h <= |f'|/m2;
  //   |f(a+h)| >= |f' h + f'' h^2/2| - m3 h^3/6 and, when f' and f'' have the same sign,
  //            >= |f''| h^2/2 - m3 h^3/6                 > 0 for h <= |f''|/m3.
  // With opposite signs f returns to zero near 2|f'|/|f''|: only the first bound holds. An f'
  // at rounding level (slope_is_rounding) counts as zero, so that a
  // rounding error cannot fake a zero at once.
  double ExclusionWithin(const typename F::Jet& jet, bool slope_is_rounding, const DerivativeBounds& m) const {
    const double d1 = jet.slope;
    const double d2 = jet.curvature;
    const double inf = std::numeric_limits<double>::infinity();
    const double by_slope = m.second > 0.0 ? std::abs(d1) / m.second : inf;
    const double by_curvature = m.third > 0.0 ? std::abs(d2) / m.third : inf;
    double length = by_slope;
    if (slope_is_rounding) {
      length = by_curvature;
    } else if (!Opposite(d1, d2)) {
      length = std::max(by_slope, by_curvature);
    }
    return length;
  }

  const F& f_;
  F df_;
  ZeroSearchOptions options_;
  Bounds bounds_;
};

// The zeros of f in (a, b], as the Zeros of sinusoid_sum.hpp and exponential_sum.hpp document.
template <class Bounds, class F>
ZeroSearch FindZeros(const F& f, double a, double b, int max_count, const ZeroSearchOptions& options) {
  ZeroSearch search;
  // A NaN would fail every test that ends a subdivision.
  if (!std::isfinite(a) || !std::isfinite(b) || !f.IsFinite()) {
    search.status = ZeroSearchStatus::kNotFinite;
    return search;
  }
  if (!(b > a) || max_count <= 0) return search;
  const ZeroFinder<F, Bounds> finder(f, options);
  double start = a;
  if (finder.AtZeroLevel(a)) {
    // At the touch level but above rounding, and heading for zero (f f' < 0, f' above rounding):
    // the zero is due at once, not behind us (a state sampled a hair before a stop). At an
    // extremum (a touch searched past) the sign of a rounding-level f' says nothing.
    const typename F::Jet jet = f.JetAt(a);
    if (Opposite(jet.value, jet.slope) && std::abs(jet.value) > 1e-13 * finder.ScaleAt(a) &&
        !finder.SlopeIsRounding(a, jet.slope)) {
      search.zeros.push_back({std::min(b, a - jet.value / jet.slope), ZeroKind::kCrossing});
      return search;
    }
    start = a + finder.ExclusionAfterZero(a, b);
    if (start >= b) return search;
  }
  search.status = finder.Search(start, b, max_count, &search.zeros, &search.intervals);
  return search;
}

// The minimum and maximum of f over [a, b] from one search for the zeros of f'.
template <class Bounds, class F>
Extrema FindExtrema(const F& f, double a, double b, const ZeroSearchOptions& options) {
  const double fa = f(a);
  Extrema best{{a, fa}, {a, fa}};
  auto consider = [&best](double t, double value) {
    if (value < best.minimum.value) best.minimum = {t, value};
    if (value > best.maximum.value) best.maximum = {t, value};
  };
  consider(b, f(b));
  const ZeroSearch critical = FindZeros<Bounds>(f.Derivative(), a, b, std::numeric_limits<int>::max(), options);
  if (!critical.Complete()) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {{a, nan}, {a, nan}};
  }
  for (const Zero& z : critical.zeros) consider(z.t, f(z.t));
  return best;
}

}  // namespace stickslip::detail
