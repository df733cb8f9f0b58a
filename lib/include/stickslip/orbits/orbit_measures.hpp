// What users plot of a periodic orbit: the amplitudes of x1 and x2, the peak-to-peak of x2, the
// fraction of the period spent sticking and the number of stops and sticks per period.
//
// Exact, from the closed-form flow of each segment (model/flows.hpp) visited by the one walk
// over the orbit's segments (segment_walk.hpp): a coordinate's extrema over a segment are at its
// ends or at the zeros of its velocity (x1' or x2'), found by the root finder that cannot miss a
// zero (numerics/sinusoid_sum.hpp). Inside a stick x2 is constant: its values at the stick's ends.
// For an antisymmetric orbit the listed half is walked and the mirror half (-X) accounted for:
// every measure is over the whole period, k 2 pi/omega.
//
//   const OrbitMeasures m = Measure(orbit);
//   plot(orbit.parameters.omega, m.amplitude_x2);
#pragma once

#include "stickslip/orbits/orbit.hpp"

namespace stickslip {

struct OrbitMeasures {
  double amplitude_x1 = 0.0;     // max over the period of |x1(t)|
  double amplitude_x2 = 0.0;     // max over the period of |x2(t)|
  double peak_to_peak_x2 = 0.0;  // max x2 - min x2 over the period
  double stick_fraction = 0.0;   // the stick durations' sum over the period
  // Per period: stops are the slip segments' ends (x2' = 0, whatever follows: a reversal, a
  // stick, an abnormal stop), sticks the stick segments; both counted from the orbit type, a
  // segment of zero duration (where a branch changes type) included.
  int stops = 0;
  int sticks = 0;
};

// The measures of `orbit`, which need not be admissible: the extrema are those of its own
// segments' closed forms. An amplitude or peak-to-peak is NaN if the search for a velocity's zeros
// was cut short (a NaN in the orbit, or a segment too long for the search's bound): a measure
// that is not defined, never a wrong one.
OrbitMeasures Measure(const Orbit& orbit);

}  // namespace stickslip
