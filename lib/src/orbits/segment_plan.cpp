#include "stickslip/orbits/segment_plan.hpp"

#include <array>

namespace stickslip {

std::vector<SegmentSpec> SegmentPlan(const Signature& signature, Extent extent) {
  const int listed = signature.size();
  const bool mirror_half = extent == Extent::kFullPeriod && signature.antisymmetric();
  const std::vector<Mode> modes = extent == Extent::kFullPeriod ? signature.FullPeriod() : signature.segments();
  const int count = static_cast<int>(modes.size());
  std::vector<SegmentSpec> plan;
  plan.reserve(modes.size());
  for (int k = 0; k < count; ++k) {
    // After the listed half of an antisymmetric orbit comes the mirror of its first segment;
    // after a whole period, the first segment again.
    const Mode next = k + 1 < count ? modes[k + 1] : mirror_half ? modes.front() : signature.NextMode(listed - 1);
    plan.push_back({k % listed, k >= listed, modes[k], next, EndKindOf(modes[k], next)});
  }
  return plan;
}

std::span<const EndCondition> EndConditionsOf(SegmentEndKind end) {
  static constexpr std::array<EndCondition, 1> kStop = {EndCondition::kStop};
  static constexpr std::array<EndCondition, 2> kAbnormalStop = {EndCondition::kStop,
                                                                EndCondition::kSlipAccelerationZero};
  static constexpr std::array<EndCondition, 1> kExitNegative = {EndCondition::kExitIntoSlipNegative};
  static constexpr std::array<EndCondition, 1> kExitPositive = {EndCondition::kExitIntoSlipPositive};
  switch (end) {
    case SegmentEndKind::kReversal:
    case SegmentEndKind::kStickEntry: return kStop;
    case SegmentEndKind::kAbnormalStop: return kAbnormalStop;
    case SegmentEndKind::kExitToNegative: return kExitNegative;
    case SegmentEndKind::kExitToPositive: break;
  }
  return kExitPositive;
}

}  // namespace stickslip
