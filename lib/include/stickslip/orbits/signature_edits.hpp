// Edits of an orbit type, the moves of a change of type (sliding bifurcations): a segment
// inserted (a new stick at a stop, a new stop inside a slip), removed (a phase that shrank to
// zero), or a segment split around a new one. Each returns a validated signature with the
// renumbering of the listed segments made explicit, so that a name that addresses a duration
// (fix = ["d2"], user_values_of) is renamed with the edit, never silently re-targeted.
//
// The orbit versions give the same motion (state, phase and period unchanged) under the edited
// type: an inserted segment has zero length, a removed one is expected to have reached zero.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/orbits/signature.hpp"

namespace stickslip {

struct SignatureEdit {
  Signature signature;
  // Where each listed segment of the original went (0-based; -1 if removed or joined into its
  // neighbour), and whether its duration still means what it meant (not split, not joined).
  std::vector<int> new_index;
  std::vector<bool> duration_kept;

  // The name of an orbit variable after the edit: "d2" becomes "d3" when a segment was inserted
  // before segment 2; every other variable keeps its name. Throws InvalidInput for the duration
  // of a segment that no longer stands on its own.
  std::string Renamed(std::string_view variable) const;
};

// A new segment in `mode` at listed position `position` (0..n): it follows segment position - 1.
// Throws InvalidInput if the result is not a valid signature (a stick beside a stick).
SignatureEdit InsertSegment(const Signature& signature, int position, Mode mode);

// Segment i removed. With join_equal_neighbours, the segments before and after it are joined
// when they are in the same mode (a slip interrupted by a vanished stick is one slip); without,
// they meet at an abnormal stop. Throws InvalidInput if nothing would remain, if the join would
// span the orbit's origin (rotate the orbit first), or if the result is invalid.
SignatureEdit RemoveSegment(const Signature& signature, int i, bool join_equal_neighbours);

// Segment i cut in two around a new segment in `inserted`: i, inserted, then i's mode again.
SignatureEdit SplitSegment(const Signature& signature, int i, Mode inserted);

// The orbit versions, for an orbit of any model (Orbit, BasicOrbit<Model>): only its signature
// and durations change.
// The orbit under the edited type, the same motion: the new segment has zero length.
template <typename AnyOrbit>
AnyOrbit InsertSegment(const AnyOrbit& orbit, int position, Mode mode) {
  AnyOrbit edited = orbit;
  edited.signature = InsertSegment(orbit.signature, position, mode).signature;
  edited.durations.insert(edited.durations.begin() + position, 0.0);
  return edited;
}
// Segment i's duration dropped (a joined neighbour takes the sum of both).
template <typename AnyOrbit>
AnyOrbit RemoveSegment(const AnyOrbit& orbit, int i, bool join_equal_neighbours) {
  const SignatureEdit edit = RemoveSegment(orbit.signature, i, join_equal_neighbours);
  AnyOrbit edited = orbit;
  edited.signature = edit.signature;
  const bool joined = edit.new_index.size() - edit.signature.segments().size() == 2;
  if (joined) edited.durations[i - 1] += orbit.durations[i + 1];
  edited.durations.erase(edited.durations.begin() + i, edited.durations.begin() + i + (joined ? 2 : 1));
  return edited;
}
// Segment i split at time tau after its start (0 <= tau <= d_i) around a zero-length segment.
// Throws InvalidInput naming "tau" otherwise.
template <typename AnyOrbit>
AnyOrbit SplitSegment(const AnyOrbit& orbit, int i, double tau, Mode inserted) {
  AnyOrbit edited = orbit;
  edited.signature = SplitSegment(orbit.signature, i, inserted).signature;
  const double d = orbit.durations[i];
  if (!(tau >= 0.0 && tau <= d)) throw InvalidInput("tau", tau, fmt::format("0 <= tau <= d{} = {}", i + 1, d));
  edited.durations[i] = tau;
  edited.durations.insert(edited.durations.begin() + i + 1, {0.0, d - tau});
  return edited;
}

// The same motion as an orbit over `copies` whole periods without the half-period symmetry: the
// whole period's segments (the listed half, then its mirror image, for an antisymmetric orbit)
// listed `copies` times, the period multiple times `copies`, the durations repeated. Listed
// segment i of the original is segment i + k n of the result, n = its listed count, k = 0, 1, ...
// (the type a period doubling leads to: copies = 2; a symmetry breaking: copies = 1). Throws
// InvalidInput naming "copies" unless 1 <= copies <= 64.
Signature Unfolded(const Signature& signature, int copies);
template <typename AnyOrbit>
AnyOrbit Unfolded(const AnyOrbit& orbit, int copies) {
  AnyOrbit unfolded = orbit;
  unfolded.signature = Unfolded(orbit.signature, copies);
  const int repeats = unfolded.signature.size() / orbit.signature.size();
  unfolded.durations.clear();
  for (int k = 0; k < repeats; ++k) {
    unfolded.durations.insert(unfolded.durations.end(), orbit.durations.begin(), orbit.durations.end());
  }
  return unfolded;
}

}  // namespace stickslip
