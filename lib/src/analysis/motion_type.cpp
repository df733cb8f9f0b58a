#include "stickslip/analysis/motion_type.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"

namespace stickslip {

double RelativeDistance(const State& a, const State& b) {
  const double d = (a - b).lpNorm<Eigen::Infinity>() / (1.0 + b.lpNorm<Eigen::Infinity>());
  return std::isfinite(d) ? d : std::numeric_limits<double>::infinity();
}

namespace {

// The preference of an event as the orbit's origin: lower is better (see the header).
int OriginRank(const Event& e) {
  if (e.mode_after != Mode::kSlipNegative) return 3;
  if (e.kind == EventKind::kStop && e.mode_before == Mode::kSlipPositive) return 0;
  if (e.kind == EventKind::kStickExit) return 1;
  return 2;
}

bool SameEvent(const Event& a, const Event& b, bool mirrored) {
  auto m = [&](Mode mode) { return mirrored ? Mirror(mode) : mode; };
  return a.kind == b.kind && m(a.mode_before) == b.mode_before && m(a.mode_after) == b.mode_after;
}

// One period's events: the origin's index and the number of listed segments, or why there is
// none. The period's end is the event like the origin (its mirror image when antisymmetric)
// nearest to origin + covered time; it must fall within kEndSlack periods of it.
struct PeriodEvents {
  int origin = -1;
  int segments = 0;
  std::string problem;
  bool unsettled = false;  // the origin's event comes back, but off the period: not settled yet
};

PeriodEvents ReadPeriod(const std::vector<Event>& events, double covered, double period_time, double period,
                        bool antisymmetric, int max_segments) {
  constexpr double kEndSlack = 1e-3;  // forcing periods
  constexpr const char* kNoEvent = "no stop or stick exit in a period (a permanent stick has no orbit type)";
  PeriodEvents found;
  if (events.empty()) {
    found.problem = kNoEvent;
    return found;
  }
  // Every kind of event of the period occurs once in the period from the first event on (the
  // record's start is no event, even where it lies on one).
  const double window_end = events.front().t + period_time - kEndSlack * period;
  int best_rank = 4;
  for (int i = 0; i < static_cast<int>(events.size()) && events[i].t < window_end; ++i) {
    if (OriginRank(events[i]) < best_rank) {
      best_rank = OriginRank(events[i]);
      found.origin = i;
    }
  }
  if (found.origin < 0 || events.front().t >= period_time) {
    found.problem = kNoEvent;
    found.origin = -1;
    return found;
  }
  const Event& origin = events[found.origin];
  const double end_time = origin.t + covered;
  double best = std::numeric_limits<double>::infinity();
  for (int j = found.origin + 1; j < static_cast<int>(events.size()) && j - found.origin <= max_segments + 1; ++j) {
    const double distance = std::abs(events[j].t - end_time);
    if (SameEvent(origin, events[j], antisymmetric) && distance < best) {
      best = distance;
      found.segments = j - found.origin;
    }
  }
  if (!(best <= kEndSlack * period)) {
    found.problem = found.segments == 0 || found.segments > max_segments
                        ? fmt::format("the origin's event does not come back within {} segments", max_segments)
                        : fmt::format("the origin's event comes back {:.3g} off the period", best);
    found.unsettled = found.segments > 0 && found.segments <= max_segments;
    found.segments = 0;
  } else if (found.segments > max_segments) {
    found.problem = fmt::format("{} segments in a period, more than max_segments = {}", found.segments, max_segments);
    found.segments = 0;
  }
  return found;
}

}  // namespace

MotionType ReadMotionType(const SimulationResult& record, int k, double period, const MotionTypeOptions& options) {
  // Antisymmetry X(t + k T/2) = -X(t), on the section and half a period later (odd k only: the
  // forcing must change sign); then one period's events from the origin on (the whole period when
  // the events do not bear out the antisymmetry the section showed).
  MotionType type;
  if (k % 2 == 1) {
    double mismatch = 0.0;
    for (int n = 0; n < options.confirmations * k; ++n) {
      const State half = StateAt(record, n * period + 0.5 * k * period);
      mismatch = std::max(mismatch, RelativeDistance(-half, StateAt(record, n * period)));
    }
    type.antisymmetry_mismatch = mismatch;
    type.antisymmetric = mismatch <= options.periodicity_tolerance;
  }
  PeriodEvents events;
  if (type.antisymmetric) {
    events = ReadPeriod(record.events, 0.5 * k * period, k * period, period, true, options.max_segments);
    if (events.segments == 0) type.antisymmetric = false;
  }
  if (!type.antisymmetric) {
    events = ReadPeriod(record.events, k * period, k * period, period, false, options.max_segments);
  }
  type.origin = events.origin;
  type.segments = events.segments;
  type.problem = events.problem;
  type.unsettled = events.unsettled;
  if (type.segments == 0) return type;
  std::vector<Mode> modes;
  for (int j = type.origin; j < type.origin + type.segments; ++j) modes.push_back(record.events[j].mode_after);
  try {
    type.signature.emplace(modes, type.antisymmetric, k);
  } catch (const InvalidInput& e) {
    type.problem = fmt::format("its events are no orbit type: {}", e.what());
  }
  return type;
}

}  // namespace stickslip
