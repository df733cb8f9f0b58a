#include "stickslip/orbits/least_period.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"

namespace stickslip {

const char* ToString(LeastPeriodStatus status) {
  switch (status) {
    case LeastPeriodStatus::kLeast: return "least";
    case LeastPeriodStatus::kReduced: return "reduced";
    case LeastPeriodStatus::kNotRepeating: break;
  }
  return "not-repeating";
}

void LeastPeriodOptions::Validate() const {
  if (!(tolerance >= kMinTolerance && tolerance <= kMaxTolerance)) {
    throw InvalidInput("tolerance", tolerance, fmt::format("{} <= tolerance <= {}", kMinTolerance, kMaxTolerance));
  }
}

namespace {

// Whether `segments` are copies of their first `length`: plain copies, or for an antisymmetric
// half alternately the copy and its mirror image (the shorter orbit's half, then its other half).
bool IsRepeatOf(const std::vector<Mode>& segments, int length, bool antisymmetric) {
  for (int i = length; i < static_cast<int>(segments.size()); ++i) {
    const Mode first = segments[i % length];
    const bool mirrored = antisymmetric && (i / length) % 2 == 1;
    if (segments[i] != (mirrored ? Mirror(first) : first)) return false;
  }
  return true;
}

// Whether `signature` is `times` copies of a shorter one that has a whole number of forcing periods
// (odd for an antisymmetric one, whose half must end where the forcing has changed sign).
bool IsCopies(const Signature& signature, int times) {
  return signature.size() % times == 0 && signature.period_multiple() % times == 0 &&
         (!signature.antisymmetric() || times % 2 == 1) &&
         IsRepeatOf(signature.segments(), signature.size() / times, signature.antisymmetric());
}

Signature FirstCopy(const Signature& signature, int times) {
  const auto begin = signature.segments().begin();
  return Signature(std::vector<Mode>(begin, begin + signature.size() / times), signature.antisymmetric(),
                   signature.period_multiple() / times);
}

struct CopyMismatch {
  double durations = 0.0;  // forcing periods
  double state = 0.0;      // relative
  bool Within(double tolerance) const { return durations <= tolerance && state <= tolerance; }
};

// How far `orbit` is from `times` copies of its first copy: every duration against the first
// copy's, the first copy's span against its share of the period, and the state after it against
// the start (mirrored when antisymmetric: after half a period of the shorter orbit).
CopyMismatch MismatchOfCopies(const Orbit& orbit, int times) {
  const int m = orbit.signature.size() / times;
  const double forcing_period = 2.0 * std::numbers::pi / orbit.parameters.omega;
  CopyMismatch mismatch;
  double span = 0.0;
  for (int i = 0; i < orbit.signature.size(); ++i) {
    mismatch.durations = std::max(mismatch.durations, std::abs(orbit.durations[i] - orbit.durations[i % m]));
    if (i < m) span += orbit.durations[i];
  }
  const double share = orbit.signature.CoveredFraction() * orbit.Period() / times;
  mismatch.durations = std::max(mismatch.durations, std::abs(span - share)) / forcing_period;
  const State start = orbit.InitialState();
  const State after = orbit.SegmentStates()[m];
  const State expected = orbit.signature.antisymmetric() ? State(-start) : start;
  mismatch.state = (after - expected).lpNorm<Eigen::Infinity>() / (1.0 + start.lpNorm<Eigen::Infinity>());
  if (!std::isfinite(mismatch.durations) || !std::isfinite(mismatch.state)) return {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  return mismatch;
}

Orbit FirstCopyOf(const Orbit& orbit, int times) {
  Orbit reduced = orbit;
  reduced.signature = FirstCopy(orbit.signature, times);
  reduced.durations.resize(reduced.signature.size());
  return reduced;
}

}  // namespace

SignatureRepeat LeastPeriodSignature(const Signature& signature) {
  // The most copies give the least period.
  for (int times = signature.size(); times > 1; --times) {
    if (IsCopies(signature, times)) return {FirstCopy(signature, times), times};
  }
  return {signature, 1};
}

LeastPeriodOrbit ReduceToLeastPeriod(const Orbit& orbit, const LeastPeriodOptions& options) {
  options.Validate();
  if (static_cast<int>(orbit.durations.size()) != orbit.signature.size()) {
    throw InvalidInput::WithMessage("durations", fmt::format("{} durations for the {} segments of '{}'",
                                                             orbit.durations.size(), orbit.signature.size(),
                                                             orbit.signature.ToString()));
  }
  const SignatureRepeat repeat = LeastPeriodSignature(orbit.signature);
  LeastPeriodOrbit result{LeastPeriodStatus::kLeast, orbit, 1, 0.0, 0.0, "the signature repeats no shorter one"};
  if (repeat.repeats == 1) return result;
  const CopyMismatch full = MismatchOfCopies(orbit, repeat.repeats);
  result.duration_mismatch = full.durations;
  result.state_mismatch = full.state;
  // The copies of a coarser repeat are copies of the finer one: its counts divide the signature's.
  for (int times = repeat.repeats; times > 1; --times) {
    if (repeat.repeats % times != 0 || !IsCopies(orbit.signature, times)) continue;
    if (!MismatchOfCopies(orbit, times).Within(options.tolerance)) continue;
    result.status = LeastPeriodStatus::kReduced;
    result.orbit = FirstCopyOf(orbit, times);
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

}  // namespace stickslip
