// The period map of an orbit by the exact simulator, independent of the monodromy matrix that
// the saltation matrices give (orbits/stability.hpp): sampled half-way through the first segment,
// where it is smooth, its Jacobian by central differences has the same eigenvalues as the
// monodromy matrix at t = 0.
#pragma once

#include <numbers>

#include <Eigen/Core>

#include "stickslip/model/exact_simulator.hpp"
#include "stickslip/model/pascal_2014.hpp"
#include "stickslip/orbits/orbit.hpp"

namespace stickslip {

// ... over `fraction` of the period (one half for the half-period map of an antisymmetric orbit).
template <typename Model>
Eigen::Matrix<double, Model::kStateSize, Model::kStateSize> PeriodMapJacobian(const Model& model,
                                                                              const BasicOrbit<Model>& o,
                                                                              double fraction = 1.0) {
  using ModelState = typename Model::State;
  const double t = 0.5 * o.durations[0];
  const typename Model::Parameters& p = o.parameters;
  const double omega = model.ForcingFrequency(p);
  const ModelState x = model.Flow(o.signature.segments()[0], o.start, o.phi, t, p);
  const double phase = o.phi + omega * t;
  BasicSimulationOptions<ModelState> options;
  options.duration = fraction * o.signature.period_multiple() * 2.0 * std::numbers::pi / omega;
  auto map = [&](const ModelState& start) { return SimulateExact(model, p, start, phase, options).segments.back().end; };
  Eigen::Matrix<double, Model::kStateSize, Model::kStateSize> j(model.StateSize(), model.StateSize());
  for (int k = 0; k < model.StateSize(); ++k) {
    const double h = 1e-6;
    ModelState plus = x, minus = x;
    plus(k) += h;
    minus(k) -= h;
    j.col(k) = (map(plus) - map(minus)) / (2 * h);
  }
  return j;
}
inline Eigen::Matrix4d PeriodMapJacobian(const Orbit& o, double fraction = 1.0) {
  return PeriodMapJacobian(Pascal2014{}, o.OnModel(), fraction);
}

}  // namespace stickslip
