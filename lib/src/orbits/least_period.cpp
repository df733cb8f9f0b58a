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

}  // namespace

namespace least_period_detail {

bool IsCopies(const Signature& signature, int times, bool autonomous) {
  return signature.size() % times == 0 && (autonomous || signature.period_multiple() % times == 0) &&
         (!signature.antisymmetric() || times % 2 == 1) &&
         IsRepeatOf(signature.segments(), signature.size() / times, signature.antisymmetric());
}

Signature FirstCopy(const Signature& signature, int times, bool autonomous) {
  const auto begin = signature.segments().begin();
  return Signature(std::vector<Mode>(begin, begin + signature.size() / times), signature.antisymmetric(),
                   autonomous ? signature.period_multiple() : signature.period_multiple() / times);
}

}  // namespace least_period_detail

SignatureRepeat LeastPeriodSignature(const Signature& signature, bool autonomous) {
  namespace detail = least_period_detail;
  // The most copies give the least period.
  for (int times = signature.size(); times > 1; --times) {
    if (detail::IsCopies(signature, times, autonomous)) return {detail::FirstCopy(signature, times, autonomous), times};
  }
  return {signature, 1};
}

LeastPeriodOrbit ReduceToLeastPeriod(const Orbit& orbit, const LeastPeriodOptions& options) {
  return ReduceToLeastPeriod<Pascal2014>(Pascal2014{}, orbit, options);
}

}  // namespace stickslip
