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

#include "stickslip/model/pascal_2014/events.hpp"
#include "stickslip/numerics/exponential_sum.hpp"
#include "stickslip/numerics/sinusoid_sum.hpp"
#include "stickslip/orbits/orbit.hpp"
#include "stickslip/orbits/segment_walk.hpp"

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

// The margins at a segment's end, as functions of the end state x, the forcing phase there and
// the parameters, for any model (model/oscillator_model.hpp); templated on the scalar so that
// forward-mode AD gives their gradients (margin_gradients.hpp). With s the contact's velocity and
// F the stick force:
// stop-slope: a slip in `mode` decelerates into its stop, -sign(s) s' > 0 (x2'' for the paper).
template <typename Model, typename T>
T StopSlope(const Model& model, Mode mode, const typename Model::template StateT<T>& x, const T& phase,
            const typename Model::template ParametersT<T>& p) {
  return -double(SlipDirection(mode)) * model.ContactAcceleration(mode, x, phase, p);
}
// reversal: the force at a stop exceeds the static level towards the slip that follows,
// F - F_s > 0 before slip-, -F - F_s > 0 before slip+ (the paper's s - eta u_r, f > 0 of eq. 12,
// and -s - eta u_r, f1 < 0 of eq. 14).
template <typename Model, typename T>
T ReversalForce(const Model& model, Mode next, const typename Model::template StateT<T>& x, const T& phase,
                const typename Model::template ParametersT<T>& p) {
  const T force = model.StickForce(x, phase, p);
  const T threshold = model.StaticThreshold(p);
  return next == Mode::kSlipNegative ? T(force - threshold) : T(-force - threshold);
}
// stick-entry: the force at a stop into a stick lies inside the static band, F_s - |F| (eq. 30).
template <typename Model, typename T>
T StickEntryForce(const Model& model, const typename Model::template StateT<T>& x, const T& phase,
                  const typename Model::template ParametersT<T>& p) {
  using std::abs;
  return model.StaticThreshold(p) - abs(model.StickForce(x, phase, p));
}
// abnormal-stop: s touches zero and keeps its sign, sign(s) s''' > 0, where s''' = -dF/dt up to
// a positive factor (eq. 23).
template <typename Model, typename T>
T AbnormalStopJerk(const Model& model, Mode mode, const typename Model::template StateT<T>& x, const T& phase,
                   const typename Model::template ParametersT<T>& p) {
  return double(SlipDirection(mode)) * -model.StickForceRate(x, phase, p);
}
// exit-slope: F leaves the static band at a stick exit, dF/dt > 0 into slip-, < 0 into slip+.
template <typename Model, typename T>
T ExitSlope(const Model& model, SegmentEndKind end, const typename Model::template StateT<T>& x, const T& phase,
            const typename Model::template ParametersT<T>& p) {
  const T rate = model.StickForceRate(x, phase, p);
  return end == SegmentEndKind::kExitToNegative ? rate : T(-rate);
}

// The smallest interior local minimum of f on (0, d), ignoring critical points within a guard of
// either end (there f is at an end value fixed by an end condition); +inf if none; NaN if the
// search for them could not be completed (a NaN in the orbit, or a segment too long for the
// search's bound): a margin that is not defined there, never a wrong one.
Extremum InteriorMinimum(const SinusoidSum& f, double d);
Extremum InteriorMinimum(const ExponentialSum& f, double d);

// The margins of one listed segment, visited by the walk (segment_walk.hpp), appended to `margins`.
template <typename Model>
void AddSegmentMargins(const Model& model, const SegmentVisit<double, Model>& s,
                       const typename Model::Parameters& p, std::vector<Margin>& margins) {
  const int i = s.spec.listed;
  const Mode mode = s.spec.mode;
  const double d = s.duration;
  const double t_end = s.t0 + d;
  auto add = [&](const char* name, MarginKind kind, double value, double t) { margins.push_back({name, kind, i, value, t}); };
  add("duration", MarginKind::kDuration, d, s.t0);
  if (mode != Mode::kStick) {
    const typename Model::EventFunction velocity = model.ContactVelocityAlong(s.motion).Affine(SlipDirection(mode), 0.0);
    const Extremum low = InteriorMinimum(velocity, d);
    add("velocity", MarginKind::kSlipVelocity, low.value, s.t0 + low.t);
    switch (s.spec.end) {
      case SegmentEndKind::kReversal:
        add("stop-slope", MarginKind::kStopSlope, StopSlope(model, mode, s.end, s.end_phase, p), t_end);
        add("reversal", MarginKind::kStopForce, ReversalForce(model, s.spec.next, s.end, s.end_phase, p), t_end);
        break;
      case SegmentEndKind::kStickEntry:
        add("stop-slope", MarginKind::kStopSlope, StopSlope(model, mode, s.end, s.end_phase, p), t_end);
        add("stick-entry", MarginKind::kStopForce, StickEntryForce(model, s.end, s.end_phase, p), t_end);
        break;
      default:
        add("abnormal-stop", MarginKind::kStopForce, AbnormalStopJerk(model, mode, s.end, s.end_phase, p), t_end);
        break;
    }
    return;
  }
  const double threshold = model.StaticThreshold(p);
  using F = typename Model::EventFunction;
  const F force = model.StickForceAlong(s.motion, s.phase, p);
  const bool exit_negative = s.spec.end == SegmentEndKind::kExitToNegative;
  // The constraint that ends the stick is zero at the exit by its end condition.
  auto constraint_margin = [&](const char* name, const F& c, bool ends_stick) {
    Extremum low = ends_stick ? InteriorMinimum(c, d) : Minimum(c, 0.0, d);
    if (ends_stick && c(0.0) < low.value) low = {0.0, c(0.0)};
    add(name, MarginKind::kStickConstraint, low.value, s.t0 + low.t);
  };
  constraint_margin("G", force.Affine(1.0, threshold), !exit_negative);   // G, eq. (35)
  constraint_margin("G1", force.Affine(-1.0, threshold), exit_negative);  // G1
  const double slope = force.Derivative()(d);
  add("exit-slope", MarginKind::kExitSlope, exit_negative ? slope : -slope, t_end);
}

// Every margin of `orbit` of any model, segment by segment in the walk's order, then the orbit's own.
template <typename Model>
std::vector<Margin> AdmissibilityMargins(const Model& model, const BasicOrbit<Model>& orbit) {
  std::vector<Margin> margins;
  margins.reserve(5 * orbit.signature.size() + 1);
  WalkSegments(model, orbit, Extent::kListed, PhaseRule::kFromOrigin,
               [&](const SegmentVisit<double, Model>& s) { AddSegmentMargins(model, s, orbit.parameters, margins); });
  margins.push_back({"sliding-friction", MarginKind::kFrictionLevel, -1,
                     Model::ParameterAt(orbit.parameters, Model::kKineticLevelParameter), 0.0});
  return margins;
}

// The paper's model (model/pascal_2014.hpp).
std::vector<Margin> AdmissibilityMargins(const Orbit& orbit);

// The margin with the smallest value (the first on ties), or the first NaN one: a margin that
// could not be computed may be the smallest. By value: callers often pass a temporary vector.
Margin SmallestMargin(const std::vector<Margin>& margins);

}  // namespace stickslip
