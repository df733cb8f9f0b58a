#include "stickslip/orbits/orbit_measures.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "stickslip/model/events.hpp"
#include "stickslip/numerics/sinusoid_sum.hpp"
#include "stickslip/orbits/segment_walk.hpp"

namespace stickslip {

namespace {

// The least and the greatest value of a coordinate met so far; NaN once a value is undefined.
struct Range {
  double low = std::numeric_limits<double>::infinity();
  double high = -std::numeric_limits<double>::infinity();

  void Add(double lo, double hi) {
    if (std::isnan(lo) || std::isnan(hi) || std::isnan(low)) {
      low = high = std::numeric_limits<double>::quiet_NaN();
      return;
    }
    low = std::min(low, lo);
    high = std::max(high, hi);
  }
  void Add(const Extrema& e) { Add(e.minimum.value, e.maximum.value); }
  // The range over the whole period of an antisymmetric orbit, whose second half is -X.
  void Mirror() { Add(-high, -low); }
  double Amplitude() const { return std::isnan(low) ? low : std::max(high, -low); }
};

}  // namespace

OrbitMeasures Measure(const Orbit& orbit) {
  Range x1, x2;
  double stick_time = 0.0;
  WalkSegments(orbit, Extent::kListed, PhaseRule::kFromOrigin, [&](const SegmentVisit<double>& s) {
    x1.Add(MinimumAndMaximum(CoordinateAlong(s.motion, 0), 0.0, s.duration));
    if (s.spec.mode == Mode::kStick) {
      // x2 is held (eq. 9): its values at the ends differ by rounding only.
      for (double x : {s.start(1), s.end(1)}) x2.Add(x, x);
      stick_time += s.duration;
    } else {
      x2.Add(MinimumAndMaximum(CoordinateAlong(s.motion, 1), 0.0, s.duration));
    }
  });
  if (orbit.signature.antisymmetric()) {
    x1.Mirror();
    x2.Mirror();
  }
  OrbitMeasures m;
  m.amplitude_x1 = x1.Amplitude();
  m.amplitude_x2 = x2.Amplitude();
  m.peak_to_peak_x2 = x2.high - x2.low;
  m.stick_fraction = stick_time / (orbit.Period() * orbit.signature.CoveredFraction());
  for (Mode mode : orbit.signature.FullPeriod()) ++(mode == Mode::kStick ? m.sticks : m.stops);
  return m;
}

}  // namespace stickslip
