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
    bound += std::hypot(s.cos_coefficient, s.sin_coefficient) *
             std::pow(std::abs(s.frequency), order);
  }
  return bound;
}

double SinusoidSum::Scale() const {
  double scale = std::abs(constant_);
  for (const Sinusoid& s : terms_) scale += std::hypot(s.cos_coefficient, s.sin_coefficient);
  return scale;
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
      : f_(f), df_(f.Derivative()), d2f_(df_.Derivative()), options_(options),
        m2_(f.DerivativeBound(2)), m3_(f.DerivativeBound(3)),
        touch_level_(options.touch_tolerance * std::max(f.Scale(), 1e-300)) {}

  // Zeros of f in [l, r] with f(l) != 0, appended to `out` in increasing order.
  void Search(double l, double r, int max_count, std::vector<Zero>* out) const {
    struct Interval {
      double l, r, fl, fr;
    };
    std::vector<Interval> stack = {{l, r, f_(l), f_(r)}};
    while (!stack.empty() && static_cast<int>(out->size()) < max_count) {
      const Interval iv = stack.back();
      stack.pop_back();
      const double h = iv.r - iv.l;
      if (ProvablyOneSigned(iv.fl, iv.fr, h, m2_)) continue;
      const double dl = df_(iv.l);
      const double dr = df_(iv.r);
      if (ProvablyOneSigned(dl, dr, h, m3_)) {
        // f is monotone here: at most one zero, a crossing.
        if (iv.fl * iv.fr <= 0.0) {
          out->push_back({Bracketed(f_, iv.l, iv.r, iv.fl, iv.fr, options_.time_tolerance),
                          ZeroKind::kCrossing});
        }
        continue;
      }
      if (dl * dr < 0.0 && ProvablyOneSigned(d2f_(iv.l), d2f_(iv.r), h, f_.DerivativeBound(4))) {
        // f' is monotone with one zero: f has one interior extremum, so f is monotone on each
        // side of it.
        const double te = Bracketed(df_, iv.l, iv.r, dl, dr, options_.time_tolerance);
        const double fe = f_(te);
        // An extremum within the touch level of zero is one double zero, not two crossings a
        // rounding error apart.
        if (std::abs(fe) <= touch_level_) {
          out->push_back({te, ZeroKind::kTouch});
        } else if (iv.fl * fe < 0.0) {
          out->push_back({Bracketed(f_, iv.l, te, iv.fl, fe, options_.time_tolerance),
                          ZeroKind::kCrossing});
          if (fe * iv.fr <= 0.0 && static_cast<int>(out->size()) < max_count) {
            out->push_back({Bracketed(f_, te, iv.r, fe, iv.fr, options_.time_tolerance),
                            ZeroKind::kCrossing});
          }
        } else if (fe * iv.fr <= 0.0) {
          out->push_back({Bracketed(f_, te, iv.r, fe, iv.fr, options_.time_tolerance),
                          ZeroKind::kCrossing});
        }
        continue;
      }
      if (h <= options_.time_tolerance) {
        // Degenerate (f, f' and f'' all near zero): report a touch if f is at zero level.
        const double tm = 0.5 * (iv.l + iv.r);
        if (iv.fl * iv.fr <= 0.0) {
          out->push_back({tm, ZeroKind::kCrossing});
        } else if (std::abs(f_(tm)) <= touch_level_) {
          out->push_back({tm, ZeroKind::kTouch});
        }
        continue;
      }
      const double tm = 0.5 * (iv.l + iv.r);
      const double fm = f_(tm);
      stack.push_back({tm, iv.r, fm, iv.fr});  // right half after the left one
      stack.push_back({iv.l, tm, iv.fl, fm});
    }
  }

  // Length of a neighbourhood (a, a + length] in which f has no zero, given that f(a) is at
  // zero level, from Taylor's bounds:
  //   |f(a+h)| >= |f'| h - m2 h^2/2                      > 0 for h <= |f'|/m2;
  //   |f(a+h)| >= |f' h + f'' h^2/2| - m3 h^3/6 and, when f' and f'' have the same sign,
  //            >= |f''| h^2/2 - m3 h^3/6                 > 0 for h <= |f''|/m3.
  // With opposite signs f returns to zero near 2|f'|/|f''|: only the first bound holds. An f'
  // at rounding level counts as zero, so that a rounding error cannot fake a zero at once.
  double ExclusionAfterZero(double a) const {
    const double d1 = df_(a);
    const double d2 = d2f_(a);
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
  SinusoidSum d2f_;
  ZeroSearchOptions options_;
  double m2_;
  double m3_;
  double touch_level_;
};

}  // namespace

std::vector<Zero> Zeros(const SinusoidSum& f, double a, double b, int max_count,
                        const ZeroSearchOptions& options) {
  std::vector<Zero> zeros;
  if (!(b > a) || max_count <= 0) return zeros;
  const ZeroFinder finder(f, options);
  double start = a;
  if (finder.AtZeroLevel(a)) {
    start = a + finder.ExclusionAfterZero(a);
    if (start >= b) return zeros;
  }
  finder.Search(start, b, max_count, &zeros);
  return zeros;
}

Extremum Minimum(const SinusoidSum& f, double a, double b, const ZeroSearchOptions& options) {
  Extremum best{a, f(a)};
  const double fb = f(b);
  if (fb < best.value) best = {b, fb};
  const SinusoidSum df = f.Derivative();
  for (const Zero& z : Zeros(df, a, b, std::numeric_limits<int>::max(), options)) {
    const double value = f(z.t);
    if (value < best.value) best = {z.t, value};
  }
  return best;
}

}  // namespace stickslip
