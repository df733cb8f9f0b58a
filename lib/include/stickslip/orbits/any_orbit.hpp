// What the layers above ask of any model's orbit (model/oscillator_model.hpp), the paper's Orbit
// and another model's BasicOrbit alike: its BasicOrbit form, its period, one of its variables by
// the index of OrbitLayout, and how far two orbits are apart. The templates on the model that
// switch types and trace (branches/) take OrbitOfModel<Model> and ask through these.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "stickslip/model/oscillator_model.hpp"
#include "stickslip/orbits/orbit.hpp"
#include "stickslip/orbits/orbit_layout.hpp"
#include "stickslip/orbits/segment_walk.hpp"

namespace stickslip {

// The orbit as its model's BasicOrbit: the paper's Orbit converted, any other as it is.
inline BasicOrbit<Pascal2014> AsBasicOrbit(const Orbit& orbit) { return orbit.OnModel(); }
template <typename Model>
const BasicOrbit<Model>& AsBasicOrbit(const BasicOrbit<Model>& orbit) {
  return orbit;
}

// The time after which the orbit repeats: k 2 pi/omega for a forced model (Orbit::Period), the
// whole period's durations for an autonomous one.
template <OscillatorModel Model>
double PeriodOf(const Model& model, const BasicOrbit<Model>& orbit) {
  if (model.Autonomous()) {
    double listed = 0.0;
    for (double d : orbit.durations) listed += d;
    return listed / orbit.signature.CoveredFraction();
  }
  return orbit.signature.period_multiple() * 2.0 * std::numbers::pi / model.ForcingFrequency(orbit.parameters);
}

// `count` (>= 2) states evenly spaced in time over the period, from the start to the period's end
// (back at the start on a periodic orbit), by the closed forms along the one segment walk: exact
// also where a margin vanishes (a grazing), where a simulator may take either side.
template <OscillatorModel Model>
std::vector<typename Model::State> SampleOrbit(const Model& model, const BasicOrbit<Model>& orbit, int count) {
  std::vector<typename Model::State> samples;
  const double period = PeriodOf(model, orbit);
  int k = 0;
  WalkSegments(model, orbit, Extent::kFullPeriod, PhaseRule::kAccumulated, [&](const SegmentVisit<double, Model>& s) {
    for (; k < count; ++k) {
      const double t = period * k / (count - 1);
      if (!s.last && t > s.t0 + s.duration) break;  // in a later segment
      samples.push_back(s.motion.StateAt(t - s.t0));
    }
  });
  return samples;
}

// The variable of OrbitLayout's `index` (start state, phase, durations, parameters).
template <OscillatorModel Model>
double VariableOf(const Model& model, const BasicOrbit<Model>& orbit, int index) {
  const OrbitLayout layout(model.Description(), orbit.signature.size());
  if (index < layout.StartVariables()) return orbit.start(index);
  if (index == layout.Phi()) return orbit.phi;
  if (index < layout.Parameter(0)) return orbit.durations[index - layout.Duration(0)];
  return Model::ParameterAt(orbit.parameters, index - layout.Parameter(0));
}

// The largest difference in the start state, the phase and the period: 0 for the same motion from
// the same origin, whatever the signatures.
template <OscillatorModel Model>
double OrbitDistance(const Model& model, const BasicOrbit<Model>& a, const BasicOrbit<Model>& b) {
  const double period = std::abs(PeriodOf(model, a) - PeriodOf(model, b));
  const double phase = std::abs(a.phi - b.phi);
  return std::max({(a.start - b.start).template lpNorm<Eigen::Infinity>(), phase, period});
}
double OrbitDistance(const Orbit& a, const Orbit& b);  // the paper's model's

}  // namespace stickslip
