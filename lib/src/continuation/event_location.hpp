// Locating a test function's zero on the branch itself, between two accepted points, by a
// bracketing root finder in arclength: TOMS 748 for a continuous function, bisection for a sign.
#pragma once

#include <optional>
#include <vector>

#include "arclength_corrector.hpp"
#include "events.hpp"

namespace stickslip::detail {

struct Located {
  double s = 0.0;           // arclength from the last accepted point
  const Event* event = nullptr;
  Sample sample;            // the corrected point there
  double value = 0.0;       // the event's function there
  double value_before = 0.0;  // ... and at the last accepted point
  bool located = true;      // false if the corrector failed inside the bracket
  double bracket = 0.0;     // final arclength bracket width
};

// The zero of `event` between a and b, b at arclength ds from a, where it changes sign from ga to
// gb. If the corrector fails inside the bracket, not located, at b. nullopt where the sign change
// of a function that may have poles is one: the value next to the change (at the located point;
// where the corrector failed, the smaller of those at the ends of the narrowest bracket the trial
// points reached) is larger than the smaller of ga and gb.
std::optional<Located> Locate(const Event& event, const Sample& a, const Sample& b, double ds, double ga, double gb,
                              ArclengthCorrector& corrector, const EventLocationOptions& options);

// Every event that changes sign between a and b, located, grouped into points: in arclength
// order, events less than options.same_point tolerances apart are one point, in priority order.
std::vector<std::vector<Located>> DetectAndLocate(const std::vector<Event>& events, const Sample& a, const Sample& b,
                                                  double ds, ArclengthCorrector& corrector,
                                                  const EventLocationOptions& options);

}  // namespace stickslip::detail
