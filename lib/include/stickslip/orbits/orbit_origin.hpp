// The same orbit from another origin. An orbit's time origin is a segment end (a stop or a stick
// exit, where x2' = 0: orbit.hpp), and which one is a choice: FindOrbit takes the paper's
// preference (orbit_finder.hpp), a trace keeps the origin of its start through every change of
// type. Two descriptions of one motion then differ by a cyclic rotation of the segments, the state
// and phase at the new origin, and, for an antisymmetric orbit whose new origin lies in the
// mirrored half, the mirror image: the listed half then starts with the mirrored modes, at -X, half
// a period (phase + k pi) later.
//
//   for (int j = 0; j < OriginCount(orbit.signature); ++j) compare(WithOriginAt(orbit, j), other);
#pragma once

#include <numbers>
#include <vector>

#include "stickslip/orbits/orbit.hpp"
#include "stickslip/orbits/signature.hpp"

namespace stickslip {

// The segment ends of one whole period: the listed segments' count, twice it when antisymmetric.
int OriginCount(const Signature& signature);

// The signature read from segment end j (0 <= j < OriginCount) of the whole period on.
Signature WithOriginAt(const Signature& signature, int j);

// The orbit from the start of its segment j of the whole period (the listed segments, then their
// mirror images when antisymmetric): the state there by the closed-form flows, the phase
// phi + omega t_j (+ k pi in the mirrored half, reduced to [0, 2 pi)), the durations rotated. Throws
// std::out_of_range for j outside [0, OriginCount).
Orbit WithOriginAt(const Orbit& orbit, int j);

// The orbit's mirror image, the other motion of an asymmetric pair: the system is symmetric under
// x -> -x with the forcing half a period on (cos(w t + phi + pi) = -cos(w t + phi)), so -X(t) with
// the phase phi + pi and every slip's direction reversed is a motion whenever X(t) is. An
// antisymmetric orbit is its own (from another origin).
Orbit MirrorImage(const Orbit& orbit);

// The same of any model's orbit: a motion's mirror image is one where the model is odd under
// x -> -x with the forcing half a period on, which a model whose contact slides on a fixed surface
// is (a belt's speed breaks it: the caller decides).
template <typename Model>
BasicOrbit<Model> MirrorImage(const BasicOrbit<Model>& orbit) {
  std::vector<Mode> modes;
  for (Mode mode : orbit.signature.segments()) modes.push_back(Mirror(mode));
  BasicOrbit<Model> mirrored = orbit;
  mirrored.signature = Signature(modes, orbit.signature.antisymmetric(), orbit.signature.period_multiple());
  mirrored.start = -orbit.start;
  mirrored.phi = PhaseInCycle(orbit.phi + std::numbers::pi);
  return mirrored;
}

}  // namespace stickslip
