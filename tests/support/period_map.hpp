// The period map of an orbit by the exact simulator, independent of the monodromy matrix that
// the saltation matrices give (orbits/stability.hpp): sampled half-way through the first segment,
// where it is smooth, its Jacobian by central differences has the same eigenvalues as the
// monodromy matrix at t = 0.
#pragma once

#include <Eigen/Core>

#include "stickslip/model/flows.hpp"
#include "stickslip/model/simulation.hpp"
#include "stickslip/orbits/orbit.hpp"

namespace stickslip {

// ... over `fraction` of the period (one half for the half-period map of an antisymmetric orbit).
inline Eigen::Matrix4d PeriodMapJacobian(const Orbit& o, double fraction = 1.0) {
  const double t = 0.5 * o.durations[0];
  const Parameters& p = o.parameters;
  const State x = Flow(o.signature.segments()[0], o.InitialState(), o.phi, t, p);
  const double phase = o.phi + p.omega * t;
  SimulationOptions options;
  options.duration = fraction * o.Period();
  auto map = [&](const State& start) { return SimulateExact(p, start, phase, options); };
  Eigen::Matrix4d j;
  for (int k = 0; k < 4; ++k) {
    const double h = 1e-6;
    State plus = x, minus = x;
    plus(k) += h;
    minus(k) -= h;
    j.col(k) = (map(plus).segments.back().end - map(minus).segments.back().end) / (2 * h);
  }
  return j;
}

}  // namespace stickslip
