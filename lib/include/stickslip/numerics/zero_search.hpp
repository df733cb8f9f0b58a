// What a search for the zeros of a function of time returns, and how it is tuned: shared by the
// root finders of sinusoid_sum.hpp and exponential_sum.hpp, which run one and the same search.
#pragma once

#include <vector>

namespace stickslip {

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
  // |f| <= touch_tolerance * (the size of f: SinusoidSum::Scale(), or the size of an
  // ExponentialSum's terms at that time) at an interior extremum counts as touching zero.
  double touch_tolerance = 1e-11;
  // How a zero is polished inside its bracket. kBracket: TOMS 748 to time_tolerance, the zero's
  // time within half of it (the simulator's event times, the verification's stops). kJet:
  // Halley's steps on f's jet to rounding, in about half the evaluations; for the zeros of f'
  // searched for f's extrema, whose value is second-order in the time's error.
  enum class Polish { kBracket, kJet };
  Polish polish = Polish::kBracket;
  // The most sub-intervals one search examines, so that its cost is bounded whatever f and
  // [a, b] are: a few per oscillation of f, enough for ~1e5 oscillations.
  int max_intervals = 1 << 20;
};

// How a search ended.
enum class ZeroSearchStatus {
  kComplete,          // every zero in (a, b] was found, or the first max_count of them
  kTooManyIntervals,  // options.max_intervals was reached: zeros past those found may be missed
  kNotFinite,         // f, a or b is not finite: nothing was searched
  kNotBounded,        // past the zeros found, f or the bound on f'' overflows (or every term of f
                      // underflows) on a sub-interval too narrow to split: later zeros may be missed
};
// "complete", "too many sub-intervals", "not finite", "not bounded"
const char* ToString(ZeroSearchStatus status);

struct ZeroSearch {
  std::vector<Zero> zeros;
  ZeroSearchStatus status = ZeroSearchStatus::kComplete;
  int intervals = 0;  // sub-intervals examined
  bool Complete() const { return status == ZeroSearchStatus::kComplete; }
};

// A minimum or maximum of f over [a, b] and where it is attained (an end point or a zero of f').
struct Extremum {
  double t = 0.0;
  double value = 0.0;
};

struct Extrema {
  Extremum minimum;
  Extremum maximum;
};

}  // namespace stickslip
