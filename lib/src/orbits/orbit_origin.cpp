#include "stickslip/orbits/orbit_origin.hpp"

#include <numbers>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

namespace stickslip {

int OriginCount(const Signature& signature) {
  return signature.antisymmetric() ? 2 * signature.size() : signature.size();
}

namespace {

void CheckOrigin(const Signature& signature, int j) {
  if (j < 0 || j >= OriginCount(signature)) {
    throw std::out_of_range(fmt::format("origin {} of '{}' outside 0..{}", j, signature.ToString(),
                                        OriginCount(signature) - 1));
  }
}

}  // namespace

Signature WithOriginAt(const Signature& signature, int j) {
  CheckOrigin(signature, j);
  // The listed count of segments from the whole period's segment j on; for an antisymmetric orbit
  // the half from there, whose second part is the mirror image of the first part of the half.
  const std::vector<Mode> full = signature.FullPeriod();
  const int n = signature.size();
  std::vector<Mode> rotated;
  for (int i = 0; i < n; ++i) rotated.push_back(full[(j + i) % static_cast<int>(full.size())]);
  return Signature(std::move(rotated), signature.antisymmetric(), signature.period_multiple());
}

Orbit WithOriginAt(const Orbit& orbit, int j) {
  CheckOrigin(orbit.signature, j);
  const int n = orbit.signature.size();
  const bool mirrored = j >= n;  // in the mirrored half of an antisymmetric orbit
  const int listed = mirrored ? j - n : j;
  const State start = orbit.SegmentStates()[listed];
  const double t = orbit.SegmentTimes()[listed];
  Orbit rotated = orbit;
  rotated.signature = WithOriginAt(orbit.signature, j);
  const double sign = mirrored ? -1.0 : 1.0;
  rotated.x10 = sign * start(0);
  rotated.x20 = sign * start(1);
  rotated.v10 = sign * start(2);
  const double phase = orbit.phi + orbit.parameters.omega * t + (mirrored ? std::numbers::pi : 0.0);
  rotated.phi = PhaseInCycle(phase);
  for (int i = 0; i < n; ++i) rotated.durations[i] = orbit.durations[(listed + i) % n];
  return rotated;
}

Orbit MirrorImage(const Orbit& orbit) {
  std::vector<Mode> modes;
  for (Mode mode : orbit.signature.segments()) modes.push_back(Mirror(mode));
  Orbit mirrored = orbit;
  mirrored.signature = Signature(modes, orbit.signature.antisymmetric(), orbit.signature.period_multiple());
  mirrored.x10 = -orbit.x10;
  mirrored.x20 = -orbit.x20;
  mirrored.v10 = -orbit.v10;
  mirrored.phi = PhaseInCycle(orbit.phi + std::numbers::pi);
  return mirrored;
}

}  // namespace stickslip
