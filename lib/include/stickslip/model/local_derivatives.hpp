// Exact gradients of scalar functions of (state, forcing phase, parameters) such as the event
// functions x2', x2'' and s (eq. 2, 11), by forward-mode automatic differentiation.
#pragma once

// <Eigen/Core> must precede the unsupported AutoDiff module.
#include <type_traits>

#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include "stickslip/model/flows.hpp"

namespace stickslip {

struct LocalGradient {
  double value = 0.0;
  Eigen::Vector4d d_state = Eigen::Vector4d::Zero();
  double d_phase = 0.0;
  Eigen::Matrix<double, 1, kParameterCount> d_parameters =
      Eigen::Matrix<double, 1, kParameterCount>::Zero();
};

// The scalar type of a generic lambda's argument. Such lambdas must return Scalar<...>
// explicitly: an `auto` return of an AutoDiff expression would dangle (it references
// temporaries that die with the lambda).
template <typename Argument>
using Scalar = std::decay_t<Argument>;

// f is called as f(state, phase, parameters) with an automatic-differentiation scalar.
template <typename Function>
LocalGradient Differentiate(Function&& f, const State& x, double phase, const Parameters& p) {
  constexpr int kDirections = 4 + 1 + kParameterCount;
  using Dual = Eigen::AutoDiffScalar<Eigen::Matrix<double, kDirections, 1>>;
  StateT<Dual> xd;
  for (int i = 0; i < 4; ++i) xd(i) = Dual(x(i), kDirections, i);
  BasicParameters<Dual> pd;
  for (int k = 0; k < kParameterCount; ++k) {
    pd[kAllParameters[k]] = Dual(p[kAllParameters[k]], kDirections, 5 + k);
  }
  const Dual value = f(xd, Dual(phase, kDirections, 4), pd);
  LocalGradient g;
  g.value = value.value();
  if (value.derivatives().size() == kDirections) {
    g.d_state = value.derivatives().template head<4>();
    g.d_phase = value.derivatives()(4);
    g.d_parameters = value.derivatives().template tail<kParameterCount>().transpose();
  }
  return g;
}

}  // namespace stickslip
