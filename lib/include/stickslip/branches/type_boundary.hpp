// A boundary of an orbit type continued in two parameters (issue 13, the type boundaries whose
// defining condition is a segment end): where a stick of zero length sits in the orbit, its exit
// condition at zero length is the margin's zero, so the periodicity equations of the type with
// that stick, its duration held at zero and a second parameter released, are a square system at a
// fixed continued parameter, whose branch is the boundary curve in the plane of the two.
//   reversal:i       crossing-sliding (SK): the stick the adjacent type inserts after segment i,
//                    of zero length: s at the stop reaches the static level (eq. 11)
//   abnormal-stop:i  the stick inserted between two equal slips (u_r = u_s), likewise
//   duration:i       of a stick (T0): the located orbit's own stick, at zero length
// The grazings (velocity:i, G:i, G1:i: an interior extremum, which needs its time as an unknown)
// and the ends that hold identically at zero length (a zero-length slip ends where it starts, at
// x2' = 0: stick-entry:i, a slip's duration:i) are not boundaries this construction gives.
//
// Along the curve the zero-length stick's own margins are zero or undefined (it is the boundary),
// so the points are not flagged admissible; the other margins say which part of the curve bounds
// motions (codimension-two points, where a second margin reaches zero, end the branch as usual).
#pragma once

#include <string>
#include <string_view>

#include "stickslip/branches/type_switch.hpp"

namespace stickslip {

struct TypeBoundarySetup {
  OrbitContinuationSetup setup;  // ContinueOrbit(setup) follows the curve
  std::string held;              // the zero-length stick's duration, held at 0 ("d2")
  int stick = 0;                 // its 0-based listed segment in setup.start.signature
};

// The boundary through `located` (TypeChangeAt) in the plane of its parameter and `second` (a
// parameter: chi, eta, omega, u_s, u_r; released), with the options, shooting and flow of
// `branch_setup`. Throws InvalidInput naming "margin" for a margin this construction does not
// give a boundary of, and "second" for a second parameter that is the continued one, already
// released, or no parameter.
TypeBoundarySetup TypeBoundary(const LocatedTypeChange& located, const OrbitContinuationSetup& branch_setup,
                               std::string_view second);

}  // namespace stickslip
