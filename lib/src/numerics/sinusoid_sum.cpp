#include "stickslip/numerics/sinusoid_sum.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include <boost/math/tools/roots.hpp>

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
  std::vector<Sinusoid> terms = terms_;
  for (Sinusoid& s : terms) {
    s.cos_coefficient *= k;
    s.sin_coefficient *= k;
  }
  return SinusoidSum(k * constant_ + c, k * slope_, std::move(terms));
}

SinusoidSum SinusoidSum::Derivative() const {
  std::vector<Sinusoid> terms;
  terms.reserve(terms_.size());
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

const char* ToString(ZeroSearchStatus status) {
  constexpr const char* kNames[] = {"complete", "too many sub-intervals", "not finite"};  // in enum order
  return kNames[static_cast<int>(status)];
}

namespace {

// The root of g in [l, r], given g(l) and g(r) of opposite signs (or one of them zero).
double Bracketed(const SinusoidSum& g, double l, double r, double gl, double gr,
                 double time_tolerance) {
  if (gl == 0.0) return l;
  if (gr == 0.0) return r;
  std::uintmax_t max_iter = 200;
  auto tolerance = [time_tolerance](double x, double y) { return std::abs(y - x) <= time_tolerance; };
  const auto [lo, hi] = boost::math::tools::toms748_solve(
      [&g](double t) { return g(t); }, l, r, gl, gr, tolerance, max_iter);
  return 0.5 * (lo + hi);
}

// Proves g has no zero in [l, r] from its end values and sup|g''| <= m2: between the ends g lies
// above its chord minus m2 (t - l)(r - t)/2 >= m2 h^2/8.
bool ProvablyOneSigned(double gl, double gr, double h, double m2) {
  if (gl * gr <= 0.0) return false;
  return std::min(std::abs(gl), std::abs(gr)) > m2 * h * h / 8.0;
}

class ZeroFinder {
 public:
  ZeroFinder(const SinusoidSum& f, const ZeroSearchOptions& options)
      : f_(f), df_(f.Derivative()), options_(options), m2_(f.DerivativeBound(2)),
        m3_(f.DerivativeBound(3)), m4_(f.DerivativeBound(4)),
        touch_level_(options.touch_tolerance * std::max(f.Scale(), 1e-300)) {}

  // Zeros of f in [l, r] with f(l) != 0, appended to `out` in increasing order.
  ZeroSearchStatus Search(double l, double r, int max_count, std::vector<Zero>* out, int* examined) const {
    struct End {
      double t;
      SinusoidSum::Jet f;
    };
    struct Interval {
      End l, r;
    };
    std::vector<Interval> stack = {{{l, f_.JetAt(l)}, {r, f_.JetAt(r)}}};
    while (!stack.empty() && static_cast<int>(out->size()) < max_count) {
      if (*examined >= options_.max_intervals) return ZeroSearchStatus::kTooManyIntervals;
      ++*examined;
      const Interval iv = stack.back();
      stack.pop_back();
      const double h = iv.r.t - iv.l.t;
      const double fl = iv.l.f.value, fr = iv.r.f.value;
      if (ProvablyOneSigned(fl, fr, h, m2_)) continue;
      const double dl = iv.l.f.slope, dr = iv.r.f.slope;
      if (ProvablyOneSigned(dl, dr, h, m3_)) {
        // f is monotone here: at most one zero, a crossing.
        if (fl * fr <= 0.0) {
          out->push_back({Bracketed(f_, iv.l.t, iv.r.t, fl, fr, options_.time_tolerance), ZeroKind::kCrossing});
        }
        continue;
      }
      if (dl * dr < 0.0 && ProvablyOneSigned(iv.l.f.curvature, iv.r.f.curvature, h, m4_)) {
        // f' is monotone with one zero: f has one interior extremum, so f is monotone on each
        // side of it.
        const double te = Bracketed(df_, iv.l.t, iv.r.t, dl, dr, options_.time_tolerance);
        const double fe = f_(te);
        // An extremum within the touch level of zero is one double zero, not two crossings a
        // rounding error apart.
        if (std::abs(fe) <= touch_level_) {
          out->push_back({te, ZeroKind::kTouch});
        } else if (fl * fe < 0.0) {
          out->push_back({Bracketed(f_, iv.l.t, te, fl, fe, options_.time_tolerance), ZeroKind::kCrossing});
          if (fe * fr <= 0.0 && static_cast<int>(out->size()) < max_count) {
            out->push_back({Bracketed(f_, te, iv.r.t, fe, fr, options_.time_tolerance), ZeroKind::kCrossing});
          }
        } else if (fe * fr <= 0.0) {
          out->push_back({Bracketed(f_, te, iv.r.t, fe, fr, options_.time_tolerance), ZeroKind::kCrossing});
        }
        continue;
      }
      const double tm = 0.5 * (iv.l.t + iv.r.t);
      // Far from t = 0 adjacent doubles may lie further apart than the tolerance: an interval
      // that no longer splits is as narrow as it gets.
      if (h <= options_.time_tolerance || !(tm > iv.l.t && tm < iv.r.t)) {
        // Degenerate (f, f' and f'' all near zero): report a touch if f is at zero level.
        if (fl * fr <= 0.0) {
          out->push_back({tm, ZeroKind::kCrossing});
        } else if (std::abs(f_(tm)) <= touch_level_) {
          out->push_back({tm, ZeroKind::kTouch});
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
  // zero level, from Taylor's bounds:
  //   |f(a+h)| >= |f'| h - m2 h^2/2                      > 0 for h <= |f'|/m2;
  //   |f(a+h)| >= |f' h + f'' h^2/2| - m3 h^3/6 and, when f' and f'' have the same sign,
  //            >= |f''| h^2/2 - m3 h^3/6                 > 0 for h <= |f''|/m3.
  // With opposite signs f returns to zero near 2|f'|/|f''|: only the first bound holds. An f'
  // at rounding level counts as zero, so that a rounding error cannot fake a zero at once.
  double ExclusionAfterZero(double a) const {
    const SinusoidSum::Jet jet = f_.JetAt(a);
    const double d1 = jet.slope;
    const double d2 = jet.curvature;
    const double inf = std::numeric_limits<double>::infinity();
    const double by_slope = m2_ > 0.0 ? std::abs(d1) / m2_ : inf;
    const double by_curvature = m3_ > 0.0 ? std::abs(d2) / m3_ : inf;
    const bool slope_is_rounding = std::abs(d1) <= options_.touch_tolerance * f_.DerivativeBound(1);
    double length = by_slope;
    if (slope_is_rounding) {
      length = by_curvature;
    } else if (d1 * d2 >= 0.0) {
      length = std::max(by_slope, by_curvature);
    }
    return std::max(length, options_.time_tolerance);
  }

  bool AtZeroLevel(double t) const { return std::abs(f_(t)) <= touch_level_; }

 private:
  const SinusoidSum& f_;
  SinusoidSum df_;
  ZeroSearchOptions options_;
  double m2_;
  double m3_;
  double m4_;
  double touch_level_;
};

}  // namespace

ZeroSearch Zeros(const SinusoidSum& f, double a, double b, int max_count, const ZeroSearchOptions& options) {
  ZeroSearch search;
  // A NaN would fail every test that ends a subdivision.
  if (!std::isfinite(a) || !std::isfinite(b) || !f.IsFinite()) {
    search.status = ZeroSearchStatus::kNotFinite;
    return search;
  }
  if (!(b > a) || max_count <= 0) return search;
  const ZeroFinder finder(f, options);
  double start = a;
  if (finder.AtZeroLevel(a)) {
    // At the touch level but above rounding, and heading for zero (f f' < 0): the zero is due
    // at once, not behind us (a state sampled a hair before a stop).
    const SinusoidSum::Jet jet = f.JetAt(a);
    if (jet.value * jet.slope < 0.0 && std::abs(jet.value) > 1e-13 * f.Scale()) {
      search.zeros.push_back({std::min(b, a - jet.value / jet.slope), ZeroKind::kCrossing});
      return search;
    }
    start = a + finder.ExclusionAfterZero(a);
    if (start >= b) return search;
  }
  search.status = finder.Search(start, b, max_count, &search.zeros, &search.intervals);
  return search;
}

Extremum Minimum(const SinusoidSum& f, double a, double b, const ZeroSearchOptions& options) {
  return MinimumAndMaximum(f, a, b, options).minimum;
}

Extrema MinimumAndMaximum(const SinusoidSum& f, double a, double b, const ZeroSearchOptions& options) {
  const double fa = f(a);
  Extrema best{{a, fa}, {a, fa}};
  auto consider = [&best](double t, double value) {
    if (value < best.minimum.value) best.minimum = {t, value};
    if (value > best.maximum.value) best.maximum = {t, value};
  };
  consider(b, f(b));
  const ZeroSearch critical = Zeros(f.Derivative(), a, b, std::numeric_limits<int>::max(), options);
  if (!critical.Complete()) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {{a, nan}, {a, nan}};
  }
  for (const Zero& z : critical.zeros) consider(z.t, f(z.t));
  return best;
}

}  // namespace stickslip
