// What users plot of a periodic orbit: the amplitude and peak-to-peak of each coordinate (for the
// paper's model the amplitudes of x1 and x2 and the peak-to-peak of x2), the fraction of the
// period spent sticking, the number of stops and sticks per period, and the energy friction
// dissipates per period with the viscous damping that would dissipate as much (the design
// quantities of friction dampers and joints).
//
// Exact, from the closed-form motion of each segment visited by the one walk over the orbit's
// segments (segment_walk.hpp): a coordinate's extrema over a segment are at its ends or at the
// zeros of its velocity, found by the root finder that cannot miss a zero
// (numerics/sinusoid_sum.hpp). A coordinate the contact holds in a stick (x2 for the paper) is
// constant there: its values at the stick's ends.
// For an antisymmetric orbit the listed half is walked and the mirror half (-X) accounted for:
// every measure is over the whole period, k 2 pi/omega.
//
//   const OrbitMeasures m = Measure(orbit);
//   plot(orbit.parameters.omega, m.amplitude_x2);
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "stickslip/model/oscillator_model.hpp"
#include "stickslip/numerics/integral_of_square.hpp"
#include "stickslip/numerics/sinusoid_sum.hpp"
#include "stickslip/orbits/any_orbit.hpp"
#include "stickslip/orbits/orbit.hpp"
#include "stickslip/orbits/segment_walk.hpp"

namespace stickslip {

// The least and the greatest value of a coordinate met so far; NaN once a value is undefined.
struct CoordinateRange {
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
  double PeakToPeak() const { return high - low; }
};

// The measures of an orbit of any model (model/oscillator_model.hpp), per coordinate in the order
// of its description.
struct BasicOrbitMeasures {
  std::vector<CoordinateRange> coordinates;
  double stick_fraction = 0.0;
  int stops = 0;
  int sticks = 0;
  // Per period: int (F_k + alpha |s|) |s| dt over the slips, in the model's units of force times
  // length: F_k times the distance the contact slides relative to its surface (in each slip s keeps
  // its sign, so that distance is |the contact coordinate's change - v_b d|), plus alpha int s^2 dt
  // (integral_of_square.hpp) where the friction has a slope alpha. NaN where that overflows.
  double friction_work = 0.0;
  // The viscous coefficient c that dissipates as much on the contact's coordinate moving as
  // X cos(w t) (X half its peak-to-peak, w = 2 pi / period): c = W / (pi w X^2).
  double equivalent_damping = 0.0;
};

// The coordinate the contact holds in a stick (its displacement); every model has one.
template <typename Model>
int ContactCoordinate(const Model& model) {
  const int n = static_cast<int>(model.Description().coordinates.size());
  for (int k = 0; k < n; ++k) {
    if (model.HeldInStick(k)) return k;
  }
  throw std::logic_error("the model holds no coordinate in a stick");
}

// Only the values at the extrema are measures, second-order in their times' errors: the zeros of
// the velocities are polished on the jet, in about half the evaluations (numerics/zero_search.hpp).
// The margins keep the bracket's polishing: their zeros are located events, and a change at
// rounding moves a located event within its tolerance.
inline constexpr ZeroSearchOptions kExtremaSearch{.polish = ZeroSearchOptions::Polish::kJet};

template <typename Model>
BasicOrbitMeasures Measure(const Model& model, const BasicOrbit<Model>& orbit) {
  BasicOrbitMeasures m;
  m.coordinates.resize(model.Description().coordinates.size());
  const int contact = ContactCoordinate(model);
  const double rest_velocity = RestVelocity<Model>(orbit.parameters, 0.0);
  const double slope = model.FrictionSlope();
  double stick_time = 0.0, slid = 0.0, squared_speed = 0.0;  // int s^2 dt over the slips
  WalkSegments(model, orbit, Extent::kListed, PhaseRule::kFromOrigin, [&](const SegmentVisit<double, Model>& s) {
    const bool stick = s.spec.mode == Mode::kStick;
    if (!stick) slid += std::abs(s.end(contact) - s.start(contact) - rest_velocity * s.duration);
    if (!stick && slope != 0.0) squared_speed += IntegralOfSquare(model.ContactVelocityAlong(s.motion), s.duration);
    for (std::size_t i = 0; i < m.coordinates.size(); ++i) {
      const int k = static_cast<int>(i);
      if (stick && model.HeldInStick(k)) {
        // Held: its values at the ends differ by rounding only.
        for (double x : {s.start(k), s.end(k)}) m.coordinates[i].Add(x, x);
      } else {
        m.coordinates[i].Add(MinimumAndMaximum(model.CoordinateAlong(s.motion, k), 0.0, s.duration, kExtremaSearch));
      }
    }
    if (stick) stick_time += s.duration;
  });
  if (orbit.signature.antisymmetric()) {
    for (CoordinateRange& c : m.coordinates) c.Mirror();
  }
  // The period (the forcing's periods, or an autonomous orbit's durations) and the time the listed
  // segments cover of it.
  const double period = PeriodOf(model, orbit);
  const double covered = period * orbit.signature.CoveredFraction();
  m.stick_fraction = stick_time / covered;
  for (Mode mode : orbit.signature.FullPeriod()) ++(mode == Mode::kStick ? m.sticks : m.stops);
  m.friction_work = (model.KineticForce(orbit.parameters) * slid + slope * squared_speed) /
                    orbit.signature.CoveredFraction();
  const double amplitude = 0.5 * m.coordinates[contact].PeakToPeak();
  m.equivalent_damping = amplitude > 0.0 ? m.friction_work / (std::numbers::pi * (2.0 * std::numbers::pi / period) * amplitude * amplitude)
                                         : std::numeric_limits<double>::quiet_NaN();
  return m;
}

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
  // The energy friction dissipates per period (eta u_s, eq. 2's kinetic force, which is per unit m2,
  // times the distance x2 slides: a chain in physical units with m1 = 1 and m2 = 1/eta dissipates
  // u_s times it, a factor m2 less; so for equivalent_damping), and the viscous
  // coefficient that dissipates as much on x2 moving as X cos(w t) (X half x2's peak-to-peak, w the
  // orbit's angular frequency 2 pi / period): nan where x2 does not move.
  double friction_work = 0.0;
  double equivalent_damping = 0.0;
};

// The measures of `orbit`, which need not be admissible: the extrema are those of its own
// segments' closed forms. An amplitude or peak-to-peak is NaN if the search for a velocity's zeros
// was cut short (a NaN in the orbit, or a segment too long for the search's bound): a measure
// that is not defined, never a wrong one.
OrbitMeasures Measure(const Orbit& orbit);

}  // namespace stickslip
