// A flow and its exact first derivatives, for a model with a state of `kStateSize` components (or
// Eigen::Dynamic) and `kParameters` parameters (oscillator_model.hpp): what one shooting segment
// contributes to the periodicity equations' Jacobian.
#pragma once

#include <Eigen/Core>

namespace stickslip {

template <int kStateSize, int kParameters>
struct BasicFlowDerivatives {
  using ParameterMatrix = Eigen::Matrix<double, kStateSize, kParameters>;
  Eigen::Matrix<double, kStateSize, 1> state;                  // X(s)
  Eigen::Matrix<double, kStateSize, kStateSize> d_start;       // dX(s)/dX(0)
  Eigen::Matrix<double, kStateSize, 1> d_elapsed;              // dX(s)/ds, the vector field
  Eigen::Matrix<double, kStateSize, 1> d_phase;                // dX(s)/dpsi
  ParameterMatrix d_parameters;                                // columns in the model's parameter order
};

}  // namespace stickslip
