#include "stickslip/branches/trace.hpp"

#include <string>
#include <vector>

#include "stickslip/branches/model_trace.hpp"

namespace stickslip {

namespace trace_detail {

const char* DirectionName(int direction) { return direction > 0 ? "up" : "down"; }

bool IsMarginChange(const SpecialPoint& s) { return s.test_function.starts_with(orbit_columns::kMarginPrefix); }

bool IsFamilyEnd(const SpecialPoint* s) {
  return s->test_function == std::string(orbit_columns::kMarginPrefix) + "sliding-friction";
}

TraceEnd LinkEndOf(BranchEnd end) {
  switch (end) {
    case BranchEnd::kParameterBound:
    case BranchEnd::kStartOutsideRange: return TraceEnd::kParameterBound;
    case BranchEnd::kClosedLoop: return TraceEnd::kLoop;
    case BranchEnd::kStopped: return TraceEnd::kResonance;
    case BranchEnd::kMaxPoints: return TraceEnd::kMaxPoints;
    default: return TraceEnd::kContinuationFailed;
  }
}

std::vector<const SpecialPoint*> ChangesAtEnd(const Branch& branch, double loop_tolerance) {
  const Eigen::VectorXd& u_end = branch.points.back().u;
  const double same = loop_tolerance * (1.0 + u_end.lpNorm<Eigen::Infinity>());
  int first_at_end = static_cast<int>(branch.points.size()) - 1;
  while (first_at_end > 0 && (branch.points[first_at_end - 1].u - u_end).lpNorm<Eigen::Infinity>() <= same) {
    --first_at_end;
  }
  std::vector<const SpecialPoint*> changes;
  for (const SpecialPoint& s : branch.special_points) {
    if (IsMarginChange(s) && s.point >= first_at_end) changes.push_back(&s);
  }
  return changes;
}

}  // namespace trace_detail

const char* ToString(TraceEnd end) {
  switch (end) {
    case TraceEnd::kSwitched: return "switched";
    case TraceEnd::kSameTypeOn: return "same-type-on";
    case TraceEnd::kParameterBound: return "parameter-bound";
    case TraceEnd::kLoop: return "loop";
    case TraceEnd::kResonance: return "resonance";
    case TraceEnd::kNotConfirmed: return "not-confirmed";
    case TraceEnd::kNoAdjacentType: return "no-adjacent-type";
    case TraceEnd::kFamilyEnd: return "family-end";
    case TraceEnd::kContinuationFailed: return "continuation-failed";
    case TraceEnd::kMaxPoints: return "max-points";
    case TraceEnd::kMaxBranches: return "max-branches";
    case TraceEnd::kNotAMotion: break;
  }
  return "not-a-motion";
}

const char* ToString(LinkStart start) {
  switch (start) {
    case LinkStart::kTraceStart: return "trace-start";
    case LinkStart::kSwitch: return "switch";
    case LinkStart::kFollowedPast: return "followed-past";
    case LinkStart::kAdmissibleAgain: break;
  }
  return "admissible-again";
}

void TraceOptions::Validate() const {
  ValidateOwnFields();
  type_switch.Validate();
}

bool TraceCompleted(TraceEnd down, TraceEnd up) {
  auto ok = [](TraceEnd e) {
    return e == TraceEnd::kParameterBound || e == TraceEnd::kFamilyEnd || e == TraceEnd::kLoop || e == TraceEnd::kResonance ||
           e == TraceEnd::kMaxPoints || e == TraceEnd::kMaxBranches;
  };
  return ok(down) && ok(up);
}

template TraceResult TraceOrbits(const OrbitContinuationSetup& start, const TraceOptions& options);
template OrbitContinuationSetup AtLeastPeriod(OrbitContinuationSetup setup);

}  // namespace stickslip
