// Coulomb's law at rest, for every model's ModeFromRest: from the stick force s (signed so that
// s > threshold drives a slip with negative contact velocity) and the static threshold, a slip
// where |s| exceeds the threshold, a stick inside it. On the threshold, to rounding, the sign of
// ds/dt during a stick decides, as the continuous extension of the strict inequality: a stick that
// starts where the force is leaving the band ends at once (an orbit's origin at a stick exit).
// Only inside the band: a force a rounding outside it slips whatever its rate (the Odeint
// simulator's event logic sticks there when the force is coming back; neither is wrong to rounding).
#pragma once

#include <cmath>

#include "stickslip/model/mode.hpp"

namespace stickslip {

// `rate()` gives ds/dt during a stick; it is called only on the threshold.
template <typename Rate>
Mode CoulombModeAtRest(double s, double threshold, Rate&& rate) {
  if (s > threshold) return Mode::kSlipNegative;
  if (s < -threshold) return Mode::kSlipPositive;
  const double level = 1e-12 * (std::abs(s) + threshold + 1.0);
  if (threshold - std::abs(s) <= level) {
    const double ds_dt = rate();
    if (s > 0.0 && ds_dt > 0.0) return Mode::kSlipNegative;
    if (s < 0.0 && ds_dt < 0.0) return Mode::kSlipPositive;
  }
  return Mode::kStick;
}

}  // namespace stickslip
