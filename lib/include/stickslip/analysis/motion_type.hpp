// The orbit type of a simulated motion that repeats on the stroboscopic section after k forcing
// periods: whether it is antisymmetric (X(t + k T/2) = -X(t), odd k), the events of one period
// from an origin, and the signature they give. Shared by FindOrbit (analysis/orbit_finder.hpp)
// and the brute-force map (analysis/brute_force_map.hpp).
//
// The origin is, of the events in the first period of the record, the first of, in this order of
// preference: a reversal from slip+ into slip-, a stick exit into slip-, an abnormal stop in
// slip-, any event (the paper's choice for all five of its orbits). The period's end is the event
// like the origin (its mirror image when antisymmetric) nearest to origin + k T (k T/2); it must
// fall within 1e-3 T of it, or the motion has not settled.
//
//   const MotionType type = ReadMotionType(record, k, 2 * pi / omega, {});
//   if (type.signature) std::cout << type.signature->ToString();
#pragma once

#include <limits>
#include <optional>
#include <string>

#include "stickslip/model/simulation.hpp"
#include "stickslip/orbits/signature.hpp"

namespace stickslip {

struct MotionTypeOptions {
  // X(t + k T/2) = -X(t) when |X(t + k T/2) + X(t)|_inf <= tolerance (1 + |X(t)|_inf).
  double periodicity_tolerance = 1e-6;
  // Antisymmetry is checked at the section points n T, n < confirmations k, and half a period
  // later: the record must reach (confirmations k + k/2) T.
  int confirmations = 3;
  int max_segments = 200;  // the largest number of listed segments of an orbit type
};

struct MotionType {
  bool antisymmetric = false;
  double antisymmetry_mismatch = std::numeric_limits<double>::quiet_NaN();  // for odd k
  int origin = -1;   // index of the origin's event in record.events
  int segments = 0;  // listed segments from the origin on (0: none read)
  std::optional<Signature> signature;  // when the events of one period give an orbit type
  std::string problem;                 // why there is none ("no stop or stick exit in a period ...")
  bool unsettled = false;  // the origin's event comes back, but off the period: not settled yet
};

// |a - b|_inf relative to 1 + |b|_inf, as the tolerances of FindOrbit and ReadMotionType are
// stated; infinite for non-finite states.
double RelativeDistance(const State& a, const State& b);

// `record` starts at a section time (t = 0) and covers at least 2 k T (origin within the first
// k T, and one period from it), T = `period`.
MotionType ReadMotionType(const SimulationResult& record, int k, double period, const MotionTypeOptions& options);

}  // namespace stickslip
