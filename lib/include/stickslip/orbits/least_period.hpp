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
// For any model (model/oscillator_model.hpp); an autonomous one's durations are measured in its
// own period.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/orbits/any_orbit.hpp"
#include "stickslip/orbits/orbit.hpp"
#include "stickslip/orbits/segment_walk.hpp"
#include "stickslip/orbits/signature.hpp"

namespace stickslip {

struct SignatureRepeat {
  Signature least;  // the shortest signature that, repeated, gives the input (the input if none)
  int repeats = 1;  // copies of `least` in the input: its period multiple is least's times this
};

// The least-period signature of `signature` (the rules above).
// An autonomous orbit (no forcing) has no forcing period to divide: any repeat of its sequence
// may be its least period, and the period multiple is kept.
SignatureRepeat LeastPeriodSignature(const Signature& signature, bool autonomous = false);

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

template <typename Model>
struct BasicLeastPeriodOrbit {
  LeastPeriodStatus status = LeastPeriodStatus::kLeast;
  OrbitOfModel<Model> orbit;  // the reduced orbit (the given one unless kReduced)
  int repeats = 1;            // copies of `orbit` in the given one (1 unless kReduced)
  // For the signature's own repeat count (LeastPeriodSignature): how far the durations (in
  // forcing periods) and the state after the first copy (relative) are from repeating. 0 for kLeast.
  double duration_mismatch = 0.0;
  double state_mismatch = 0.0;
  std::string message;  // one line: what was reduced, or why not
};
using LeastPeriodOrbit = BasicLeastPeriodOrbit<Pascal2014>;

namespace least_period_detail {

// Whether `signature` is `times` copies of a shorter one that has a whole number of forcing periods
// (odd for an antisymmetric one, whose half must end where the forcing has changed sign); an
// autonomous orbit's copies need no forcing period.
bool IsCopies(const Signature& signature, int times, bool autonomous);
Signature FirstCopy(const Signature& signature, int times, bool autonomous);

struct CopyMismatch {
  double durations = 0.0;  // forcing periods (an autonomous orbit's: its periods)
  double state = 0.0;      // relative
  bool Within(double tolerance) const { return durations <= tolerance && state <= tolerance; }
};

// How far `orbit` is from `times` copies of its first copy: every duration against the first
// copy's, the first copy's span against its share of the period, and the state after it against
// the start (mirrored when antisymmetric: after half a period of the shorter orbit).
template <OscillatorModel Model>
CopyMismatch MismatchOfCopies(const Model& model, const BasicOrbit<Model>& orbit, int times) {
  const int m = orbit.signature.size() / times;
  const double period = PeriodOf(model, orbit);
  const double forcing_period = model.Autonomous() ? period / orbit.signature.period_multiple()
                                                   : 2.0 * std::numbers::pi / model.ForcingFrequency(orbit.parameters);
  CopyMismatch mismatch;
  double span = 0.0;
  for (int i = 0; i < orbit.signature.size(); ++i) {
    mismatch.durations = std::max(mismatch.durations, std::abs(orbit.durations[i] - orbit.durations[i % m]));
    if (i < m) span += orbit.durations[i];
  }
  const double share = orbit.signature.CoveredFraction() * period / times;
  mismatch.durations = std::max(mismatch.durations, std::abs(span - share)) / forcing_period;
  using State = typename Model::State;
  State after = orbit.start;
  WalkSegments(model, orbit, Extent::kListed, PhaseRule::kAccumulated, [&](const SegmentVisit<double, Model>& s) {
    if (s.index == m - 1) after = s.end;
  });
  const State expected = orbit.signature.antisymmetric() ? State(-orbit.start) : orbit.start;
  mismatch.state = (after - expected).template lpNorm<Eigen::Infinity>() /
                   (1.0 + orbit.start.template lpNorm<Eigen::Infinity>());
  if (!std::isfinite(mismatch.durations) || !std::isfinite(mismatch.state)) {
    return {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  }
  return mismatch;
}

}  // namespace least_period_detail

// `orbit` at its least period: the first copy of its signature's repeat, when its durations and
// state repeat too; a coarser repeat (a divisor of the signature's count) when only that one does
// (a period-6 sequence that is a period-2 orbit). Throws InvalidInput for options out of range or
// durations that do not match the signature's size.
template <OscillatorModel Model>
BasicLeastPeriodOrbit<Model> ReduceToLeastPeriod(const Model& model, const OrbitOfModel<Model>& orbit,
                                                 const LeastPeriodOptions& options = {}) {
  namespace detail = least_period_detail;
  options.Validate();
  if (static_cast<int>(orbit.durations.size()) != orbit.signature.size()) {
    throw InvalidInput::WithMessage("durations", fmt::format("{} durations for the {} segments of '{}'",
                                                             orbit.durations.size(), orbit.signature.size(),
                                                             orbit.signature.ToString()));
  }
  const bool autonomous = model.Autonomous();
  const SignatureRepeat repeat = LeastPeriodSignature(orbit.signature, autonomous);
  BasicLeastPeriodOrbit<Model> result{LeastPeriodStatus::kLeast, orbit, 1, 0.0, 0.0,
                                      "the signature repeats no shorter one"};
  if (repeat.repeats == 1) return result;
  const auto& basic = AsBasicOrbit(orbit);
  const detail::CopyMismatch full = detail::MismatchOfCopies(model, basic, repeat.repeats);
  result.duration_mismatch = full.durations;
  result.state_mismatch = full.state;
  // The copies of a coarser repeat are copies of the finer one: its counts divide the signature's.
  for (int times = repeat.repeats; times > 1; --times) {
    if (repeat.repeats % times != 0 || !detail::IsCopies(orbit.signature, times, autonomous)) continue;
    if (!detail::MismatchOfCopies(model, basic, times).Within(options.tolerance)) continue;
    result.status = LeastPeriodStatus::kReduced;
    result.orbit.signature = detail::FirstCopy(orbit.signature, times, autonomous);
    result.orbit.durations.resize(result.orbit.signature.size());
    result.repeats = times;
    result.message = fmt::format("'{}' is {} copies of '{}'", orbit.signature.ToString(), times,
                                 result.orbit.signature.ToString());
    return result;
  }
  result.status = LeastPeriodStatus::kNotRepeating;
  result.message = fmt::format(
      "'{}' repeats '{}' {} times, but the orbit does not: durations {:.3g} forcing periods and state {:.3g} from "
      "repeating (tolerance {:g})",
      orbit.signature.ToString(), repeat.least.ToString(), repeat.repeats, full.durations, full.state,
      options.tolerance);
  return result;
}

// The paper's model's.
LeastPeriodOrbit ReduceToLeastPeriod(const Orbit& orbit, const LeastPeriodOptions& options = {});

}  // namespace stickslip
