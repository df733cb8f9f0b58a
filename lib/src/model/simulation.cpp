#include "stickslip/model/simulation.hpp"

#include <algorithm>

#include "stickslip/model/exact_simulator.hpp"

namespace stickslip {

const char* ToString(SimulationEnd end) {
  switch (end) {
    case SimulationEnd::kDuration: return "duration";
    case SimulationEnd::kMaxEvents: return "max-events";
    case SimulationEnd::kStuckAtRest: return "stuck-at-rest";
    case SimulationEnd::kSearchLimit: break;
  }
  return "search-limit";
}

const char* ToString(EventKind kind) {
  return kind == EventKind::kStop ? "stop" : "stick-exit";
}

const char* ToString(SegmentEnd end) {
  switch (end) {
    case SegmentEnd::kStop: return "stop";
    case SegmentEnd::kStickExit: return "stick-exit";
    case SegmentEnd::kHorizon: break;
  }
  return "horizon";
}

Mode InitialMode(const State& x0, double phi, const Parameters& p) { return InitialMode(Pascal2014{}, x0, phi, p); }

SimulationResult SimulateExact(const Parameters& p, const State& x0, double phi,
                               const SimulationOptions& options) {
  return SimulateExact(Pascal2014{}, p, x0, phi, options);
}

State StateAt(const SimulationResult& result, double t) {
  const auto it = std::lower_bound(
      result.segments.begin(), result.segments.end(), t,
      [](const Segment& s, double time) { return s.t_end < time; });
  const Segment& s = it == result.segments.end() ? result.segments.back() : *it;
  const Parameters& p = result.parameters;
  return Flow(s.mode, s.start, p.omega * s.t_start + result.phi, t - s.t_start, p);
}

}  // namespace stickslip
