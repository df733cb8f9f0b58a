// Admissibility margins of a periodic orbit: every inequality its signature needs to be a motion
// of the system, each as a signed number (positive = admissible) with where it is attained.
// The smallest margin is the distance to the nearest change of orbit type; the continuation
// engine watches all of them.
//
// Per listed segment i (names carry the 1-based segment number):
//   duration:i       d_i > 0
//   velocity:i       slip: the smallest interior local minimum of sign(x2') x2' (zeros of x2''
//                    by root finding); +inf when there is none
//   stop-slope:i     slip ending at a stop: -sign(x2') x2'' at the stop (the slip decelerates)
//   reversal:i       stop with reversal: s - eta u_r (into slip-) or -s - eta u_r (into slip+)
//                    (f > 0 of eq. 12, f1 < 0 of eq. 14)
//   stick-entry:i    stop into a stick: eta u_r - |s| (eq. 30)
//   abnormal-stop:i  abnormal stop: sign(x2') x2''' (x2' touches zero and keeps its sign, eq. 23)
//   G:i, G1:i        stick: the minimum of G and G1 over the stick (eq. 35, 39, 49, 51); for
//                    the constraint that ends the stick, its start and interior minima
//   exit-slope:i     stick: the slope with which s reaches +-eta u_r (it must leave the band)
// and, for the orbit as a whole,
//   sliding-friction u_s > 0 (eq. 4): where a branch reaches u_s = 0 the family ends
// A margin whose search for interior minima could not be completed (a NaN in the orbit, or a
// segment too long for the root finder's bound) is NaN: not defined, rather than wrong.
// An interior extremum can only be born at a segment end, where the matching slope margin passes
// through zero; so a change of orbit type is always a sign change of some margin.
#pragma once

#include <string>
#include <vector>

#include "stickslip/model/events.hpp"
#include "stickslip/orbits/orbit.hpp"

namespace stickslip {

enum class MarginKind {
  kDuration,         // a phase shrinking to zero
  kSlipVelocity,     // x2' touching zero inside a slip: a new stop
  kStopSlope,        // transversality at a stop
  kStopForce,        // the force condition at a stop
  kStickConstraint,  // G or G1 grazing zero inside a stick
  kExitSlope,        // transversality at a stick exit
  kFrictionLevel,    // the sliding friction level itself
};
const char* ToString(MarginKind kind);

struct Margin {
  const char* base = "";  // "G", "duration", ...: the name without the segment number
  MarginKind kind = MarginKind::kDuration;
  int segment = 0;     // 0-based listed segment (-1 for the orbit as a whole)
  double value = 0.0;  // > 0 admissible
  double t = 0.0;      // where it is attained, time from the orbit's origin
  // "G:3" (1-based segment), or the base alone for the orbit as a whole. Formatted on demand:
  // the continuation evaluates margins at every point and needs only the values.
  std::string Name() const;
};

std::vector<Margin> AdmissibilityMargins(const Orbit& orbit);

// The margins at a segment's end, as functions of the end state x, the forcing phase there and
// the parameters; templated so that forward-mode AD gives their gradients (margin_gradients.hpp).
// stop-slope: a slip in `mode` decelerates into its stop, -sign(x2') x2'' > 0.
template <typename T>
T StopSlope(Mode mode, const StateT<T>& x, const T& phase, const BasicParameters<T>& p) {
  return -double(SlipDirection(mode)) * Acceleration(mode, x, phase, p)(1);
}
// reversal: the force at a stop exceeds the static level towards the slip that follows,
// s - eta u_r > 0 before slip- (f > 0, eq. 12), -s - eta u_r > 0 before slip+ (f1 < 0, eq. 14).
template <typename T>
T ReversalForce(Mode next, const StateT<T>& x, const T& phase, const BasicParameters<T>& p) {
  const T force = StickForce(x, phase, p);
  const T threshold = p.eta * p.u_r;
  return next == Mode::kSlipNegative ? T(force - threshold) : T(-force - threshold);
}
// stick-entry: the force at a stop into a stick lies inside the static band, eta u_r - |s| (eq. 30).
template <typename T>
T StickEntryForce(const StateT<T>& x, const T& phase, const BasicParameters<T>& p) {
  using std::abs;
  return p.eta * p.u_r - abs(StickForce(x, phase, p));
}
// abnormal-stop: x2' touches zero and keeps its sign, sign(x2') x2''' > 0 (eq. 23).
template <typename T>
T AbnormalStopJerk(Mode mode, const StateT<T>& x, const T& phase, const BasicParameters<T>& p) {
  return double(SlipDirection(mode)) * -StickForceRate(x, phase, p);
}
// exit-slope: s leaves the static band at a stick exit, ds/dt > 0 into slip-, < 0 into slip+.
template <typename T>
T ExitSlope(SegmentEndKind end, const StateT<T>& x, const T& phase, const BasicParameters<T>& p) {
  const T rate = StickForceRate(x, phase, p);
  return end == SegmentEndKind::kExitToNegative ? rate : T(-rate);
}

// The margin with the smallest value (the first on ties), or the first NaN one: a margin that
// could not be computed may be the smallest. By value: callers often pass a temporary vector.
Margin SmallestMargin(const std::vector<Margin>& margins);

}  // namespace stickslip
