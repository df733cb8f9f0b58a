// The orbit types adjacent to a change of type: where an admissibility margin (margins.hpp) of a
// signature passes through zero, which signatures the motion takes on the far side, and the start
// orbit on each at the located point (the same motion: the new segment of zero length, or the
// vanished one removed). These are the codimension-one sliding bifurcations of a Filippov system
// (di Bernardo, Kowalczyk & Nordmark 2003), read in Pascal's terms (eqs. 4, 11, 35; ERRATA):
// s = chi eta (x2 - x1) - cos(omega t + phi) is the force a stick must hold, |s| < eta u_r;
// in slip- x2'' = eta u_s - s, in slip+ x2'' = -eta u_s - s.
//
//   reversal:i       crossing-sliding: the force at the stop no longer carries the mass into the
//                    next slip; it sticks there until s reaches the exit level. A stick is
//                    inserted after segment i.
//   stick-entry:i    the force at a stop into a stick reaches the static level: the mass reverses
//                    instead. A zero-length slip of the opposite sign is inserted between the
//                    slip and the stick (the reversed slip is short only when u_r = u_s; the
//                    simulation decides). Where the stick has zero length there, a second
//                    candidate: the stick removed, the stop a reversal (the inverse of the above).
//   abnormal-stop:i  x2''' reaches zero at an abnormal stop: x2' crosses zero there instead of
//                    touching it; with u_r = u_s the mass sticks for an instant: a stick is
//                    inserted between the two equal slips.
//   velocity:i       grazing-sliding: x2' touches zero inside slip i, where x2'' = 0, so
//                    s = +-eta u_s: the slip splits around a new stick at the grazing time; when
//                    u_r = u_s the grazing is itself an abnormal stop, a second candidate (the
//                    slip split in two equal slips).
//   G:i, G1:i        adding-sliding: the force s grazes -eta u_r (G) or +eta u_r (G1) inside
//                    stick i: the stick splits around a short slip+ (G) or slip- (G1) at the
//                    grazing time.
//   duration:i       a phase shrinking to zero (T0, S0; the inverses of the above): the segment
//                    is removed; neighbours in the same mode are joined into one segment, or, when
//                    u_r = u_s, also kept apart at an abnormal stop.
//   stop-slope:i,    the end condition of segment i becomes tangential (x2'' = 0 at the stop,
//   exit-slope:i     ds/dt = 0 at the exit): two roots of the end condition merge, so the branch
//                    of the same type folds or exchanges roots there; no segment appears or
//                    vanishes, so there is no adjacent type to switch to.
//   sliding-friction u_s = 0: the end of the physical family, no adjacent type.
#pragma once

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include "stickslip/model/model_description.hpp"
#include "stickslip/orbits/margins.hpp"
#include "stickslip/orbits/orbit.hpp"
#include "stickslip/orbits/signature_edits.hpp"

namespace stickslip {

// How the adjacent signature is made from the located one.
enum class TypeEdit {
  kInsert,               // a zero-length segment inserted at a segment end
  kSplit,                // a segment cut at an interior time around a zero-length segment
  kSplitAtAbnormalStop,  // a slip cut at an interior time into two slips of its mode
  kRemove,               // a segment of zero length removed (neighbours joined if equal)
  kRemoveKeepApart,      // removed, equal neighbours kept apart at an abnormal stop
};
const char* ToString(TypeEdit edit);

struct AdjacentType {
  SignatureEdit edit;  // the adjacent signature, with the renaming of durations
  TypeEdit kind = TypeEdit::kInsert;
  int segment = 0;               // 0-based listed segment of the located signature the edit is at
  int new_segment = -1;          // 0-based listed segment of the new signature that starts at zero
                                 // length (-1 for a removal)
  const char* bifurcation = "";  // "crossing-sliding", "grazing-sliding", "adding-sliding", ...
  std::string motion;            // what the motion does on the far side, in one sentence
};

// The adjacent types of `signature` where the margin `base` ("reversal", "G", ..., without the
// segment number) of listed segment `segment` (0-based) passes through zero. `equal_friction`:
// u_r = u_s (then abnormal stops are possible). Empty for the margins that have no adjacent type
// (stop-slope, exit-slope, sliding-friction) and for a removal that would be invalid (the only
// segment; a join across the orbit's origin). Throws InvalidInput naming "margin" for a base
// that is no margin or does not belong to that segment's mode and end.
// The motions are described in `words`, the model's (ModelDescription::contact).
std::vector<AdjacentType> AdjacentTypes(std::string_view base, int segment, const Signature& signature,
                                        bool equal_friction, const ContactWords& words = {});

// Why `base` has no adjacent type, in one sentence ("" when it has one).
std::string NoAdjacentTypeReason(std::string_view base, const ContactWords& words = {});

// The start orbit on `adjacent` at the located orbit, of any model (Orbit, BasicOrbit<Model>): the
// same state, phase, parameters and period, the new segment of zero length at the segment end, or
// at `margin.t` (the interior extremum's time from the orbit's origin) for a split.
template <typename AnyOrbit>
AnyOrbit AdjacentStart(const AnyOrbit& located, const Margin& margin, const AdjacentType& adjacent) {
  const int i = adjacent.segment;
  auto new_mode = [&] { return adjacent.edit.signature.segments()[adjacent.new_segment]; };
  switch (adjacent.kind) {
    case TypeEdit::kInsert: return InsertSegment(located, adjacent.new_segment, new_mode());
    case TypeEdit::kSplit:
    case TypeEdit::kSplitAtAbnormalStop: {
      double start = 0.0;
      for (int k = 0; k < i; ++k) start += located.durations[k];
      const double tau = std::clamp(margin.t - start, 0.0, located.durations[i]);
      if (adjacent.kind == TypeEdit::kSplit) return SplitSegment(located, i, tau, new_mode());
      AnyOrbit edited = located;
      edited.signature = adjacent.edit.signature;
      edited.durations[i] = tau;
      edited.durations.insert(edited.durations.begin() + i + 1, located.durations[i] - tau);
      return edited;
    }
    case TypeEdit::kRemove: return RemoveSegment(located, i, true);
    case TypeEdit::kRemoveKeepApart: return RemoveSegment(located, i, false);
  }
  return located;
}

}  // namespace stickslip
