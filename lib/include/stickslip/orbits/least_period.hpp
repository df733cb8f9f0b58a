// Least-period reduction: a signature that repeats a shorter one, and an orbit written over
// several of its own periods, reduced to the shortest.
//
// A period-1 orbit can be written as a period-3 one: its segment sequence listed three times,
// period 3 (a brute-force motion read over 3 forcing periods, or a trace that crossed a type change
// into the repeated sequence). Both describe one motion, and an atlas must count it once. The
// reduction keeps the origin: the first copy starts where the whole did (orbit.hpp's origin, a
// stop), so the reduced orbit has the same x10, x20, v10 and phi.
//
// Plain signatures: the sequence is `repeats` equal copies, and repeats divides period K. An
// antisymmetric signature lists half a period, K T/2; a half that is an odd number of half-periods
// of a shorter antisymmetric orbit alternates copy and mirror image (Q, mirror(Q), Q, ...), and the
// repeat count divides K (both odd). A sequence that repeats within one forcing period cannot be
// the repeat of a forced orbit (the forcing's period is the least), so "slip- slip+ slip- slip+" of
// period 1 stays as it is.
//
//   const SignatureRepeat r = LeastPeriodSignature(Signature::Parse("slip- slip+ slip- slip+ / period 2"));
//   // r.least is "slip- slip+", r.repeats == 2
//   const LeastPeriodOrbit o = ReduceToLeastPeriod(orbit);
//   if (o.status == LeastPeriodStatus::kReduced) use(o.orbit);
#pragma once

#include <string>

#include "stickslip/orbits/orbit.hpp"
#include "stickslip/orbits/signature.hpp"

namespace stickslip {

struct SignatureRepeat {
  Signature least;  // the shortest signature that, repeated, gives the input (the input if none)
  int repeats = 1;  // copies of `least` in the input: its period multiple is least's times this
};

// The least-period signature of `signature` (the rules above).
SignatureRepeat LeastPeriodSignature(const Signature& signature);

struct LeastPeriodOptions {
  // The durations repeat when |d(i + j m) - d(i)| <= tolerance 2 pi/omega for every copy j (m
  // segments a copy), and the first copy spans its share of the period to the same tolerance; the
  // state after the first copy is the start (its mirror image when antisymmetric) when
  // |X - X0|_inf <= tolerance (1 + |X0|_inf). From kMinTolerance to kMaxTolerance.
  double tolerance = 1e-8;

  static constexpr double kMinTolerance = 1e-14;
  static constexpr double kMaxTolerance = 1e-2;
  void Validate() const;  // throws InvalidInput naming "tolerance"
};

enum class LeastPeriodStatus {
  kLeast,         // the signature repeats no shorter one: the orbit is as given
  kReduced,       // reduced to `repeats` fewer periods
  kNotRepeating,  // the signature repeats, but the durations or the state do not: no reduction
};
const char* ToString(LeastPeriodStatus status);  // "least", "reduced", "not-repeating"

struct LeastPeriodOrbit {
  LeastPeriodStatus status = LeastPeriodStatus::kLeast;
  Orbit orbit;      // the reduced orbit (the given one unless kReduced)
  int repeats = 1;  // copies of `orbit` in the given one (1 unless kReduced)
  // For the signature's own repeat count (LeastPeriodSignature): how far the durations (in
  // forcing periods) and the state after the first copy (relative) are from repeating. 0 for kLeast.
  double duration_mismatch = 0.0;
  double state_mismatch = 0.0;
  std::string message;  // one line: what was reduced, or why not
};

// `orbit` at its least period: the first copy of its signature's repeat, when its durations and
// state repeat too; a coarser repeat (a divisor of the signature's count) when only that one does
// (a period-6 sequence that is a period-2 orbit). Throws InvalidInput for options out of range or
// durations that do not match the signature's size.
LeastPeriodOrbit ReduceToLeastPeriod(const Orbit& orbit, const LeastPeriodOptions& options = {});

}  // namespace stickslip
