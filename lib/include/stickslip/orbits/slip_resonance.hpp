// Where a forced orbit that never sticks has no bounded amplitude: at a natural frequency of an
// undamped slip, where the forced response's 1/(omega_k^2 - omega^2) diverges (for the paper's
// model omega1 and omega2 of eq. 56). A branch that approaches one ends there as a resonance
// (branches/orbit_continuation.hpp) instead of creeping towards it with its amplitude growing.
//
//   if (const auto r = NearestSlipResonance(orbit); r && r->distance < 1e-2) report(r->index, r->frequency);
#pragma once

#include <cmath>
#include <optional>
#include <vector>

#include "stickslip/model/oscillator_model.hpp"
#include "stickslip/orbits/orbit.hpp"

namespace stickslip {

struct SlipResonance {
  int index = 0;           // k, from 1 in increasing frequency
  double frequency = 0.0;  // omega_k
  double distance = 0.0;   // |omega - omega_k| / omega_k, omega the forcing frequency
};

// The natural frequency of an undamped slip nearest the forcing frequency, for a forced orbit
// without a stick; none for an orbit that sticks, an autonomous model or a damped slip (where the
// amplitude stays bounded and branches cross the natural frequencies).
template <OscillatorModel Model>
std::optional<SlipResonance> NearestSlipResonance(const Model& model, const BasicOrbit<Model>& orbit) {
  if (model.Autonomous()) return std::nullopt;
  for (Mode mode : orbit.signature.segments()) {
    if (mode == Mode::kStick) return std::nullopt;
  }
  const std::vector<double> omega = model.UndampedSlipFrequencies(orbit.parameters);
  const double forcing = model.ForcingFrequency(orbit.parameters);
  std::optional<SlipResonance> nearest;
  for (std::size_t k = 0; k < omega.size(); ++k) {
    const double distance = std::abs(forcing - omega[k]) / omega[k];
    if (!nearest || distance < nearest->distance) nearest = SlipResonance{static_cast<int>(k) + 1, omega[k], distance};
  }
  return nearest;
}

// The paper's model.
std::optional<SlipResonance> NearestSlipResonance(const Orbit& orbit);

}  // namespace stickslip
