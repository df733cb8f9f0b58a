// Functions of time of the form f(t) = c0 + c1 t + sum_k (a_k cos(nu_k t) + b_k sin(nu_k t)),
// the form every coordinate and every event function of the oscillator takes inside one mode,
// and a root finder on them that cannot miss a root: it excludes an interval only where a
// bound on |f''| proves f has no zero there.
#pragma once

#include <optional>
#include <vector>

namespace stickslip {

struct Sinusoid {
  double frequency = 0.0;
  double cos_coefficient = 0.0;
  double sin_coefficient = 0.0;
};

class SinusoidSum {
 public:
  SinusoidSum() = default;
  SinusoidSum(double constant, double slope, std::vector<Sinusoid> terms)
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
  // |c0| + sum_k |(a_k, b_k)|: the size against which "zero" is judged.
  double Scale() const;
  // Every coefficient and frequency finite.
  bool IsFinite() const;

 private:
  double constant_ = 0.0;
  double slope_ = 0.0;
  std::vector<Sinusoid> terms_;
};

// How f meets zero: crossing it, or touching it (a double zero: a grazing or an abnormal stop).
enum class ZeroKind { kCrossing, kTouch };

struct Zero {
  double t = 0.0;
  ZeroKind kind = ZeroKind::kCrossing;
};

struct ZeroSearchOptions {
  // Width of the final bracket around a crossing, and of the bracket around the extremum at a
  // touch. The event times of the simulator are located to this accuracy.
  double time_tolerance = 1e-13;
  // |f| <= touch_tolerance * f.Scale() at an interior extremum counts as touching zero.
  double touch_tolerance = 1e-11;
  // The most sub-intervals one search examines, so that its cost is bounded whatever f and
  // [a, b] are: a few per oscillation of f, enough for ~1e5 oscillations.
  int max_intervals = 1 << 20;
};

// How a search ended.
enum class ZeroSearchStatus {
  kComplete,          // every zero in (a, b] was found, or the first max_count of them
  kTooManyIntervals,  // options.max_intervals was reached: zeros past those found may be missed
  kNotFinite,         // f, a or b is not finite: nothing was searched
};
const char* ToString(ZeroSearchStatus status);  // "complete", "too many sub-intervals", "not finite"

struct ZeroSearch {
  std::vector<Zero> zeros;
  ZeroSearchStatus status = ZeroSearchStatus::kComplete;
  int intervals = 0;  // sub-intervals examined
  bool Complete() const { return status == ZeroSearchStatus::kComplete; }
};

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
struct Extremum {
  double t = 0.0;
  double value = 0.0;
};
Extremum Minimum(const SinusoidSum& f, double a, double b, const ZeroSearchOptions& options = {});

// The minimum and the maximum of f over [a, b] from one search for the zeros of f' (the
// candidates are a, b and those zeros); both values are NaN if that search was not complete.
struct Extrema {
  Extremum minimum;
  Extremum maximum;
};
Extrema MinimumAndMaximum(const SinusoidSum& f, double a, double b, const ZeroSearchOptions& options = {});

}  // namespace stickslip
